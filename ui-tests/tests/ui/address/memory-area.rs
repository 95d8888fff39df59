use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(at = "%MW4")]
    counter: u16,
}

fn main() {}
