use plc_core::PlcStruct;

#[derive(PlcStruct, Clone, Copy)]
pub struct Axis {
    #[plc(direction = "command")]
    pub start: bool,
    #[plc(direction = "status")]
    pub busy: bool,
}

fn main() {}
