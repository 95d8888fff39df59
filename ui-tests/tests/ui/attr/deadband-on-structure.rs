use plc_core::{GlobalMemory, PlcStruct};

// A structure is no number: its reporting deadbands go on its members.
#[derive(PlcStruct, Debug, Clone)]
pub struct Axis {
    pos: f64,
}

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(deadband = 0.5)]
    axis: Axis,
}

fn main() {}
