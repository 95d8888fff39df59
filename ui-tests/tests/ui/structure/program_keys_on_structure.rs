use plc_core::{GlobalMemory, PlcStruct};

#[derive(PlcStruct, Clone, Copy)]
#[plc(bus = "tests/bus/press.toml", byte_order = "little", unaligned)]
pub struct Axis {
    pub pos: i32,
}

#[derive(GlobalMemory, Clone)]
#[plc(name = "Machine")]
pub struct Gm {
    pub lift: Axis,
}

fn main() {}
