//! The test crosshead: a servo axis on the AKD (CiA 402, cyclic synchronous position), driven
//! with PLCopen blocks as docs/motion.md shows. The drive's entries are linked at the top
//! level of [`Gm`]; each cycle [`read`] copies them into the axis, the machine's state picks
//! the blocks' inputs ([`command`]), and [`write()`] advances the set point and copies the
//! drive's targets out.

use super::vars::{Gm, State};
use plc_core::motion::AxisState;

/// Drive increments per mm of crosshead travel: the AKD's 2^20 increments per motor
/// revolution, on a ball screw of 10 mm lead.
pub const INCREMENTS_PER_MM: f64 = 1_048_576.0 / 10.0;

/// Ramps of the test move (mm/s²): the test speed is reached within 0.2 mm of travel.
const TEST_ACCELERATION_MM_S2: f64 = 50.0;
/// The stop at a specimen's break or a fault, mm/s².
const STOP_DECELERATION_MM_S2: f64 = 100.0;
/// Back to the start position (0 mm) after a test: speed and ramps.
const RETURN_SPEED_MM_S: f64 = 20.0;
const RETURN_ACCELERATION_MM_S2: f64 = 100.0;

/// The drive's inputs into the axis, then power (always on) and homing (once, where the
/// crosshead stands: 0 mm).
pub fn read(gm: &mut Gm) {
    gm.crosshead.scale = INCREMENTS_PER_MM;
    let d = &mut gm.crosshead.drive;
    d.statusword = gm.crosshead_statusword;
    d.modes_of_operation_display = gm.crosshead_mode_display;
    d.position_actual_value = gm.crosshead_position;
    d.velocity_actual_value = gm.crosshead_velocity;
    d.following_error_actual_value = gm.crosshead_following_error;
    d.error_code = gm.crosshead_error_code;
    gm.crosshead.read_drive();
    gm.power.call(&mut gm.crosshead, true);
    let unhomed = gm.power.Status && !gm.crosshead.homed;
    gm.home.call(&mut gm.crosshead, unhomed, 0.0);
}

/// Whether the crosshead is ready for a test: powered, homed, back at its start position.
pub fn ready(gm: &Gm) -> bool {
    gm.power.Status && gm.crosshead.homed && gm.to_start.Done
}

/// Whether the drive faulted (the axis is in ErrorStop until MC_Reset).
pub fn faulted(gm: &Gm) -> bool {
    gm.crosshead.state() == AxisState::ErrorStop
}

/// The motion the machine's state asks for: the test move at `speed_mm_s` while testing,
/// MC_Stop holding the crosshead after the break and in a fault, back to the start while idle.
pub fn command(gm: &mut Gm, state: State, speed_mm_s: f64) {
    let axis = &mut gm.crosshead;
    gm.test_move.call(
        axis,
        state == State::Testing,
        speed_mm_s,
        TEST_ACCELERATION_MM_S2,
        STOP_DECELERATION_MM_S2,
        1.0,
    );
    gm.stop.call(
        axis,
        matches!(state, State::Done | State::Fault),
        STOP_DECELERATION_MM_S2,
    );
    let idle = state == State::Idle && gm.power.Status && axis.homed;
    gm.to_start.call(
        axis,
        idle,
        0.0,
        RETURN_SPEED_MM_S,
        RETURN_ACCELERATION_MM_S2,
        RETURN_ACCELERATION_MM_S2,
    );
}

/// Advances the set point by the cycle's `period_s` and copies the drive's targets out.
pub fn write(gm: &mut Gm, period_s: f64) {
    gm.crosshead.cycle(period_s);
    let d = &gm.crosshead.drive;
    gm.crosshead_controlword = d.controlword;
    gm.crosshead_mode = d.modes_of_operation;
    gm.crosshead_target_position = d.target_position;
    gm.crosshead_target_velocity = d.target_velocity;
}

/// The PLCopen state of an axis as the status line shows it.
pub fn state_name(state: u8) -> &'static str {
    match AxisState::from_u8(state) {
        AxisState::Disabled => "disabled",
        AxisState::Standstill => "standstill",
        AxisState::Homing => "homing",
        AxisState::DiscreteMotion => "discrete motion",
        AxisState::ContinuousMotion => "continuous motion",
        AxisState::Stopping => "stopping",
        AxisState::ErrorStop => "error stop",
    }
}
