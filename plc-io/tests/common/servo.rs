//! The servo tests' program: the simulated AKD's entries (device `servo`) linked at the top
//! level and copied into a `plc_core::motion` axis and back each cycle, as docs/motion.md
//! shows, with the PLCopen blocks the tests call.
// Each test binary uses a different subset of these helpers.
#![allow(dead_code)]

use plc_core::GlobalMemory;
use plc_core::motion::{Axis, McHome, McMoveAbsolute, McPower, McReset, McStop};

/// The drive's 2^20 increments per revolution, one revolution per 10 mm of travel.
pub const SCALE: f64 = 1_048_576.0 / 10.0;

#[derive(GlobalMemory, Debug, Clone)]
pub struct Machine {
    #[plc(link = "ethercat.servo.controlword", direction = "output")]
    pub controlword: u16,
    #[plc(link = "ethercat.servo.modes_of_operation", direction = "output")]
    pub mode: i8,
    #[plc(link = "ethercat.servo.target_position", direction = "output")]
    pub target_position: i32,
    #[plc(link = "ethercat.servo.target_velocity", direction = "output")]
    pub target_velocity: i32,
    #[plc(link = "ethercat.servo.statusword", direction = "input")]
    pub statusword: u16,
    #[plc(
        link = "ethercat.servo.modes_of_operation_display",
        direction = "input"
    )]
    pub mode_display: i8,
    #[plc(link = "ethercat.servo.position_actual_value", direction = "input")]
    pub position: i32,
    #[plc(link = "ethercat.servo.velocity_actual_value", direction = "input")]
    pub velocity: i32,
    #[plc(
        link = "ethercat.servo.following_error_actual_value",
        direction = "input"
    )]
    pub following_error: i32,
    #[plc(link = "ethercat.servo.error_code", direction = "input")]
    pub error_code: u16,
    /// The crosshead, in mm.
    #[plc(quantity = "length")]
    pub axis: Axis,
    pub power: McPower,
    pub home: McHome,
    pub move_to: McMoveAbsolute,
    pub stop: McStop,
    pub reset: McReset,
}

impl Machine {
    /// A machine whose axis has the drive's [`SCALE`].
    pub fn new() -> Machine {
        let mut gm = Machine::default();
        gm.axis.scale = SCALE;
        gm
    }

    /// One cycle of `program` at 1 ms: the drive's inputs into the axis, `program` (the
    /// blocks), the axis's cycle, its outputs to the drive.
    pub fn cycle(&mut self, program: impl FnOnce(&mut Machine)) {
        let d = &mut self.axis.drive;
        d.statusword = self.statusword;
        d.modes_of_operation_display = self.mode_display;
        d.position_actual_value = self.position;
        d.velocity_actual_value = self.velocity;
        d.following_error_actual_value = self.following_error;
        d.error_code = self.error_code;
        self.axis.read_drive();
        program(self);
        self.axis.cycle(0.001);
        let d = &self.axis.drive;
        self.controlword = d.controlword;
        self.mode = d.modes_of_operation;
        self.target_position = d.target_position;
        self.target_velocity = d.target_velocity;
    }
}
