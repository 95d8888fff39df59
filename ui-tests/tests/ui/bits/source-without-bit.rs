use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    w: u16,
    #[plc(source = "w")]
    flag: bool,
}

fn main() {}
