//! Structures nested, in arrays of up to 3 dimensions, through aliases, with bit mapping
//! inside, eight levels deep, and a GlobalMemory that holds them.
use plc_core::{GlobalMemory, PlcStruct, PlcType};

#[derive(PlcStruct, Clone, Copy, Debug)]
pub struct Axis {
    pub pos: f64,
    #[plc(initial = 100.0, description = "target in mm")]
    pub target: f64,
    #[plc(direction = "input")]
    pub enable: bool,
    #[plc(direction = "output")]
    pub done: bool,
    #[plc(iec_type = "WORD")]
    pub status: u16,
    #[plc(source = "status", bit = 15)]
    pub fault: bool,
    #[plc(nonvolatile, read_only, ux, quantity = "length")]
    pub travelled: f64,
}

type Axes = [Axis; 4];

#[derive(PlcStruct, Clone, Copy, Debug)]
#[plc(name = "Station")]
pub struct Station {
    pub axes: Axes,
    pub grid: [[[Axis; 2]; 2]; 2],
}

#[derive(PlcStruct, Clone, Copy, Debug)]
pub struct L1 {
    pub x: u8,
}
#[derive(PlcStruct, Clone, Copy, Debug)]
pub struct L2 {
    pub x: L1,
}
#[derive(PlcStruct, Clone, Copy, Debug)]
pub struct L3 {
    pub x: L2,
}
#[derive(PlcStruct, Clone, Copy, Debug)]
pub struct L4 {
    pub x: L3,
}
#[derive(PlcStruct, Clone, Copy, Debug)]
pub struct L5 {
    pub x: L4,
}
#[derive(PlcStruct, Clone, Copy, Debug)]
pub struct L6 {
    pub x: L5,
}
#[derive(PlcStruct, Clone, Copy, Debug)]
pub struct L7 {
    pub x: L6,
}
#[derive(PlcStruct, Clone, Copy, Debug)]
pub struct L8 {
    pub x: L7,
}

// Two structures may use the same member names: each is its own group.
#[derive(PlcStruct, Clone, Copy, Debug)]
pub struct Other {
    pub pos: i32,
}

#[derive(GlobalMemory, Clone, Debug)]
pub struct Gm {
    pub station: Station,
    pub stations: [Station; 2],
    pub deep: L8,
    pub pos: Other,
    #[plc(link = "ethercat.io.inputs", direction = "input")]
    pub inputs: u16,
}

fn main() {
    assert_eq!(<L8 as PlcType>::DEPTH, 8);
    assert_eq!(Gm::VARIABLES.len(), 5);
    let gm = Gm::default();
    assert_eq!(gm.stations[1].grid[1][1][1].target, 100.0);
    assert!(Gm::find("stations[1].grid[1,1,1].target").is_some());
    assert!(Gm::find("deep.x.x.x.x.x.x.x.x").is_some());
}
