use plc_core::{GlobalMemory, PlcStruct};

#[derive(PlcStruct, Debug, Clone)]
pub struct Station {
    #[plc(alarm(text = "Door open", suppress_when = "out_of_servic"))]
    door: bool,
    #[plc(alarm(text = "Jam", suppress_when = "cell.out_of_service"))]
    jam: bool,
    out_of_service: bool,
}

#[derive(GlobalMemory, Debug, Clone)]
pub struct Gm {
    #[plc(alarm(text = "Guard door open", suppress_when = "maintenance"))]
    door: bool,
    #[plc(alarm(text = "Oil temperature", high = 80.0, suppress_when = "mode"))]
    oil: f32,
    mode: u8,
    #[plc(alarm(text = "Air pressure low", suppress_when = "cell.off"))]
    air: bool,
}

fn main() {}

#[derive(GlobalMemory, Debug, Clone)]
pub struct Elements {
    #[plc(alarm(text = "Fine", suppress_when = "off[1]"))]
    a: bool,
    #[plc(alarm(text = "Beyond the array", suppress_when = "off[2]"))]
    b: bool,
    #[plc(alarm(text = "The whole array", suppress_when = "off"))]
    c: bool,
    #[plc(alarm(text = "Into a bool", suppress_when = "mode.x"))]
    d: bool,
    off: [bool; 2],
    mode: bool,
}
