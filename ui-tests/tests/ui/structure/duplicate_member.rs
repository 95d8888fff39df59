use plc_core::PlcStruct;

#[derive(PlcStruct, Clone, Copy)]
pub struct Axis {
    pub pos: f64,
    #[plc(name = "POS")]
    pub position: f64,
}

fn main() {}
