//! The PLCopen Motion Control function blocks, with PLCopen's member names, as plain structs
//! that live in the program's image (tools and OPC UA see `power.Status`, `move_to.Busy`).
//!
//! What the blocks of one kind share, as PLCopen part 1 says: `Execute`'s rising edge starts
//! a block; `Busy` while it has not finished; `Done`, `Error` (with `ErrorID`) or
//! `CommandAborted` (another block took the axis) when it has; those three are reset on the
//! falling edge of `Execute`, or shown for one call if `Execute` fell before the end.

use super::axis::{Axis, AxisState, motion};
use super::error;
use super::profile::Limits;

/// The outputs and state every executing block has.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Run {
    done: bool,
    busy: bool,
    active: bool,
    aborted: bool,
    error: bool,
    error_id: u16,
}

/// What the common part of a block decides in a call.
enum Step {
    /// `Execute` rose: start.
    Start,
    /// Running, still owning the axis.
    Running,
    /// Nothing to do.
    Idle,
}

/// The common part: `Execute`'s edge, `CommandAborted` and the axis's error.
fn step(run: &mut Run, last: &mut bool, id: u32, axis: &Axis, execute: bool) -> Step {
    let rising = execute && !*last;
    *last = execute;
    if rising {
        *run = Run::default();
        return Step::Start;
    }
    if run.busy {
        if axis.state() == AxisState::ErrorStop && axis.command != id {
            *run = Run {
                error: true,
                error_id: axis.error_id,
                ..Run::default()
            };
        } else if axis.command != id {
            *run = Run {
                aborted: true,
                ..Run::default()
            };
        } else {
            return Step::Running;
        }
        return Step::Idle;
    }
    if !execute {
        // The falling edge resets the outputs (after they were shown once).
        *run = Run::default();
    }
    Step::Idle
}

/// Starts a block's command: busy with its number, or the error.
fn started(run: &mut Run, started: Result<u32, u16>) -> u32 {
    match started {
        Ok(id) => {
            run.busy = true;
            run.active = true;
            id
        }
        Err(e) => {
            run.error = true;
            run.error_id = e;
            0
        }
    }
}

macro_rules! outputs {
    ($fb:ident) => {
        impl $fb {
            fn outputs(&mut self, run: Run) {
                self.Done = run.done;
                self.Busy = run.busy;
                self.Active = run.active;
                self.CommandAborted = run.aborted;
                self.Error = run.error;
                self.ErrorID = run.error_id;
            }

            fn run(&self) -> Run {
                Run {
                    done: self.Done,
                    busy: self.Busy,
                    active: self.Active,
                    aborted: self.CommandAborted,
                    error: self.Error,
                    error_id: self.ErrorID,
                }
            }
        }
    };
}

/// MC_Power: powers the axis's drive (the CiA 402 state machine to operation enabled) while
/// `Enable` is TRUE, and off when it is FALSE.
///
/// ```
/// use plc_core::motion::{Axis, McPower};
/// let mut axis = Axis::default();
/// let mut power = McPower::default();
/// power.call(&mut axis, true);
/// assert!(!power.Status, "the drive is not enabled yet");
/// assert!(axis.power);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, plc_derive::PlcStruct)]
#[plc(crate = "crate", name = "MC_Power", __iec_standard)]
#[allow(non_snake_case)]
pub struct McPower {
    /// Input: power on while TRUE.
    #[plc(direction = "input")]
    pub Enable: bool,
    /// Output: the drive is powered and follows the axis's set point.
    #[plc(direction = "output")]
    pub Status: bool,
    /// Output: `Status` is valid (the drive reports a state).
    #[plc(direction = "output")]
    pub Valid: bool,
    /// Output: the drive faulted.
    #[plc(direction = "output")]
    pub Error: bool,
    /// Output: the drive's error code (0x603F), or why power is refused.
    #[plc(direction = "output")]
    pub ErrorID: u16,
}

impl McPower {
    /// Runs the block for `axis` with `Enable = enable`; returns `Status`.
    pub fn call(&mut self, axis: &mut Axis, enable: bool) -> bool {
        self.Enable = enable;
        axis.power = enable;
        let state = axis.drive.state();
        self.Valid = state != super::DriveState::NotReadyToSwitchOn;
        self.Error = axis.drive.faulted();
        self.ErrorID = if self.Error { axis.drive.error_code } else { 0 };
        self.Status = axis.powered();
        match axis.state() {
            AxisState::Disabled if self.Status => axis.set_state(AxisState::Standstill),
            AxisState::ErrorStop => {}
            _ if !enable || !self.Status => {
                axis.set_state(AxisState::Disabled);
                axis.command = axis.command.wrapping_add(1);
                axis.motion = motion::HOLD;
            }
            _ => {}
        }
        self.Status
    }
}

/// MC_Home, homing on the current position: the axis's position becomes `Position` where it
/// stands (CiA 402 homing method 37 does the same in the drive).
#[derive(Clone, Copy, Debug, PartialEq, plc_derive::PlcStruct)]
#[plc(crate = "crate", name = "MC_Home", __iec_standard)]
#[allow(non_snake_case)]
pub struct McHome {
    /// Input: homes on its rising edge.
    #[plc(direction = "input")]
    pub Execute: bool,
    /// Input: the position the axis reads where it stands, in user units.
    #[plc(direction = "input")]
    pub Position: f64,
    /// Output: homed.
    #[plc(direction = "output")]
    pub Done: bool,
    /// Output: homing.
    #[plc(direction = "output")]
    pub Busy: bool,
    /// Output: owns the axis.
    #[plc(direction = "output")]
    pub Active: bool,
    /// Output: another block took the axis.
    #[plc(direction = "output")]
    pub CommandAborted: bool,
    /// Output: refused or failed.
    #[plc(direction = "output")]
    pub Error: bool,
    /// Output: why.
    #[plc(direction = "output")]
    pub ErrorID: u16,
    /// State: `Execute` of the previous call.
    pub M: bool,
}

outputs!(McHome);

impl McHome {
    /// Runs the block for `axis`; returns `Done`.
    pub fn call(&mut self, axis: &mut Axis, execute: bool, position: f64) -> bool {
        self.Execute = execute;
        self.Position = position;
        let mut run = self.run();
        if let Step::Start = step(&mut run, &mut self.M, 0, axis, execute) {
            let refused = match axis.state() {
                AxisState::Disabled => Some(error::NOT_POWERED),
                AxisState::ErrorStop => Some(error::ERROR_STOP),
                AxisState::Standstill if position.is_finite() => None,
                AxisState::Standstill => Some(error::INVALID_PARAMETER),
                _ => Some(error::NOT_AT_STANDSTILL),
            };
            match refused {
                Some(e) => {
                    run.error = true;
                    run.error_id = e;
                }
                None => {
                    let here = (position * axis.scale) as i64;
                    axis.origin = i64::from(axis.drive.position_actual_value) - here;
                    axis.command = axis.command.wrapping_add(1);
                    axis.read_drive();
                    axis.set_position = axis.actual_position;
                    axis.homed = true;
                    run.done = true;
                }
            }
        }
        self.outputs(run);
        self.Done
    }
}

/// The members of the moving blocks (MC_MoveAbsolute, MC_MoveRelative, MC_MoveVelocity).
macro_rules! move_block {
    ($(#[$doc:meta])* $fb:ident, $name:literal, $target:ident, $target_doc:literal, $reached:ident, $reached_doc:literal) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, PartialEq, plc_derive::PlcStruct)]
        #[plc(crate = "crate", name = $name, __iec_standard)]
        #[allow(non_snake_case)]
        pub struct $fb {
            /// Input: starts on its rising edge.
            #[plc(direction = "input")]
            pub Execute: bool,
            #[doc = $target_doc]
            #[plc(direction = "input")]
            pub $target: f64,
            /// Input: the highest speed, units per second.
            #[plc(direction = "input")]
            pub Velocity: f64,
            /// Input: units per second squared.
            #[plc(direction = "input")]
            pub Acceleration: f64,
            /// Input: units per second squared.
            #[plc(direction = "input")]
            pub Deceleration: f64,
            #[doc = $reached_doc]
            #[plc(direction = "output")]
            pub $reached: bool,
            /// Output: has not finished.
            #[plc(direction = "output")]
            pub Busy: bool,
            /// Output: owns the axis.
            #[plc(direction = "output")]
            pub Active: bool,
            /// Output: another block took the axis.
            #[plc(direction = "output")]
            pub CommandAborted: bool,
            /// Output: refused, or the axis stopped on an error.
            #[plc(direction = "output")]
            pub Error: bool,
            /// Output: why.
            #[plc(direction = "output")]
            pub ErrorID: u16,
            /// State: `Execute` of the previous call.
            pub M: bool,
            /// State: the number of the command it started.
            pub Id: u32,
        }

        impl $fb {
            fn outputs(&mut self, run: Run) {
                self.$reached = run.done;
                self.Busy = run.busy;
                self.Active = run.active;
                self.CommandAborted = run.aborted;
                self.Error = run.error;
                self.ErrorID = run.error_id;
            }

            fn run(&self) -> Run {
                Run {
                    done: self.$reached,
                    busy: self.Busy,
                    active: self.Active,
                    aborted: self.CommandAborted,
                    error: self.Error,
                    error_id: self.ErrorID,
                }
            }

            fn limits(&self) -> Limits {
                Limits {
                    velocity: self.Velocity,
                    acceleration: self.Acceleration,
                    deceleration: self.Deceleration,
                }
            }
        }
    };
}

move_block!(
    /// MC_MoveAbsolute: moves the axis to `Position` with a trapezoidal profile; a move
    /// started while another runs takes over from where the axis is (aborting it).
    ///
    /// ```
    /// use plc_core::motion::{Axis, McMoveAbsolute, error};
    /// let mut axis = Axis::default();
    /// let mut to = McMoveAbsolute::default();
    /// to.call(&mut axis, true, 100.0, 50.0, 500.0, 500.0);
    /// assert!(to.Error && to.ErrorID == error::NOT_POWERED);
    /// ```
    McMoveAbsolute, "MC_MoveAbsolute", Position, "Input: where to, in user units.", Done,
    "Output: on the position, at rest."
);
move_block!(
    /// MC_MoveRelative: moves the axis by `Distance` from its set position at the start.
    McMoveRelative, "MC_MoveRelative", Distance, "Input: how far, in user units (signed).",
    Done, "Output: moved, at rest."
);
move_block!(
    /// MC_MoveVelocity: runs the axis at `Velocity` (signed: the direction) until another
    /// block takes it; `InVelocity` once at that speed.
    McMoveVelocity, "MC_MoveVelocity", Direction, "Input: the direction, +1 or -1 (0 counts as +1).",
    InVelocity, "Output: at the speed asked for."
);

impl McMoveAbsolute {
    /// Runs the block for `axis`; returns `Done`.
    pub fn call(
        &mut self,
        axis: &mut Axis,
        execute: bool,
        position: f64,
        velocity: f64,
        acceleration: f64,
        deceleration: f64,
    ) -> bool {
        (self.Execute, self.Position, self.Velocity) = (execute, position, velocity);
        (self.Acceleration, self.Deceleration) = (acceleration, deceleration);
        let mut run = self.run();
        match step(&mut run, &mut self.M, self.Id, axis, execute) {
            Step::Start => {
                self.Id = started(
                    &mut run,
                    axis.start(motion::POSITION, position, self.limits()),
                )
            }
            Step::Running if axis.motion == motion::HOLD && axis.arrived => {
                run = Run {
                    done: true,
                    ..Run::default()
                };
            }
            _ => {}
        }
        self.outputs(run);
        self.Done
    }
}

impl McMoveRelative {
    /// Runs the block for `axis`; returns `Done`.
    pub fn call(
        &mut self,
        axis: &mut Axis,
        execute: bool,
        distance: f64,
        velocity: f64,
        acceleration: f64,
        deceleration: f64,
    ) -> bool {
        (self.Execute, self.Distance, self.Velocity) = (execute, distance, velocity);
        (self.Acceleration, self.Deceleration) = (acceleration, deceleration);
        let mut run = self.run();
        match step(&mut run, &mut self.M, self.Id, axis, execute) {
            Step::Start => {
                let to = axis.set_position + distance;
                self.Id = started(&mut run, axis.start(motion::POSITION, to, self.limits()));
            }
            Step::Running if axis.motion == motion::HOLD && axis.arrived => {
                run = Run {
                    done: true,
                    ..Run::default()
                };
            }
            _ => {}
        }
        self.outputs(run);
        self.Done
    }
}

impl McMoveVelocity {
    /// Runs the block for `axis`; returns `InVelocity`.
    pub fn call(
        &mut self,
        axis: &mut Axis,
        execute: bool,
        velocity: f64,
        acceleration: f64,
        deceleration: f64,
        direction: f64,
    ) -> bool {
        (self.Execute, self.Velocity, self.Direction) = (execute, velocity, direction);
        (self.Acceleration, self.Deceleration) = (acceleration, deceleration);
        let mut run = self.run();
        match step(&mut run, &mut self.M, self.Id, axis, execute) {
            Step::Start => {
                let sign = if direction < 0.0 { -1.0 } else { 1.0 };
                let limits = Limits {
                    // The speed asked for is the limit too.
                    velocity: velocity.abs().max(f64::MIN_POSITIVE),
                    ..self.limits()
                };
                let id = axis.start(motion::VELOCITY, sign * velocity.abs(), limits);
                self.Id = started(&mut run, id);
            }
            // InVelocity while at speed; the block stays busy until another takes the axis.
            Step::Running => run.done = axis.arrived,
            Step::Idle => {}
        }
        self.outputs(run);
        self.InVelocity
    }
}

/// MC_Stop: brings the axis to rest at `Deceleration` and holds it there (no move is taken)
/// while `Execute` stays TRUE.
#[derive(Clone, Copy, Debug, PartialEq, plc_derive::PlcStruct)]
#[plc(crate = "crate", name = "MC_Stop", __iec_standard)]
#[allow(non_snake_case)]
pub struct McStop {
    /// Input: stops on its rising edge; holds while TRUE.
    #[plc(direction = "input")]
    pub Execute: bool,
    /// Input: units per second squared.
    #[plc(direction = "input")]
    pub Deceleration: f64,
    /// Output: at rest.
    #[plc(direction = "output")]
    pub Done: bool,
    /// Output: stopping.
    #[plc(direction = "output")]
    pub Busy: bool,
    /// Output: owns the axis.
    #[plc(direction = "output")]
    pub Active: bool,
    /// Output: another block took the axis (an error stop).
    #[plc(direction = "output")]
    pub CommandAborted: bool,
    /// Output: refused.
    #[plc(direction = "output")]
    pub Error: bool,
    /// Output: why.
    #[plc(direction = "output")]
    pub ErrorID: u16,
    /// State: `Execute` of the previous call.
    pub M: bool,
    /// State: the number of its command.
    pub Id: u32,
}

outputs!(McStop);

impl McStop {
    /// Runs the block for `axis`; returns `Done`.
    pub fn call(&mut self, axis: &mut Axis, execute: bool, deceleration: f64) -> bool {
        (self.Execute, self.Deceleration) = (execute, deceleration);
        let mut run = self.run();
        match step(&mut run, &mut self.M, self.Id, axis, execute) {
            Step::Start => {
                let limits = Limits {
                    velocity: axis.set_velocity.abs().max(f64::MIN_POSITIVE),
                    acceleration: deceleration,
                    deceleration,
                };
                let id = match axis.state() {
                    AxisState::Disabled => Err(error::NOT_POWERED),
                    AxisState::ErrorStop => Err(error::ERROR_STOP),
                    _ if !limits.valid() => Err(error::INVALID_PARAMETER),
                    _ => {
                        // Any state but those: the stop takes the axis.
                        axis.set_state(AxisState::Standstill);
                        let id = axis.start(motion::VELOCITY, 0.0, limits);
                        axis.set_state(AxisState::Stopping);
                        id
                    }
                };
                self.Id = started(&mut run, id);
            }
            Step::Running if axis.motion == motion::HOLD || axis.arrived => {
                run.done = true;
                if !execute {
                    run = Run {
                        done: true,
                        ..Run::default()
                    };
                    axis.set_state(AxisState::Standstill);
                    axis.motion = motion::HOLD;
                }
            }
            _ => {}
        }
        self.outputs(run);
        self.Done
    }
}

/// MC_Reset: clears the axis's error (and resets the drive's fault) on `Execute`'s rising
/// edge; `Done` once the axis left ErrorStop.
#[derive(Clone, Copy, Debug, PartialEq, plc_derive::PlcStruct)]
#[plc(crate = "crate", name = "MC_Reset", __iec_standard)]
#[allow(non_snake_case)]
pub struct McReset {
    /// Input: resets on its rising edge.
    #[plc(direction = "input")]
    pub Execute: bool,
    /// Output: reset.
    #[plc(direction = "output")]
    pub Done: bool,
    /// Output: resetting (the drive has not left its fault yet).
    #[plc(direction = "output")]
    pub Busy: bool,
    /// Output: refused.
    #[plc(direction = "output")]
    pub Error: bool,
    /// Output: why.
    #[plc(direction = "output")]
    pub ErrorID: u16,
    /// State: `Execute` of the previous call.
    pub M: bool,
}

impl McReset {
    /// Runs the block for `axis`; returns `Done`.
    pub fn call(&mut self, axis: &mut Axis, execute: bool) -> bool {
        self.Execute = execute;
        let rising = execute && !self.M;
        self.M = execute;
        if rising {
            (self.Done, self.Error, self.ErrorID) = (false, false, 0);
            self.Busy = true;
            axis.fault_reset = true;
        }
        if self.Busy && !axis.drive.faulted() {
            axis.fault_reset = false;
            axis.error_id = 0;
            if axis.state() == AxisState::ErrorStop {
                let next = if axis.powered() {
                    AxisState::Standstill
                } else {
                    AxisState::Disabled
                };
                axis.set_state(next);
                axis.motion = motion::HOLD;
            }
            self.Busy = false;
            self.Done = true;
        } else if !execute && !self.Busy {
            self.Done = false;
        }
        self.Done
    }
}

/// MC_ReadActualPosition: the axis's measured position while `Enable` is TRUE.
#[derive(Clone, Copy, Debug, PartialEq, plc_derive::PlcStruct)]
#[plc(crate = "crate", name = "MC_ReadActualPosition", __iec_standard)]
#[allow(non_snake_case)]
pub struct McReadActualPosition {
    /// Input: reads while TRUE.
    #[plc(direction = "input")]
    pub Enable: bool,
    /// Output: `Position` is valid.
    #[plc(direction = "output")]
    pub Valid: bool,
    /// Output: reading.
    #[plc(direction = "output")]
    pub Busy: bool,
    /// Output: the drive faulted.
    #[plc(direction = "output")]
    pub Error: bool,
    /// Output: why.
    #[plc(direction = "output")]
    pub ErrorID: u16,
    /// Output: the measured position, in user units.
    #[plc(direction = "output")]
    pub Position: f64,
}

impl McReadActualPosition {
    /// Runs the block for `axis`; returns `Position`.
    pub fn call(&mut self, axis: &Axis, enable: bool) -> f64 {
        self.Enable = enable;
        self.Busy = enable;
        self.Error = enable && axis.drive.faulted();
        self.ErrorID = if self.Error { error::DRIVE_FAULT } else { 0 };
        self.Valid = enable && !self.Error;
        if self.Valid {
            self.Position = axis.actual_position;
        }
        self.Position
    }
}
