use plc_core::GlobalMemory;

type Level = u8;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(initial = 300)]
    level: Level,
}

fn main() {}
