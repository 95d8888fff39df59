use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    w: u16,
    #[plc(source = "w", bit = -1)]
    flag: bool,
}

fn main() {}
