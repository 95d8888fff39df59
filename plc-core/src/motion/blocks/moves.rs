//! The moving blocks: `MC_MoveAbsolute` and `MC_MoveRelative` (one positioning move, which
//! differ only in where they go) and `MC_MoveVelocity`.

use super::run::{Run, Step, started, step};
use crate::motion::axis::{Axis, motion};
use crate::motion::profile::Limits;

/// A moving block (MC_MoveAbsolute, MC_MoveRelative, MC_MoveVelocity): its target input
/// (`$target`), its limits, what it reaches (`$reached`), and the number of its command.
macro_rules! move_block {
    ($(#[$doc:meta])* $fb:ident, $name:literal, $target:ident, $target_doc:literal, $reached:ident, $reached_doc:literal) => {
        execute_block! {
            $(#[$doc])*
            $fb = $name {
                Execute: "Input: starts on its rising edge.",
                inputs: {
                    #[doc = $target_doc]
                    $target: f64,
                    /// Input: the highest speed, units per second.
                    Velocity: f64,
                    /// Input: units per second squared.
                    Acceleration: f64,
                    /// Input: units per second squared.
                    Deceleration: f64,
                },
                $reached: $reached_doc,
                Busy: "Output: has not finished.",
                CommandAborted: "Output: another block took the axis.",
                Error: "Output: refused, or the axis stopped on an error.",
                state: {
                    /// State: the number of the command it started.
                    Id: u32,
                },
            }
        }

        impl $fb {
            /// Takes the call's inputs into the members; the limits they set.
            fn inputs(&mut self, execute: bool, target: f64, [v, a, d]: [f64; 3]) -> Limits {
                (self.Execute, self.$target) = (execute, target);
                (self.Velocity, self.Acceleration, self.Deceleration) = (v, a, d);
                Limits {
                    velocity: v,
                    acceleration: a,
                    deceleration: d,
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

/// One call of a positioning move (`MC_MoveAbsolute`, `MC_MoveRelative`): on `Execute`'s
/// rising edge it starts towards `to(axis)` as command `id`; done once the set point rests
/// there.
fn positioning(
    mut run: Run,
    (last, id): (&mut bool, &mut u32),
    axis: &mut Axis,
    execute: bool,
    limits: Limits,
    to: impl FnOnce(&Axis) -> f64,
) -> Run {
    match step(&mut run, last, Some(*id), axis, execute) {
        Step::Start => {
            let to = to(axis);
            *id = started(&mut run, axis.start(motion::POSITION, to, limits));
        }
        Step::Running if axis.motion == motion::HOLD && axis.arrived => run = Run::done(),
        _ => {}
    }
    run
}

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
        let limits = self.inputs(execute, position, [velocity, acceleration, deceleration]);
        let run = self.run();
        let state = (&mut self.M, &mut self.Id);
        let run = positioning(run, state, axis, execute, limits, |_| position);
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
        let limits = self.inputs(execute, distance, [velocity, acceleration, deceleration]);
        let run = self.run();
        let state = (&mut self.M, &mut self.Id);
        let to = |axis: &Axis| axis.set_position + distance;
        let run = positioning(run, state, axis, execute, limits, to);
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
        let limits = self.inputs(execute, direction, [velocity, acceleration, deceleration]);
        let mut run = self.run();
        match step(&mut run, &mut self.M, Some(self.Id), axis, execute) {
            Step::Start => {
                let sign = if direction < 0.0 { -1.0 } else { 1.0 };
                let limits = Limits {
                    // The speed asked for is the limit too.
                    velocity: velocity.abs().max(f64::MIN_POSITIVE),
                    ..limits
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
