//! The tensile tester: its variables, its program and a model of the machine that animates the
//! simulated bus.
//!
//! - [`Gm`]: the example variables of the JSON variable-list format (impact67 I/O words with bit-mapped limit switches and a lift
//!   brake, test information strings, nonvolatile offsets) plus the signal tower on an EL2004.
//! - [`process_tick`]: a state machine idle -> centering -> lifting -> testing -> done.
//! - [`plant`]: the machine itself, reading the simulated outputs and setting the simulated
//!   inputs from a thread, so the example visibly runs tests on the simulated bus.

pub mod plant;

use ethercat_sim::{Device, SimBus};
use plc_core::fb::Ton;
use plc_core::{FixedString, GlobalMemory, PlcStruct, Time};
use plc_io::ethercat::Transport;
use std::time::Duration;

/// The bus description of the example (`examples/bus/tensile_tester.toml`).
pub const BUS_TOML: &str = include_str!("../../bus/tensile_tester.toml");

/// Ring positions of the simulated SubDevices, as in the bus description.
pub mod position {
    /// EK1100 coupler.
    pub const COUPLER: usize = 0;
    /// EL1004: the impact67 inputs.
    pub const INPUTS: usize = 1;
    /// EL2889: the impact67 outputs.
    pub const OUTPUTS: usize = 2;
    /// EL2004: the signal tower.
    pub const LAMPS: usize = 3;
}

/// The simulated machine: EK1100, EL1004, EL2889, EL2004 in the ring order of [`BUS_TOML`].
pub fn simulated_bus() -> SimBus {
    SimBus::new(vec![
        Device::ek1100(),
        Device::el1004(),
        Device::el2889(),
        Device::el2004(),
    ])
}

/// The in-process transport to a simulated bus (no privileges needed).
pub fn sim_transport(bus: SimBus) -> Transport {
    Transport::custom(move |tx, rx| Ok(Box::new(ethercat_sim::inproc::spawn(tx, rx, bus)?)))
}

/// One of the machine's drives, as the HMI shows it: [`Gm::axes`] holds the lift, the
/// centering jaws and the test drive, in [`axis`]'s order.
#[derive(PlcStruct, Debug, Clone, Copy, PartialEq)]
pub struct Axis {
    /// The program switches the drive on (IN)
    #[plc(direction = "input")]
    pub enable: bool,
    /// The drive reached its end position (OUT)
    #[plc(direction = "output")]
    pub done: bool,
    /// Where the drive is, in mm
    pub pos_mm: f64,
    /// Cycles the drive has been on in the current step
    pub on_cycles: u32,
    /// Moves completed since commissioning (kept across restarts)
    #[plc(nonvolatile, read_only)]
    pub moves: u32,
}

/// Indexes of [`Gm::axes`].
pub mod axis {
    /// The lift.
    pub const LIFT: usize = 0;
    /// The centering jaws.
    pub const CENTERING: usize = 1;
    /// The test drive pulling the specimen.
    pub const TEST_DRIVE: usize = 2;
}

/// The tensile tester's variables. Every link is checked against the bus description while
/// compiling: a typo in one is a compile error under it.
#[derive(GlobalMemory, Debug, Clone)]
#[plc(bus = "bus/tensile_tester.toml")]
pub struct Gm {
    /// impact67 input word (the EL1004 on the simulated bus)
    #[plc(link = "ethercat.impact67_0.digital_inputs", direction = "input")]
    pub impact67_0_digital_inputs: u16,
    /// impact67 output word (the EL2889 on the simulated bus)
    #[plc(link = "ethercat.impact67_0.digital_outputs", direction = "output")]
    pub impact67_0_digital_outputs: u16,
    /// Centering jaw at its negative limit (closed on the specimen)
    #[plc(source = "impact67_0_digital_inputs", bit = 0)]
    pub ls_centering_neg: bool,
    /// Centering jaw at its positive limit (closed on the specimen)
    #[plc(source = "impact67_0_digital_inputs", bit = 1)]
    pub ls_centering_pos: bool,
    /// Lift at its lower limit
    #[plc(source = "impact67_0_digital_inputs", bit = 2)]
    pub ls_lift_neg: bool,
    /// Specimen break detector
    #[plc(source = "impact67_0_digital_inputs", bit = 3)]
    pub specimen_broken: bool,
    /// Lift brake released (energised)
    #[plc(source = "impact67_0_digital_outputs", bit = 0)]
    pub cr_lift_brake: bool,
    /// Centering drive on
    #[plc(source = "impact67_0_digital_outputs", bit = 1)]
    pub cr_centering_drive: bool,
    /// Lift drive up
    #[plc(source = "impact67_0_digital_outputs", bit = 2)]
    pub cr_lift_up: bool,
    /// Test drive (pulling the specimen) on
    #[plc(source = "impact67_0_digital_outputs", bit = 3)]
    pub cr_test_drive: bool,
    /// Signal tower green: ready
    #[plc(link = "ethercat.lamps.green", direction = "output")]
    pub lamp_green: bool,
    /// Signal tower yellow: test running
    #[plc(link = "ethercat.lamps.yellow", direction = "output")]
    pub lamp_yellow: bool,
    /// Signal tower red: fault
    #[plc(link = "ethercat.lamps.red", direction = "output")]
    pub lamp_red: bool,
    /// Horn: specimen broke
    #[plc(link = "ethercat.lamps.horn", direction = "output")]
    pub horn: bool,
    /// Test identifier
    #[plc(initial = "TEST-0000")]
    pub info_test_id: FixedString<64>,
    /// Specimen name
    #[plc(initial = "S235 flat bar 20x4")]
    pub info_specimen_name: FixedString<128>,
    /// Operator notes
    pub info_notes: FixedString<255>,
    /// Press home offset in mm
    #[plc(nonvolatile, initial = 12.5)]
    pub press_home_offset_mm: f64,
    /// Lift zero offset in mm
    #[plc(nonvolatile, initial = 0.0)]
    pub lift_zero_offset_mm: f64,
    /// Test speed setpoint in mm/s (the HMI's to set, 0.1 to 10; kept across restarts)
    #[plc(direction = "command", nonvolatile, initial = 2.0)]
    pub test_speed_mm_s: f64,
    /// Start the next test by itself 1 s after the last one
    #[plc(direction = "command", initial = true)]
    pub auto_start: bool,
    /// Start a test (set by the HMI, cleared by the program)
    #[plc(direction = "command")]
    pub cmd_start: bool,
    /// Machine state: 0 idle, 1 centering, 2 lifting, 3 testing, 4 done, 5 fault
    #[plc(direction = "status")]
    pub machine_state: u8,
    /// Machine state as text
    #[plc(direction = "status", initial = "idle")]
    pub machine_state_name: FixedString<16>,
    /// Fault text, empty when none
    #[plc(direction = "status")]
    pub fault_text: FixedString<128>,
    /// Simulated force in kN
    #[plc(direction = "status", quantity = "force")]
    pub force_kn: f64,
    /// Elongation in mm
    #[plc(direction = "status", quantity = "length")]
    pub elongation_mm: f64,
    /// Largest force of the last test in kN
    #[plc(direction = "status", quantity = "force")]
    pub max_force_kn: f64,
    /// Tests completed since the machine was commissioned
    #[plc(direction = "status", nonvolatile)]
    pub tests_completed: u32,
    /// Cycles spent in the current state
    #[plc(direction = "status")]
    pub state_cycles: u32,
    /// The drives: lift, centering jaws, test drive (`axes[2].pos_mm` is the elongation)
    pub axes: [Axis; 3],
    /// Step timeout: the centering jaws close within 5 s
    pub centering_timeout: Ton,
    /// Step timeout: the lift leaves its lower limit within 5 s
    pub lifting_timeout: Ton,
    /// Step timeout: the specimen breaks within 20 s
    pub test_timeout: Ton,
}

/// How long each step may take.
const CENTERING_TIMEOUT: Time = Time::from_secs(5);
const LIFTING_TIMEOUT: Time = Time::from_secs(5);
const TEST_TIMEOUT: Time = Time::from_secs(20);

/// The machine states, as `machine_state` holds them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u8)]
pub enum State {
    /// Waiting for a start.
    Idle = 0,
    /// Closing the centering jaws on the specimen.
    Centering = 1,
    /// Lifting the specimen off the lower limit.
    Lifting = 2,
    /// Pulling until the specimen breaks.
    Testing = 3,
    /// Test finished; drives off.
    Done = 4,
    /// A step took too long or the bus failed; waits for a start.
    Fault = 5,
}

impl State {
    fn from_u8(v: u8) -> State {
        match v {
            1 => State::Centering,
            2 => State::Lifting,
            3 => State::Testing,
            4 => State::Done,
            5 => State::Fault,
            _ => State::Idle,
        }
    }

    /// Lower-case name.
    pub fn name(self) -> &'static str {
        match self {
            State::Idle => "idle",
            State::Centering => "centering",
            State::Lifting => "lifting",
            State::Testing => "testing",
            State::Done => "done",
            State::Fault => "fault",
        }
    }
}

/// What the cycle tells the program besides the variables.
#[derive(Clone, Copy, Debug)]
pub struct TickInfo {
    /// The cycle period.
    pub period: Duration,
    /// The inputs are this cycle's (the bus answered correctly).
    pub inputs_valid: bool,
    /// The cycle's start (`Context::now`), for the step timeouts.
    pub now: Time,
}

fn go(gm: &mut Gm, to: State) {
    gm.machine_state = to as u8;
    gm.machine_state_name.set(to.name());
    gm.state_cycles = 0;
}

fn fault(gm: &mut Gm, text: &str) {
    gm.fault_text.set(text);
    go(gm, State::Fault);
}

/// The range the test drive accepts for `test_speed_mm_s`, and a made-up stiffness in kN/mm for
/// the force display.
const TEST_SPEED_MM_S: std::ops::RangeInclusive<f64> = 0.1..=10.0;
const STIFFNESS_KN_MM: f64 = 9.0;

/// One cycle of the tensile tester's program.
pub fn process_tick(gm: &mut Gm, info: TickInfo) {
    let dt = info.period.as_secs_f64();
    let secs = |s: f64| (s / dt).ceil() as u32;
    gm.state_cycles = gm.state_cycles.saturating_add(1);
    let state = State::from_u8(gm.machine_state);

    // Drives are off unless the state below switches them on.
    gm.cr_centering_drive = false;
    gm.cr_lift_up = false;
    gm.cr_lift_brake = false;
    gm.cr_test_drive = false;
    gm.horn = false;

    if !info.inputs_valid && state != State::Idle && state != State::Fault {
        fault(gm, "EtherCAT inputs invalid: bus fault during a test");
    }
    let state = State::from_u8(gm.machine_state);
    // Each step's timer runs while the machine is in that step.
    let now = info.now;
    gm.centering_timeout
        .call(now, state == State::Centering, CENTERING_TIMEOUT);
    gm.lifting_timeout
        .call(now, state == State::Lifting, LIFTING_TIMEOUT);
    gm.test_timeout
        .call(now, state == State::Testing, TEST_TIMEOUT);
    match state {
        State::Idle => {
            if gm.cmd_start || (gm.auto_start && gm.state_cycles >= secs(1.0)) {
                gm.cmd_start = false;
                let mut id = FixedString::<64>::new();
                let _ = std::fmt::Write::write_fmt(
                    &mut id,
                    format_args!("TEST-{:04}", gm.tests_completed + 1),
                );
                gm.info_test_id = id;
                gm.force_kn = 0.0;
                gm.elongation_mm = 0.0;
                gm.max_force_kn = 0.0;
                gm.fault_text.clear();
                go(gm, State::Centering);
            }
        }
        State::Centering => {
            gm.cr_centering_drive = true;
            if gm.ls_centering_neg && gm.ls_centering_pos {
                go(gm, State::Lifting);
            } else if gm.centering_timeout.Q {
                fault(gm, "centering jaws did not close within 5 s");
            }
        }
        State::Lifting => {
            gm.cr_centering_drive = true;
            gm.cr_lift_brake = true;
            gm.cr_lift_up = true;
            if !gm.ls_lift_neg && gm.state_cycles > secs(0.5) {
                go(gm, State::Testing);
            } else if gm.lifting_timeout.Q {
                fault(gm, "lift did not leave its lower limit within 5 s");
            }
        }
        State::Testing => {
            gm.cr_centering_drive = true;
            gm.cr_lift_brake = true;
            gm.cr_test_drive = true;
            let speed = gm
                .test_speed_mm_s
                .clamp(*TEST_SPEED_MM_S.start(), *TEST_SPEED_MM_S.end());
            gm.elongation_mm += speed * dt;
            // Elastic, then yielding: a curve that looks like a test on an HMI.
            let e = gm.elongation_mm;
            gm.force_kn = STIFFNESS_KN_MM * e / (1.0 + e / 2.0);
            gm.max_force_kn = gm.max_force_kn.max(gm.force_kn);
            if gm.specimen_broken {
                gm.force_kn = 0.0;
                go(gm, State::Done);
            } else if gm.test_timeout.Q {
                fault(gm, "specimen did not break within 20 s");
            }
        }
        State::Done => {
            gm.horn = gm.state_cycles < secs(0.3);
            if gm.state_cycles == 1 {
                gm.tests_completed = gm.tests_completed.saturating_add(1);
            }
            if gm.state_cycles > secs(1.0) {
                go(gm, State::Idle);
            }
        }
        State::Fault => {
            if gm.cmd_start {
                gm.cmd_start = false;
                gm.fault_text.clear();
                go(gm, State::Idle);
            }
        }
    }
    let state = State::from_u8(gm.machine_state);
    update_axes(gm, state);
    gm.lamp_green = state == State::Idle;
    gm.lamp_yellow = matches!(
        state,
        State::Centering | State::Lifting | State::Testing | State::Done
    );
    gm.lamp_red = state == State::Fault || !info.inputs_valid;
}

/// The drives' view of this cycle: each follows its output, counts its cycles on and its
/// completed moves (a move completes when its step ends with the drive at its end position).
fn update_axes(gm: &mut Gm, state: State) {
    let outputs = [
        (axis::LIFT, gm.cr_lift_up, !gm.ls_lift_neg),
        (
            axis::CENTERING,
            gm.cr_centering_drive,
            gm.ls_centering_neg && gm.ls_centering_pos,
        ),
        (axis::TEST_DRIVE, gm.cr_test_drive, gm.specimen_broken),
    ];
    for (i, on, at_end) in outputs {
        let a = &mut gm.axes[i];
        if a.enable && !on && a.done {
            a.moves = a.moves.saturating_add(1);
        }
        a.enable = on;
        a.done = at_end;
        a.on_cycles = if on { a.on_cycles.saturating_add(1) } else { 0 };
    }
    gm.axes[axis::TEST_DRIVE].pos_mm = gm.elongation_mm;
    gm.axes[axis::LIFT].pos_mm = if gm.ls_lift_neg { 0.0 } else { 5.0 };
    gm.axes[axis::CENTERING].pos_mm = if state == State::Idle { 20.0 } else { 0.0 };
}

#[cfg(test)]
// Tests set the variables a scenario needs after `Default`, as a program would.
#[allow(clippy::field_reassign_with_default)]
mod tests {
    use super::*;

    #[test]
    fn a_test_runs_from_idle_to_done_on_the_plant_signals() {
        let info = TickInfo {
            period: Duration::from_millis(10),
            inputs_valid: true,
            now: Time::ZERO,
        };
        let mut gm = Gm::default();
        gm.cmd_start = true;
        process_tick(&mut gm, info);
        assert_eq!(gm.machine_state, State::Centering as u8);
        process_tick(&mut gm, info);
        assert!(gm.cr_centering_drive);
        gm.ls_centering_neg = true;
        gm.ls_centering_pos = true;
        gm.ls_lift_neg = true;
        process_tick(&mut gm, info);
        assert_eq!(gm.machine_state, State::Lifting as u8);
        gm.ls_lift_neg = false;
        for _ in 0..60 {
            process_tick(&mut gm, info);
        }
        assert_eq!(gm.machine_state, State::Testing as u8);
        assert!(gm.cr_test_drive && gm.lamp_yellow);
        gm.specimen_broken = true;
        process_tick(&mut gm, info);
        process_tick(&mut gm, info);
        assert_eq!(gm.machine_state, State::Done as u8);
        assert_eq!(gm.tests_completed, 1);
        assert!(gm.max_force_kn > 0.0);
        assert_eq!(gm.axes[axis::TEST_DRIVE].pos_mm, gm.elongation_mm);
        assert_eq!(
            gm.axes[axis::TEST_DRIVE].moves,
            1,
            "the test drive's move completed"
        );
        assert!(!gm.axes[axis::TEST_DRIVE].enable);
    }

    #[test]
    fn a_bus_fault_during_a_test_stops_the_drives() {
        let mut gm = Gm::default();
        gm.machine_state = State::Testing as u8;
        process_tick(
            &mut gm,
            TickInfo {
                period: Duration::from_millis(1),
                inputs_valid: false,
                now: Time::ZERO,
            },
        );
        assert_eq!(gm.machine_state, State::Fault as u8);
        assert!(!gm.cr_test_drive && !gm.cr_lift_brake && gm.lamp_red);
    }

    #[test]
    fn a_step_that_takes_too_long_faults_through_its_timer() {
        let mut gm = Gm::default();
        gm.cmd_start = true;
        let tick = |gm: &mut Gm, ms: i64| {
            process_tick(
                gm,
                TickInfo {
                    period: Duration::from_millis(10),
                    inputs_valid: true,
                    now: Time::from_millis(ms),
                },
            )
        };
        tick(&mut gm, 0);
        assert_eq!(gm.machine_state, State::Centering as u8);
        tick(&mut gm, 10);
        assert!(gm.centering_timeout.IN && !gm.centering_timeout.Q);
        tick(&mut gm, 4_000);
        assert_eq!(gm.centering_timeout.ET, Time::from_millis(3_990));
        assert_eq!(gm.machine_state, State::Centering as u8);
        tick(&mut gm, 5_010);
        assert_eq!(gm.machine_state, State::Fault as u8);
        assert_eq!(
            gm.fault_text.as_str(),
            "centering jaws did not close within 5 s"
        );
        tick(&mut gm, 5_020);
        assert!(
            !gm.centering_timeout.Q,
            "the timer resets when the step ends"
        );
    }
}
