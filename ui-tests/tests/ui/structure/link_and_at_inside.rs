use plc_core::PlcStruct;

#[derive(PlcStruct, Clone, Copy)]
pub struct Axis {
    #[plc(link = "ethercat.drive.position")]
    pub pos: i32,
    #[plc(at = "%IX0.0")]
    pub end_switch: bool,
}

fn main() {}
