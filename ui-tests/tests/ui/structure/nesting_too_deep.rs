use plc_core::{GlobalMemory, PlcStruct};

#[derive(PlcStruct, Clone, Copy)]
pub struct L1 {
    pub x: u8,
}
#[derive(PlcStruct, Clone, Copy)]
pub struct L2 {
    pub x: L1,
}
#[derive(PlcStruct, Clone, Copy)]
pub struct L3 {
    pub x: L2,
}
#[derive(PlcStruct, Clone, Copy)]
pub struct L4 {
    pub x: L3,
}
#[derive(PlcStruct, Clone, Copy)]
pub struct L5 {
    pub x: L4,
}
#[derive(PlcStruct, Clone, Copy)]
pub struct L6 {
    pub x: L5,
}
#[derive(PlcStruct, Clone, Copy)]
pub struct L7 {
    pub x: L6,
}
#[derive(PlcStruct, Clone, Copy)]
pub struct L8 {
    pub x: L7,
}
// Nine levels of structures: one too many, inside a structure and in a program.
#[derive(PlcStruct, Clone, Copy)]
pub struct L9 {
    pub x: L8,
}

#[derive(GlobalMemory, Clone)]
pub struct Gm {
    pub eight: L8,
    pub nine: L9,
}

fn main() {}
