//! The tensile tester's variables: [`Gm`], the drives' view of the HMI ([`Axis`]) and the
//! machine's states as `machine_state` holds them ([`State`]).

use plc_core::fb::Ton;
use plc_core::motion::{self, McHome, McMoveAbsolute, McMoveVelocity, McPower, McReset, McStop};
use plc_core::{FixedString, GlobalMemory, PlcStruct};

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
    /// Where the drive is
    #[plc(unit = "mm")]
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
    /// Guard door open: input 5 of the real impact67, a safety relay's door-open contact. The
    /// relay stops the drives; this tells the operator why. The simulated EL1004 has 4
    /// channels, so the bit reads 0 (closed) there; `plc force` opens the door.
    #[plc(
        source = "impact67_0_digital_inputs",
        bit = 4,
        alarm(text = "Guard door open", severity = 900)
    )]
    pub guard_door_open: bool,
    /// Crosshead beyond its travel (overtravel limit switch): input 6 of the real impact67,
    /// 0 on the simulated bus as `guard_door_open` is
    #[plc(
        source = "impact67_0_digital_inputs",
        bit = 5,
        alarm(text = "Crosshead overtravel", severity = 900)
    )]
    pub ls_crosshead_overtravel: bool,
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
    #[plc(
        link = "ethercat.crosshead.target_position",
        direction = "output",
        unit = "inc"
    )]
    pub crosshead_target_position: i32,
    /// Crosshead drive: target velocity in increments/s (0x60FF)
    #[plc(
        link = "ethercat.crosshead.target_velocity",
        direction = "output",
        unit = "inc/s"
    )]
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
    /// Crosshead drive: measured position in increments (0x6064); the encoder's last counts
    /// jitter, so a change is published once it moved by more than 2
    #[plc(
        link = "ethercat.crosshead.position_actual_value",
        direction = "input",
        unit = "inc",
        deadband = 2
    )]
    pub crosshead_position: i32,
    /// Crosshead drive: measured velocity in increments/s (0x606C), published once it moved
    /// by more than 10
    #[plc(
        link = "ethercat.crosshead.velocity_actual_value",
        direction = "input",
        unit = "inc/s",
        deadband = 10
    )]
    pub crosshead_velocity: i32,
    /// Crosshead drive: following error in increments (0x60F4)
    #[plc(
        link = "ethercat.crosshead.following_error_actual_value",
        direction = "input",
        unit = "inc"
    )]
    pub crosshead_following_error: i32,
    /// Crosshead drive: error code of its last fault (0x603F, 0 none). Any code raises the
    /// drive fault alarm (a limit at 1: every code is at or above it); the operator reads
    /// the code here. Not latched: the code stays until MC_Reset clears the fault, and the
    /// alarm with it
    #[plc(
        link = "ethercat.crosshead.error_code",
        direction = "input",
        alarm(text = "Crosshead drive fault", high = 1, severity = 800)
    )]
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
    #[plc(nonvolatile, initial = 12.5, unit = "mm")]
    pub press_home_offset_mm: f64,
    /// Lift zero offset in mm
    #[plc(nonvolatile, initial = 0.0, unit = "mm")]
    pub lift_zero_offset_mm: f64,
    /// Test speed setpoint in mm/s (the HMI's to set, 0.1 to 10; kept across restarts)
    #[plc(direction = "command", nonvolatile, initial = 2.0, unit = "mm/s")]
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
    /// Simulated force: the load cell's noise is published only once the force moved by
    /// more than 0.05 kN. The frame is rated 16 kN: a warning from 15 kN, above the rating
    /// from 16 kN, each held 50 ms so one noisy reading raises nothing (the simulated
    /// specimens break by 14.1 kN)
    #[plc(
        direction = "status",
        quantity = "force",
        unit = "kN",
        deadband = 0.05,
        alarm(
            text = "Force above the machine's rating",
            high = 15.0,
            high_high = 16.0,
            deadband = 0.5,
            delay = "50ms",
            severity = 800
        )
    )]
    pub force_kn: f64,
    /// Elongation: the crosshead's travel since the test started, published once it moved by
    /// more than 0.01 mm
    #[plc(
        direction = "status",
        quantity = "length",
        unit = "mm",
        deadband = 0.01
    )]
    pub elongation_mm: f64,
    /// Where the crosshead stood when the test started
    #[plc(direction = "status", quantity = "length", unit = "mm")]
    pub test_start_mm: f64,
    /// Largest force of the last test
    #[plc(direction = "status", quantity = "force", unit = "kN")]
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
    /// The centering jaws did not close within 5 s: set with that fault, cleared when the
    /// fault is reset. Its own variable because an alarm cannot be declared on
    /// `centering_timeout.Q`, a member of a block declared in plc-core
    #[plc(
        direction = "status",
        alarm(text = "Specimen not centred in time", severity = 600)
    )]
    pub centering_timed_out: bool,
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
    /// The state `machine_state` holds (an unknown number reads as Idle).
    pub(super) fn from_u8(v: u8) -> State {
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
