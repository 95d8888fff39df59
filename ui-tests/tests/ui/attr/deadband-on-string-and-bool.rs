use plc_core::{FixedString, GlobalMemory};

// A reporting deadband is for numbers: text and bools are published on every change.
#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(deadband = 1)]
    specimen: FixedString<16>,
    #[plc(deadband = 0.5)]
    door_closed: bool,
}

fn main() {}
