//! `MC_Home`, homing on the current position.

use super::run::{Run, Step, step};
use crate::motion::axis::{Axis, AxisState};
use crate::motion::error;

execute_block! {
    /// MC_Home, homing on the current position: the axis's position becomes `Position` where
    /// it stands (CiA 402 homing method 37 does the same in the drive).
    McHome = "MC_Home" {
        Execute: "Input: homes on its rising edge.",
        inputs: {
            /// Input: the position the axis reads where it stands, in user units.
            Position: f64,
        },
        Done: "Output: homed.",
        Busy: "Output: homing.",
        CommandAborted: "Output: another block took the axis.",
        Error: "Output: refused or failed.",
        state: {},
    }
}

impl McHome {
    /// Runs the block for `axis`; returns `Done`.
    pub fn call(&mut self, axis: &mut Axis, execute: bool, position: f64) -> bool {
        self.Execute = execute;
        self.Position = position;
        let mut run = self.run();
        // Homing on the current position ends in the call that starts it: it never holds
        // the axis over a cycle.
        if let Step::Start = step(&mut run, &mut self.M, None, axis, execute) {
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
                    run = Run::done();
                }
            }
        }
        self.outputs(run);
        self.Done
    }
}
