//! The tensile tester: its variables, its program and a model of the machine that animates the
//! simulated bus.
//!
//! - [`Gm`]: the example variables of the JSON variable-list format (impact67 I/O words with bit-mapped limit switches and a lift
//!   brake, test information strings, nonvolatile offsets) plus the signal tower on an EL2004
//!   and the test crosshead, a servo axis on a Kollmorgen AKD.
//! - [`process_tick`]: a state machine idle -> centering -> lifting -> testing -> done (and
//!   fault); the crosshead pulls at the test speed while testing ([`crosshead`]).
//! - [`plant`]: the machine itself, reading the simulated outputs and the crosshead's
//!   position and setting the simulated inputs from a thread, so the example visibly runs
//!   tests on the simulated bus.

pub mod crosshead;
pub mod plant;

use ethercat_sim::{Device, SimBus};
use plc_core::fb::Ton;
use plc_core::motion::{self, McHome, McMoveAbsolute, McMoveVelocity, McPower, McReset, McStop};
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
    /// AKD: the crosshead's servo drive.
    pub const CROSSHEAD: usize = 4;
}

/// The simulated machine: EK1100, EL1004, EL2889, EL2004 and an AKD servo drive in the ring
/// order of [`BUS_TOML`].
pub fn simulated_bus() -> SimBus {
    SimBus::new(vec![
        Device::ek1100(),
        Device::el1004(),
        Device::el2889(),
        Device::el2004(),
        Device::akd(),
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
    /// Test drive pulling the specimen: on while the crosshead's test move runs (the servo
    /// moves the crosshead; the output tells the machine and traces that a test pulls)
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
    /// Crosshead drive: controlword (0x6040), from `crosshead.drive` each cycle
    #[plc(link = "ethercat.crosshead.controlword", direction = "output")]
    pub crosshead_controlword: u16,
    /// Crosshead drive: mode of operation (0x6060, 8 cyclic synchronous position)
    #[plc(link = "ethercat.crosshead.modes_of_operation", direction = "output")]
    pub crosshead_mode: i8,
    /// Crosshead drive: target position in increments (0x607A)
    #[plc(link = "ethercat.crosshead.target_position", direction = "output")]
    pub crosshead_target_position: i32,
    /// Crosshead drive: target velocity in increments/s (0x60FF)
    #[plc(link = "ethercat.crosshead.target_velocity", direction = "output")]
    pub crosshead_target_velocity: i32,
    /// Crosshead drive: statusword (0x6041), into `crosshead.drive` each cycle
    #[plc(link = "ethercat.crosshead.statusword", direction = "input")]
    pub crosshead_statusword: u16,
    /// Crosshead drive: mode of operation it runs in (0x6061)
    #[plc(
        link = "ethercat.crosshead.modes_of_operation_display",
        direction = "input"
    )]
    pub crosshead_mode_display: i8,
    /// Crosshead drive: measured position in increments (0x6064)
    #[plc(link = "ethercat.crosshead.position_actual_value", direction = "input")]
    pub crosshead_position: i32,
    /// Crosshead drive: measured velocity in increments/s (0x606C)
    #[plc(link = "ethercat.crosshead.velocity_actual_value", direction = "input")]
    pub crosshead_velocity: i32,
    /// Crosshead drive: following error in increments (0x60F4)
    #[plc(
        link = "ethercat.crosshead.following_error_actual_value",
        direction = "input"
    )]
    pub crosshead_following_error: i32,
    /// Crosshead drive: error code of its last fault (0x603F, 0 none)
    #[plc(link = "ethercat.crosshead.error_code", direction = "input")]
    pub crosshead_error_code: u16,
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
    /// Start a test (set by the HMI, cleared by the program); in a fault, acknowledges it
    #[plc(direction = "command")]
    pub cmd_start: bool,
    /// Acknowledge a fault (set by the HMI, cleared by the program): MC_Reset resets the
    /// crosshead's drive, then the machine is idle
    #[plc(direction = "command")]
    pub cmd_reset: bool,
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
    /// Elongation in mm: the crosshead's travel since the test started
    #[plc(direction = "status", quantity = "length")]
    pub elongation_mm: f64,
    /// Where the crosshead stood when the test started, in mm
    #[plc(direction = "status", quantity = "length")]
    pub test_start_mm: f64,
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
    /// Step timeout: the specimen breaks within 100 s (7.2 mm at the slowest test speed
    /// take 72 s)
    pub test_timeout: Ton,
    /// The test crosshead's servo axis, in mm (`crosshead::INCREMENTS_PER_MM`); homed to 0 mm
    /// where it stands at start
    #[plc(quantity = "length")]
    pub crosshead: motion::Axis,
    /// MC_Power of the crosshead: on while the program runs
    pub power: McPower,
    /// MC_Home of the crosshead: once, on the position it stands at
    pub home: McHome,
    /// MC_MoveVelocity: the crosshead pulls at the test speed while testing
    pub test_move: McMoveVelocity,
    /// MC_Stop: stops the crosshead when the specimen breaks, and in a fault
    pub stop: McStop,
    /// MC_MoveAbsolute: the crosshead back to its start position (0 mm) before a test
    pub to_start: McMoveAbsolute,
    /// MC_Reset: resets the crosshead's drive fault when the operator acknowledges it
    pub reset: McReset,
}

/// How long each step may take.
const CENTERING_TIMEOUT: Time = Time::from_secs(5);
const LIFTING_TIMEOUT: Time = Time::from_secs(5);
const TEST_TIMEOUT: Time = Time::from_secs(100);

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
    /// Test finished; drives off, the crosshead stopped.
    Done = 4,
    /// A step took too long, the bus failed or the crosshead's drive faulted; waits for
    /// `cmd_reset` or `cmd_start`.
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
    crosshead::read(gm);
    let state = State::from_u8(gm.machine_state);
    let speed = gm
        .test_speed_mm_s
        .clamp(*TEST_SPEED_MM_S.start(), *TEST_SPEED_MM_S.end());

    // Drives are off unless the state below switches them on.
    gm.cr_centering_drive = false;
    gm.cr_lift_up = false;
    gm.cr_lift_brake = false;
    gm.cr_test_drive = false;
    gm.horn = false;

    if !info.inputs_valid && state != State::Idle && state != State::Fault {
        fault(gm, "EtherCAT inputs invalid: bus fault during a test");
    } else if crosshead::faulted(gm) && state != State::Fault {
        let mut text = FixedString::<128>::new();
        let _ = std::fmt::Write::write_fmt(
            &mut text,
            format_args!(
                "crosshead drive fault 16#{:04X}: reset to go on",
                gm.crosshead.drive.error_code
            ),
        );
        gm.fault_text = text;
        go(gm, State::Fault);
    }
    let state = State::from_u8(gm.machine_state);
    if state != State::Fault {
        gm.reset.call(&mut gm.crosshead, false);
    }
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
            // A start waits for the crosshead: powered, homed and back at its start.
            let asked = gm.cmd_start || (gm.auto_start && gm.state_cycles >= secs(1.0));
            if asked && crosshead::ready(gm) {
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
                gm.test_start_mm = gm.crosshead.actual_position;
                go(gm, State::Testing);
            } else if gm.lifting_timeout.Q {
                fault(gm, "lift did not leave its lower limit within 5 s");
            }
        }
        State::Testing => {
            gm.cr_centering_drive = true;
            gm.cr_lift_brake = true;
            gm.cr_test_drive = true;
            // The crosshead pulls (`crosshead::command`); the elongation is its travel.
            gm.elongation_mm = (gm.crosshead.actual_position - gm.test_start_mm).max(0.0);
            // Elastic, then yielding: a curve that looks like a test on an HMI.
            let e = gm.elongation_mm;
            gm.force_kn = STIFFNESS_KN_MM * e / (1.0 + e / 2.0);
            gm.max_force_kn = gm.max_force_kn.max(gm.force_kn);
            if gm.specimen_broken {
                gm.force_kn = 0.0;
                go(gm, State::Done);
            } else if gm.test_timeout.Q {
                fault(gm, "specimen did not break within 100 s");
            } else if gm.test_move.Error {
                fault(gm, "the crosshead refused the test move");
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
            // The operator's acknowledgement runs MC_Reset until the drive left its fault.
            let acknowledged = gm.cmd_start || gm.cmd_reset;
            gm.cmd_start = false;
            gm.cmd_reset = false;
            let resetting = acknowledged || gm.reset.Busy;
            gm.reset.call(&mut gm.crosshead, resetting);
            if gm.reset.Done {
                gm.fault_text.clear();
                go(gm, State::Idle);
            }
        }
    }
    let state = State::from_u8(gm.machine_state);
    crosshead::command(gm, state, speed);
    crosshead::write(gm, dt);
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
    use plc_core::motion::{AxisState, DriveState, command};

    /// A CiA 402 drive that takes each command at once and is where it is told to be: the
    /// crosshead's drive without a bus.
    struct Drive {
        state: DriveState,
        position: i32,
        error_code: u16,
        last_controlword: u16,
    }

    impl Drive {
        fn new() -> Drive {
            Drive {
                state: DriveState::SwitchOnDisabled,
                position: 0,
                error_code: 0,
                last_controlword: 0,
            }
        }

        /// Takes the program's outputs and sets its inputs, as an exchange would.
        fn exchange(&mut self, gm: &mut Gm) {
            let cw = gm.crosshead_controlword;
            let reset =
                cw & command::FAULT_RESET != 0 && self.last_controlword & command::FAULT_RESET == 0;
            self.last_controlword = cw;
            use DriveState::*;
            self.state = match (self.state, cw & 0x0F) {
                (Fault, _) if reset => {
                    self.error_code = 0;
                    SwitchOnDisabled
                }
                (Fault, _) => Fault,
                (_, 0x06) => ReadyToSwitchOn,
                (ReadyToSwitchOn | SwitchedOn | OperationEnabled, 0x07) => SwitchedOn,
                (SwitchedOn | OperationEnabled, 0x0F) => OperationEnabled,
                (s, 0x07 | 0x0F) => s,
                _ => SwitchOnDisabled,
            };
            if self.state == OperationEnabled {
                self.position = gm.crosshead_target_position;
            }
            gm.crosshead_statusword = self.state.statusword_bits();
            gm.crosshead_mode_display = gm.crosshead_mode;
            gm.crosshead_position = self.position;
            gm.crosshead_error_code = self.error_code;
        }

        fn fault(&mut self, code: u16) {
            self.state = DriveState::Fault;
            self.error_code = code;
        }
    }

    const CYCLE: Duration = Duration::from_millis(10);

    /// `n` cycles of 10 ms from `start_ms`, each exchanging with `drive` first.
    fn run(gm: &mut Gm, drive: &mut Drive, start_ms: i64, n: i64) {
        for k in 0..n {
            drive.exchange(gm);
            process_tick(
                gm,
                TickInfo {
                    period: CYCLE,
                    inputs_valid: true,
                    now: Time::from_millis(start_ms + 10 * k),
                },
            );
        }
    }

    /// A machine started and powered, its crosshead homed, waiting for a start.
    fn powered() -> (Gm, Drive) {
        let mut gm = Gm::default();
        gm.auto_start = false;
        let mut drive = Drive::new();
        run(&mut gm, &mut drive, 0, 10);
        assert!(gm.power.Status && gm.crosshead.homed && gm.to_start.Done);
        assert_eq!(gm.machine_state, State::Idle as u8);
        (gm, drive)
    }

    #[test]
    fn a_test_pulls_with_the_crosshead_until_the_break_and_stops_it() {
        let (mut gm, mut drive) = powered();
        gm.cmd_start = true;
        run(&mut gm, &mut drive, 0, 1);
        assert_eq!(gm.machine_state, State::Centering as u8);
        run(&mut gm, &mut drive, 0, 1);
        assert!(gm.cr_centering_drive);
        gm.ls_centering_neg = true;
        gm.ls_centering_pos = true;
        gm.ls_lift_neg = true;
        run(&mut gm, &mut drive, 0, 1);
        assert_eq!(gm.machine_state, State::Lifting as u8);
        gm.ls_lift_neg = false;
        run(&mut gm, &mut drive, 0, 60);
        assert_eq!(gm.machine_state, State::Testing as u8);
        assert!(gm.cr_test_drive && gm.lamp_yellow);
        // At the test speed of 2 mm/s (reached after 0.04 s at 50 mm/s²): 4 mm in 2 s.
        run(&mut gm, &mut drive, 0, 10);
        assert!(gm.test_move.InVelocity);
        let before = gm.crosshead.actual_position;
        run(&mut gm, &mut drive, 0, 200);
        assert_eq!(gm.crosshead.state(), AxisState::ContinuousMotion);
        let travel = gm.crosshead.actual_position - before;
        assert!((travel - 4.0).abs() < 1e-3, "pulled {travel} mm");
        // The elongation is the travel since the test started, as the drive measured it.
        let since_start = gm.crosshead.actual_position - gm.test_start_mm;
        assert!(
            (gm.elongation_mm - since_start).abs() < 0.03,
            "{}",
            gm.elongation_mm
        );
        assert!(gm.force_kn > 0.0);
        gm.specimen_broken = true;
        run(&mut gm, &mut drive, 0, 2);
        assert_eq!(gm.machine_state, State::Done as u8);
        assert_eq!(gm.tests_completed, 1);
        assert!(gm.max_force_kn > 0.0);
        assert!(!gm.cr_test_drive);
        // MC_Stop brakes at 100 mm/s²: at rest within 20 ms, 0.02 mm further.
        run(&mut gm, &mut drive, 0, 5);
        assert!(gm.stop.Done && !gm.test_move.Busy);
        assert_eq!(gm.crosshead.state(), AxisState::Stopping);
        let rest = gm.crosshead.actual_position;
        run(&mut gm, &mut drive, 0, 10);
        assert_eq!(gm.crosshead.actual_position, rest, "held where it stopped");
        assert_eq!(gm.axes[axis::TEST_DRIVE].pos_mm, gm.elongation_mm);
        assert_eq!(
            gm.axes[axis::TEST_DRIVE].moves,
            1,
            "the test drive's move completed"
        );
        assert!(!gm.axes[axis::TEST_DRIVE].enable);
        // Idle again, the crosshead goes back to its start for the next test.
        gm.specimen_broken = false;
        run(&mut gm, &mut drive, 0, 200);
        assert_eq!(gm.machine_state, State::Idle as u8);
        assert!(gm.to_start.Done && gm.crosshead.actual_position.abs() < 1e-6);
    }

    #[test]
    fn a_start_waits_for_the_crosshead_to_be_powered_and_homed() {
        let mut gm = Gm::default();
        gm.cmd_start = true;
        let mut drive = Drive::new();
        run(&mut gm, &mut drive, 0, 1);
        assert_eq!(gm.machine_state, State::Idle as u8);
        assert!(
            gm.cmd_start,
            "the start is kept until the crosshead is ready"
        );
        run(&mut gm, &mut drive, 10, 10);
        assert_eq!(gm.machine_state, State::Centering as u8);
        assert!(gm.home.Done || gm.crosshead.homed);
    }

    #[test]
    fn a_drive_fault_faults_the_machine_and_the_operators_reset_clears_it() {
        let (mut gm, mut drive) = powered();
        gm.machine_state = State::Testing as u8;
        run(&mut gm, &mut drive, 0, 50);
        assert_eq!(gm.crosshead.state(), AxisState::ContinuousMotion);
        drive.fault(0x8611);
        run(&mut gm, &mut drive, 0, 2);
        assert_eq!(gm.machine_state, State::Fault as u8);
        assert_eq!(
            gm.fault_text.as_str(),
            "crosshead drive fault 16#8611: reset to go on"
        );
        assert!(gm.lamp_red && !gm.cr_test_drive);
        assert_eq!(gm.crosshead.state(), AxisState::ErrorStop);
        assert_eq!((gm.power.Error, gm.power.ErrorID), (true, 0x8611));
        // Nothing happens until the operator acknowledges.
        run(&mut gm, &mut drive, 0, 20);
        assert_eq!(gm.machine_state, State::Fault as u8);
        gm.cmd_reset = true;
        run(&mut gm, &mut drive, 0, 10);
        assert!(!gm.cmd_reset);
        assert_eq!(gm.machine_state, State::Idle as u8);
        assert!(gm.fault_text.is_empty());
        assert_eq!(gm.crosshead.error_id, 0);
        run(&mut gm, &mut drive, 0, 200);
        assert!(gm.power.Status && gm.to_start.Done, "{:?}", gm.crosshead);
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
        let (mut gm, mut drive) = powered();
        gm.cmd_start = true;
        let tick = |gm: &mut Gm, drive: &mut Drive, ms: i64| run(gm, drive, ms, 1);
        tick(&mut gm, &mut drive, 0);
        assert_eq!(gm.machine_state, State::Centering as u8);
        tick(&mut gm, &mut drive, 10);
        assert!(gm.centering_timeout.IN && !gm.centering_timeout.Q);
        tick(&mut gm, &mut drive, 4_000);
        assert_eq!(gm.centering_timeout.ET, Time::from_millis(3_990));
        assert_eq!(gm.machine_state, State::Centering as u8);
        tick(&mut gm, &mut drive, 5_010);
        assert_eq!(gm.machine_state, State::Fault as u8);
        assert_eq!(
            gm.fault_text.as_str(),
            "centering jaws did not close within 5 s"
        );
        tick(&mut gm, &mut drive, 5_020);
        assert!(
            !gm.centering_timeout.Q,
            "the timer resets when the step ends"
        );
    }
}
