//! A structure need not be `Copy` (a `Clone` is enough), inside arrays and beside function
//! blocks, with bit mapping and initial values.

use plc_core::fb::{FTrig, Tof};
use plc_core::{GlobalMemory, PlcStruct, Value};

#[derive(PlcStruct, Debug, Clone)]
pub struct Valve {
    pub open_cmd: bool,
    #[plc(initial = 1.5)]
    pub stroke_s: f32,
    pub flags: u8,
    #[plc(source = "flags", bit = 0)]
    pub open_fb: bool,
    pub off_delay: Tof,
}

#[derive(GlobalMemory, Debug, Clone)]
pub struct Plant {
    pub valves: [Valve; 2],
    pub stop_edge: FTrig,
}

fn main() {
    let mut p = Plant::default();
    let loc = Plant::find("valves[1].stroke_s").unwrap();
    assert_eq!(p.get_at(&loc), Value::Real(1.5));
    p.valves[0].flags = 1;
    p.unpack_bits();
    assert!(p.valves[0].open_fb);
    let again = Plant::from_image(&p.to_image());
    assert!(again.valves[0].open_fb && again.valves[1].stroke_s == 1.5);
}
