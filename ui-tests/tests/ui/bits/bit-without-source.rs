use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    w: u16,
    #[plc(bit = 2)]
    flag: bool,
}

fn main() {}
