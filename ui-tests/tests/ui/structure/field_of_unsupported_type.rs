use plc_core::{GlobalMemory, PlcStruct};

pub struct NotPlc {
    pub x: u8,
}

#[derive(PlcStruct, Clone, Copy)]
pub struct Axis {
    pub inner: NotPlc,
}

#[derive(GlobalMemory, Clone)]
pub struct Gm {
    pub other: NotPlc,
}

fn main() {}
