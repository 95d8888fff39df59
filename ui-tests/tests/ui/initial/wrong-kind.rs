use plc_core::{FixedString, GlobalMemory};

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(initial = "fast")]
    speed: i32,
    #[plc(initial = 1)]
    enabled: bool,
    #[plc(initial = 2.5)]
    count: u16,
    #[plc(initial = 7)]
    label: FixedString<8>,
}

fn main() {}
