use plc_core::GlobalMemory;

type Level = u8;

#[derive(GlobalMemory)]
pub struct Gm {
    w: u16,
    #[plc(source = "w", bit = 3)]
    level: Level,
}

fn main() {}
