use plc_core::{GlobalMemory, PlcStruct};

#[derive(PlcStruct, Clone, Copy)]
pub struct Axis {
    #[plc(nonvolatile)]
    pub cycles: u32,
}

#[derive(PlcStruct, Clone, Copy)]
pub struct Station {
    #[plc(nonvolatile)]
    pub axis: Axis,
}

#[derive(GlobalMemory, Clone)]
pub struct Gm {
    #[plc(retain)]
    pub lift: Axis,
}

fn main() {}
