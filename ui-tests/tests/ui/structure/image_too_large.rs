use plc_core::{GlobalMemory, PlcStruct};

#[derive(PlcStruct, Clone, Copy)]
pub struct Block {
    pub data: [u64; 65535],
}

#[derive(PlcStruct, Clone, Copy)]
pub struct Rack {
    pub blocks: [Block; 8193],
}

#[derive(GlobalMemory, Clone)]
pub struct Gm {
    pub rack: Rack,
}

fn main() {}
