//! An axis as PLCopen Motion Control sees it (its `AXIS_REF`): a CiA 402 drive, the scale from
//! the drive's increments to the user's units, the PLCopen state, and the set point the
//! motion blocks command. The program calls the blocks, then [`Axis::cycle`] once per cycle,
//! which advances the set point by the cycle's period and writes the drive's targets.

use super::cia402::{Cia402, DriveState, command, mode};
use super::error;
use super::profile::{Limits, SetPoint};

/// The PLCopen states of an axis (PLCopen Motion Control part 1, the state diagram).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u8)]
pub enum AxisState {
    /// Not powered.
    Disabled = 0,
    /// Powered, at rest.
    Standstill = 1,
    /// Being homed.
    Homing = 2,
    /// Moving to a position.
    DiscreteMotion = 3,
    /// Moving at a speed.
    ContinuousMotion = 4,
    /// Stopping under `MC_Stop`: no move is taken until it is released.
    Stopping = 5,
    /// Stopped by an error: `MC_Reset` first.
    ErrorStop = 6,
}

impl AxisState {
    /// The state stored as `n` (an unknown number reads as ErrorStop).
    pub fn from_u8(n: u8) -> AxisState {
        match n {
            0 => AxisState::Disabled,
            1 => AxisState::Standstill,
            2 => AxisState::Homing,
            3 => AxisState::DiscreteMotion,
            4 => AxisState::ContinuousMotion,
            5 => AxisState::Stopping,
            _ => AxisState::ErrorStop,
        }
    }
}

/// What the set point does.
pub(crate) mod motion {
    /// Nothing: it holds.
    pub const HOLD: u8 = 0;
    /// Goes to `target`.
    pub const POSITION: u8 = 1;
    /// Runs at `target` units per second.
    pub const VELOCITY: u8 = 2;
}

/// One axis: a drive and what PLCopen keeps of it. Positions are in user units (`scale`
/// increments each; `quantity` on the program's variable names the unit), velocities in
/// units per second. Every member is in the image, so tools and OPC UA see the axis's state.
///
/// ```
/// use plc_core::motion::{Axis, AxisState};
/// let axis = Axis::default();
/// assert_eq!(axis.state(), AxisState::Disabled);
/// assert_eq!(axis.scale, 1000.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, plc_derive::PlcStruct)]
#[plc(crate = "crate", name = "AXIS_REF")]
pub struct Axis {
    /// The drive's process data.
    pub drive: Cia402,
    /// Drive increments per user unit.
    #[plc(initial = 1000.0)]
    pub scale: f64,
    /// The PLCopen state ([`AxisState`] as a number).
    pub state: u8,
    /// The measured position, in user units.
    pub actual_position: f64,
    /// The measured velocity, in units per second.
    pub actual_velocity: f64,
    /// The set point's position, what the drive is told to follow.
    pub set_position: f64,
    /// The set point's velocity.
    pub set_velocity: f64,
    /// Where the set point goes (a position) or how fast (a velocity), by `motion`.
    pub target: f64,
    /// What the set point does: 0 holds, 1 goes to a position, 2 runs at a speed.
    pub motion: u8,
    /// The limits of the running motion.
    pub velocity_limit: f64,
    /// The acceleration of the running motion.
    pub acceleration: f64,
    /// The deceleration of the running motion.
    pub deceleration: f64,
    /// Whether the running motion has arrived (on its position, or at its speed).
    #[plc(initial = true)]
    pub arrived: bool,
    /// The number of the command that owns the axis: each move that starts takes the next,
    /// and a block whose number it no longer is was aborted.
    pub command: u32,
    /// The drive's position, in increments, that reads as user position 0 (set by homing).
    pub origin: i64,
    /// Whether the axis was homed.
    pub homed: bool,
    /// The error that stopped the axis (0 none; see `motion::error`).
    pub error_id: u16,
    /// Whether power is asked for (by `MC_Power`).
    pub power: bool,
    /// The controlword of the previous cycle (a fault reset acts on its rising edge).
    pub last_controlword: u16,
    /// A fault reset is asked for (by `MC_Reset`).
    pub fault_reset: bool,
}

/// `x` rounded to the nearest integer, saturating (no_std has no `f64::round`).
fn round(x: f64) -> i64 {
    if x.is_nan() {
        0
    } else if x >= 0.0 {
        (x + 0.5) as i64
    } else {
        (x - 0.5) as i64
    }
}

impl Axis {
    /// The PLCopen state.
    pub fn state(&self) -> AxisState {
        AxisState::from_u8(self.state)
    }

    pub(crate) fn set_state(&mut self, s: AxisState) {
        self.state = s as u8;
    }

    /// Whether the drive follows its targets and the axis takes moves.
    pub fn powered(&self) -> bool {
        self.drive.state() == DriveState::OperationEnabled && self.power
    }

    /// Stops the axis for `id` (PLCopen's ErrorStop): the set point decelerates to rest.
    pub fn error_stop(&mut self, id: u16) {
        if self.error_id == 0 {
            self.error_id = id;
        }
        self.set_state(AxisState::ErrorStop);
        self.command = self.command.wrapping_add(1);
        self.motion = motion::VELOCITY;
        self.target = 0.0;
        self.arrived = false;
    }

    /// Starts a motion for a new command; its number. Moves of a stopping or stopped axis are
    /// refused with the reason's error id.
    pub(crate) fn start(&mut self, motion: u8, target: f64, limits: Limits) -> Result<u32, u16> {
        if !limits.valid() || !target.is_finite() {
            return Err(error::INVALID_PARAMETER);
        }
        match self.state() {
            AxisState::Disabled => return Err(error::NOT_POWERED),
            AxisState::ErrorStop => return Err(error::ERROR_STOP),
            AxisState::Stopping => return Err(error::STOPPING),
            _ => {}
        }
        let state = if motion == self::motion::VELOCITY {
            AxisState::ContinuousMotion
        } else {
            AxisState::DiscreteMotion
        };
        Ok(self.take(motion, target, limits, state))
    }

    /// Starts a stop (`MC_Stop`) for a new command; its number. As PLCopen's state diagram
    /// has it, a stop takes the axis into Stopping from any powered state, Stopping included
    /// (a second stop takes over from the first); a disabled axis or one in ErrorStop refuses.
    pub(crate) fn stop(&mut self, limits: Limits) -> Result<u32, u16> {
        match self.state() {
            AxisState::Disabled => Err(error::NOT_POWERED),
            AxisState::ErrorStop => Err(error::ERROR_STOP),
            _ if !limits.valid() => Err(error::INVALID_PARAMETER),
            _ => Ok(self.take(motion::VELOCITY, 0.0, limits, AxisState::Stopping)),
        }
    }

    /// Gives the axis to a new command running `motion` towards `target` within `limits`, in
    /// `state`; the command's number.
    fn take(&mut self, motion: u8, target: f64, limits: Limits, state: AxisState) -> u32 {
        self.command = self.command.wrapping_add(1);
        self.motion = motion;
        self.target = target;
        self.velocity_limit = limits.velocity;
        self.acceleration = limits.acceleration;
        self.deceleration = limits.deceleration;
        self.arrived = false;
        self.set_state(state);
        self.command
    }

    /// Reads the drive's measured values into user units: call it first in the cycle, after
    /// the drive's inputs were copied into `drive`.
    pub fn read_drive(&mut self) {
        let scale = if self.scale == 0.0 { 1.0 } else { self.scale };
        let raw = i64::from(self.drive.position_actual_value) - self.origin;
        self.actual_position = raw as f64 / scale;
        self.actual_velocity = f64::from(self.drive.velocity_actual_value) / scale;
        if self.power && self.drive.faulted() && self.state() != AxisState::ErrorStop {
            self.error_stop(error::DRIVE_FAULT);
        }
    }

    /// Advances the set point by `period` seconds and writes the drive's targets: call it
    /// last in the cycle, after the blocks.
    pub fn cycle(&mut self, period: f64) {
        let dt = if period > 0.0 { period } else { 0.001 };
        if !self.powered() {
            // Not following: the set point follows the drive, so power does not jump.
            self.set_position = self.actual_position;
            self.set_velocity = 0.0;
        } else {
            let now = SetPoint {
                position: self.set_position,
                velocity: self.set_velocity,
            };
            let limits = Limits {
                velocity: self.velocity_limit,
                acceleration: self.acceleration,
                deceleration: self.deceleration,
            };
            let (next, arrived) = match self.motion {
                motion::POSITION if limits.valid() => now.towards(self.target, &limits, dt),
                motion::VELOCITY if limits.valid() => now.at_speed(self.target, &limits, dt),
                _ => (
                    SetPoint {
                        position: now.position,
                        velocity: 0.0,
                    },
                    true,
                ),
            };
            self.set_position = next.position;
            self.set_velocity = next.velocity;
            self.arrived = arrived;
            if arrived && self.motion == motion::POSITION {
                self.motion = motion::HOLD;
                if self.state() == AxisState::DiscreteMotion {
                    self.set_state(AxisState::Standstill);
                }
            }
            if arrived && self.target == 0.0 && self.motion == motion::VELOCITY {
                // A stop (or an error stop) that has come to rest.
                self.motion = motion::HOLD;
            }
        }
        let raw = round(self.set_position * self.scale) + self.origin;
        self.drive.target_position = raw.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32;
        let v = round(self.set_velocity * self.scale);
        self.drive.target_velocity = v.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32;
        self.drive.modes_of_operation = mode::CSP;
        self.drive.controlword = self.controlword();
        self.last_controlword = self.drive.controlword;
    }

    /// The controlword for this cycle: towards operation enabled while power is asked for,
    /// disable voltage otherwise.
    fn controlword(&self) -> u16 {
        if self.fault_reset && self.drive.faulted() {
            // A rising edge of bit 7 each second cycle until the drive leaves its fault.
            return if self.last_controlword & command::FAULT_RESET == 0 {
                command::FAULT_RESET
            } else {
                command::DISABLE_VOLTAGE
            };
        }
        if !self.power {
            return command::DISABLE_VOLTAGE;
        }
        Cia402::towards_enabled(self.drive.state())
    }
}
