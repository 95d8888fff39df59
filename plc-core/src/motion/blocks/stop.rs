//! `MC_Stop`, which brings the axis to rest and holds it, and `MC_Reset`, which takes it out
//! of ErrorStop.

use super::run::{Run, Step, started, step};
use crate::motion::axis::{Axis, AxisState, motion};
use crate::motion::profile::Limits;

execute_block! {
    /// MC_Stop: brings the axis to rest at `Deceleration` and holds it there while `Execute`
    /// stays TRUE. As PLCopen's state diagram has it, the stop takes the axis into Stopping
    /// from any powered state (another stop included), where no move is taken; `Done` once
    /// at rest; the axis goes to Standstill once the stop is done and `Execute` is FALSE.
    McStop = "MC_Stop" {
        Execute: "Input: stops on its rising edge; holds while TRUE.",
        inputs: {
            /// Input: units per second squared.
            Deceleration: f64,
        },
        Done: "Output: at rest.",
        Busy: "Output: stopping.",
        CommandAborted: "Output: another block took the axis (an error stop, another stop).",
        Error: "Output: refused.",
        state: {
            /// State: the number of its command.
            Id: u32,
        },
    }
}

impl McStop {
    /// Runs the block for `axis`; returns `Done`.
    pub fn call(&mut self, axis: &mut Axis, execute: bool, deceleration: f64) -> bool {
        (self.Execute, self.Deceleration) = (execute, deceleration);
        let mut run = self.run();
        let at_rest = |axis: &Axis| axis.motion == motion::HOLD || axis.arrived;
        match step(&mut run, &mut self.M, Some(self.Id), axis, execute) {
            Step::Start => {
                let limits = Limits {
                    velocity: axis.set_velocity.abs().max(f64::MIN_POSITIVE),
                    acceleration: deceleration,
                    deceleration,
                };
                self.Id = started(&mut run, axis.stop(limits));
            }
            Step::Running if at_rest(axis) => run = Run::done(),
            _ => {}
        }
        let holding = axis.command == self.Id && axis.state() == AxisState::Stopping;
        if holding && !execute && at_rest(axis) {
            axis.set_state(AxisState::Standstill);
            axis.motion = motion::HOLD;
        }
        self.outputs(run);
        self.Done
    }
}

/// MC_Reset: clears the axis's error (and resets the drive's fault) on `Execute`'s rising
/// edge; `Done` once the drive left its fault and the axis ErrorStop.
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

outputs!(McReset {
    done: Done,
    busy: Busy,
    error: Error,
    error_id: ErrorID
});

impl McReset {
    /// Runs the block for `axis`; returns `Done`.
    pub fn call(&mut self, axis: &mut Axis, execute: bool) -> bool {
        self.Execute = execute;
        let mut run = self.run();
        // A reset does not take the axis: no other block aborts it.
        if let Step::Start = step(&mut run, &mut self.M, None, axis, execute) {
            run.busy = true;
            axis.fault_reset = true;
        }
        if run.busy && !axis.drive.faulted() {
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
            run = Run::done();
        }
        self.outputs(run);
        self.Done
    }
}
