//! Every form of alarm declaration compiles, and the table says what was declared.
use plc_core::alarm::{AlarmKind, SuppressWhen};
use plc_core::{GlobalMemory, PlcStruct, Time};

#[derive(PlcStruct, Debug, Clone)]
pub struct Station {
    #[plc(alarm(text = "Door open", suppress_when = "OUT_OF_SERVICE", severity = 800))]
    door: bool,
    out_of_service: bool,
    #[plc(alarm(text = "Motor temperature", high = 90, low_low = -20.5, deadband = 2))]
    motor: [f32; 2],
}

#[derive(PlcStruct, Debug, Clone)]
pub struct Cell {
    stations: [Station; 2],
    #[plc(alarm = "Cell stopped")]
    stopped: bool,
}

#[derive(GlobalMemory, Debug, Clone)]
pub struct Gm {
    #[plc(alarm = "Guard door open")]
    door: bool,
    #[plc(alarm = "Air pressure low", alarm_when = false)]
    air_ok: bool,
    #[plc(alarm(text = "Overtravel", latched, delay = "500ms", severity = 1000))]
    overtravel: [bool; 2],
    cell: Cell,
    #[plc(alarm(text = "Oil temperature", high = 80.0, high_high = 95.0, low = 5.0, low_low = 0.0,
                deadband = 1.0, delay = "2s", severity = 600, latched,
                suppress_when = "cell.stations[1].out_of_service"))]
    oil: f64,
    ok: u8,
}

const _: () = assert!(Gm::ALARMS.len() == 2 + 2 + (2 * (1 + 2) + 1) + 1);

fn main() {
    let a = Gm::ALARMS;
    assert_eq!(a[1].condition.kind, AlarmKind::Discrete { active: false });
    assert_eq!((a[3].leaf, a[3].condition.delay), (1, Time::from_millis(500)));
    let oil = a.last().unwrap();
    assert_eq!(oil.suppress_when, SuppressWhen::Path("cell.stations[1].out_of_service"));
    let names = plc_core::alarm::alarm_paths(Gm::VARIABLES, a);
    assert_eq!(names[4], "cell.stations[0].door");
    assert_eq!(names[5], "cell.stations[0].motor[0]");
    assert_eq!(names[10], "cell.stopped");
}
