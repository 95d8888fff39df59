//! The run logic the blocks share, as PLCopen part 1 ("General rules") gives it for the two
//! kinds of block:
//!
//! - Execute-kind blocks (`MC_Home`, the moves, `MC_Stop`, `MC_Reset`): `Execute`'s rising
//!   edge starts them; `Busy` while they have not finished; `Done`, `Error` (with `ErrorID`)
//!   or `CommandAborted` (another block took the axis) when they have; those are reset on the
//!   falling edge of `Execute`, or shown for one call if `Execute` fell before the end.
//! - Enable-kind blocks (`MC_Power`, `MC_ReadActualPosition`): their outputs are `Valid`
//!   while they hold and no error is reported; `Error` and `Valid` never both.

use crate::motion::axis::{Axis, AxisState};

/// The outputs and state every Execute-kind block has.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(super) struct Run {
    pub done: bool,
    pub busy: bool,
    pub active: bool,
    pub aborted: bool,
    pub error: bool,
    pub error_id: u16,
}

impl Run {
    /// Finished: `Done` alone.
    pub fn done() -> Run {
        Run {
            done: true,
            ..Run::default()
        }
    }
}

/// What the common part of an Execute-kind block decides in a call.
pub(super) enum Step {
    /// `Execute` rose: start.
    Start,
    /// Running (still owning the axis, for a block that takes it).
    Running,
    /// Nothing to do.
    Idle,
}

/// The common part of an Execute-kind block: `Execute`'s edge (`last` holds its previous
/// value) and, for a block that runs the axis as command `owner`, `CommandAborted` or the
/// axis's error once the axis runs another command. A block that does not take the axis
/// (homing, a reset) passes `None`.
pub(super) fn step(
    run: &mut Run,
    last: &mut bool,
    owner: Option<u32>,
    axis: &Axis,
    execute: bool,
) -> Step {
    let rising = execute && !*last;
    *last = execute;
    if rising {
        *run = Run::default();
        return Step::Start;
    }
    if run.busy {
        match owner {
            Some(id) if axis.command != id => {
                *run = if axis.state() == AxisState::ErrorStop {
                    Run {
                        error: true,
                        error_id: axis.error_id,
                        ..Run::default()
                    }
                } else {
                    Run {
                        aborted: true,
                        ..Run::default()
                    }
                };
                return Step::Idle;
            }
            _ => return Step::Running,
        }
    }
    if !execute {
        // The falling edge resets the outputs (after they were shown once).
        *run = Run::default();
    }
    Step::Idle
}

/// Starts a block's command: busy with its number, or the error.
pub(super) fn started(run: &mut Run, started: Result<u32, u16>) -> u32 {
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

/// The outputs of an Enable-kind block: `Valid` while its outputs are `ready` and no `fault`
/// is reported, `Error` and `ErrorID` for the fault.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Enabled {
    pub valid: bool,
    pub error: bool,
    pub error_id: u16,
}

impl Enabled {
    /// The outputs for a block whose outputs are `ready`, reporting `fault` if any.
    pub fn new(ready: bool, fault: Option<u16>) -> Enabled {
        Enabled {
            valid: ready && fault.is_none(),
            error: fault.is_some(),
            error_id: fault.unwrap_or(0),
        }
    }
}

/// A block's members from and to a [`Run`]: `outputs!(Fb { done: Done, busy: Busy, ... })`
/// names the members the block has (the others stay at their default in the `Run`);
/// `outputs!(Fb, Done)` is the whole set, with `Done` named as the block names it.
macro_rules! outputs {
    ($fb:ident, $done:ident) => {
        outputs!($fb {
            done: $done,
            busy: Busy,
            active: Active,
            aborted: CommandAborted,
            error: Error,
            error_id: ErrorID
        });
    };
    ($fb:ident { $($field:ident: $member:ident),* }) => {
        impl $fb {
            /// Writes the block's output members.
            fn outputs(&mut self, run: $crate::motion::blocks::run::Run) {
                $(self.$member = run.$field;)*
            }

            /// The block's output members as they are.
            // The update fills what a block without every member (MC_Reset) lacks; for the
            // others it has nothing left to fill.
            #[allow(clippy::needless_update)]
            fn run(&self) -> $crate::motion::blocks::run::Run {
                $crate::motion::blocks::run::Run {
                    $($field: self.$member,)*
                    ..::core::default::Default::default()
                }
            }
        }
    };
}

/// Declares an Execute-kind block with PLCopen's members in PLCopen's order: `Execute`, the
/// block's own inputs, its `Done` (under the block's name for it), `Busy`, `Active`,
/// `CommandAborted`, `Error`, `ErrorID`, then its state (`M`, `Execute` of the previous call,
/// and the block's own); and its [`Run`] conversions (`outputs!`). Each block says in its
/// own words what `Execute`, `Done`, `Busy`, `CommandAborted` and `Error` mean for it.
macro_rules! execute_block {
    (
        $(#[$doc:meta])*
        $fb:ident = $name:literal {
            Execute: $execute:literal,
            inputs: { $($(#[$input_doc:meta])* $input:ident: $input_ty:ty,)* },
            $done:ident: $done_doc:literal,
            Busy: $busy:literal,
            CommandAborted: $aborted:literal,
            Error: $error:literal,
            state: { $($(#[$state_doc:meta])* $state:ident: $state_ty:ty,)* },
        }
    ) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, PartialEq, plc_derive::PlcStruct)]
        #[plc(crate = "crate", name = $name, __iec_standard)]
        #[allow(non_snake_case)]
        pub struct $fb {
            #[doc = $execute]
            #[plc(direction = "input")]
            pub Execute: bool,
            $(
                $(#[$input_doc])*
                #[plc(direction = "input")]
                pub $input: $input_ty,
            )*
            #[doc = $done_doc]
            #[plc(direction = "output")]
            pub $done: bool,
            #[doc = $busy]
            #[plc(direction = "output")]
            pub Busy: bool,
            /// Output: owns the axis.
            #[plc(direction = "output")]
            pub Active: bool,
            #[doc = $aborted]
            #[plc(direction = "output")]
            pub CommandAborted: bool,
            #[doc = $error]
            #[plc(direction = "output")]
            pub Error: bool,
            /// Output: why.
            #[plc(direction = "output")]
            pub ErrorID: u16,
            /// State: `Execute` of the previous call.
            pub M: bool,
            $(
                $(#[$state_doc])*
                pub $state: $state_ty,
            )*
        }

        outputs!($fb, $done);
    };
}
