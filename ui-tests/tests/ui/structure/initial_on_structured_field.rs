use plc_core::{GlobalMemory, PlcStruct};

#[derive(PlcStruct, Clone, Copy)]
pub struct Axis {
    #[plc(initial = 100.0)]
    pub target: f64,
}

#[derive(GlobalMemory, Clone)]
pub struct Gm {
    #[plc(initial = 5)]
    pub lift: Axis,
    #[plc(initial = 5)]
    pub axes: [Axis; 2],
}

fn main() {}
