// The attributes of the framework's project files: `ux`, `quantity`, and links whose entry is
// a dotted path, as its motion axes write them; `unit` and the reporting `deadband` beside an
// alarm's own deadband, on a number, an array and a structure's member.
use plc_core::{GlobalMemory, PlcStruct};

#[derive(PlcStruct, Debug, Clone)]
pub struct Axis {
    #[plc(unit = "mm", deadband = 0.01)]
    pos: f64,
    homed: bool,
}

#[derive(GlobalMemory, Debug, Clone)]
pub struct Gm {
    #[plc(ux, description = "Start the test")]
    cmd_start: bool,
    #[plc(ux, quantity = "force")]
    load_cell_force: f64,
    #[plc(link = "ethercat.motion.x.position", quantity = "length")]
    x_position: i32,
    #[plc(link = "ethercat.motion.x.actual_velocity")]
    x_actual_velocity: i32,
    #[plc(unit = "kN", deadband = 0.5, alarm(text = "Overload", high = 90.0, deadband = 2.0))]
    force: f32,
    #[plc(unit = "°C", deadband = 1)]
    temperatures: [i16; 4],
    axis: Axis,
}

fn main() {
    let v = Gm::VARIABLES;
    assert!(v[0].ux && v[1].ux && !v[2].ux);
    assert_eq!((v[1].quantity, v[2].quantity, v[3].quantity), (Some("force"), Some("length"), None));
    assert_eq!(v[3].link, Some("ethercat.motion.x.actual_velocity"));
    assert_eq!((v[4].unit, v[4].deadband), (Some("kN"), Some(0.5)));
    assert_eq!((v[5].unit, v[5].deadband), (Some("°C"), Some(1.0)));
    assert_eq!((v[3].unit, v[3].deadband), (None, None));
    let pos = &v[6].members()[0];
    assert_eq!((pos.unit, pos.deadband), (Some("mm"), Some(0.01)));
    let gm = Gm::default();
    let _ = (gm.cmd_start, gm.load_cell_force, gm.x_position, gm.x_actual_velocity);
    let _ = (gm.force, gm.temperatures, gm.axis.pos, gm.axis.homed);
}
