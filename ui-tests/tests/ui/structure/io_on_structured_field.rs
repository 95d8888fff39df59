use plc_core::{GlobalMemory, PlcStruct};

#[derive(PlcStruct, Clone, Copy)]
pub struct Axis {
    pub pos: i32,
}

#[derive(GlobalMemory, Clone)]
pub struct Gm {
    #[plc(link = "ethercat.drive.position")]
    pub lift: Axis,
    #[plc(at = "%ID0")]
    pub centering: Axis,
    pub status_word: u16,
    #[plc(source = "lift", bit = 0)]
    pub flag: bool,
}

fn main() {}
