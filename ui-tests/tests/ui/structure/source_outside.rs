use plc_core::{GlobalMemory, PlcStruct};

#[derive(PlcStruct, Clone, Copy)]
pub struct Axis {
    #[plc(source = "status_word", bit = 0)]
    pub ready: bool,
}

#[derive(GlobalMemory, Clone)]
pub struct Gm {
    pub status_word: u16,
    pub axis: Axis,
}

fn main() {}
