use plc_core::{FixedString, GlobalMemory};

type Level = u8;
type Label = FixedString<8>;
type Flag = bool;
type Force = f32;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(initial = "high")]
    level: Level,
    #[plc(initial = 3)]
    label: Label,
    #[plc(initial = 1)]
    flag: Flag,
    #[plc(initial = true)]
    force: Force,
    #[plc(initial = 1.5)]
    count: Level,
}

fn main() {}
