use plc_core::{GlobalMemory, PlcStruct};

#[derive(PlcStruct, Clone, Copy)]
pub struct Cell {
    pub v: u8,
}

#[derive(GlobalMemory, Clone)]
pub struct Gm {
    pub cells: [[Cell; 256]; 257],
}

fn main() {}
