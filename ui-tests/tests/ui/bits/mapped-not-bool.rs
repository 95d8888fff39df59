use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    w: u16,
    #[plc(source = "w", bit = 3)]
    level: u8,
}

fn main() {}
