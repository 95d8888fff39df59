use plc_core::{GlobalMemory, PlcStruct};

#[derive(PlcStruct, Clone, Copy)]
pub struct Axis {
    pub pos: i32,
}

type Lift = Axis;
type Axes = [Axis; 70000];

#[derive(GlobalMemory, Clone)]
pub struct Gm {
    #[plc(initial = 1, nonvolatile)]
    pub lift: Lift,
    pub axes: Axes,
}

fn main() {}
