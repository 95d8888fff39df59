use plc_core::PlcStruct;

#[derive(PlcStruct, Clone, Copy)]
pub enum Mode {
    Auto,
    Manual,
}

#[derive(PlcStruct, Clone, Copy)]
pub struct Pair(u8, u8);

fn main() {}
