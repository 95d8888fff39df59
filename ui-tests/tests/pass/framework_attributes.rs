// The attributes of the framework's project files: `ux`, `quantity`, and links whose entry is
// a dotted path, as its motion axes write them.
use plc_core::GlobalMemory;

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
}

fn main() {
    let v = Gm::VARIABLES;
    assert!(v[0].ux && v[1].ux && !v[2].ux);
    assert_eq!((v[1].quantity, v[2].quantity, v[3].quantity), (Some("force"), Some("length"), None));
    assert_eq!(v[3].link, Some("ethercat.motion.x.actual_velocity"));
    let gm = Gm::default();
    let _ = (gm.cmd_start, gm.load_cell_force, gm.x_position, gm.x_actual_velocity);
}
