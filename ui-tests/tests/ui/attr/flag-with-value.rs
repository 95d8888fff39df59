use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(nonvolatile = 1)]
    offset: f64,
}

fn main() {}
