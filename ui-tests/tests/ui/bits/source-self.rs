use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(source = "flag", bit = 0)]
    flag: bool,
}

fn main() {}
