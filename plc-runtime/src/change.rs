//! An online change: new variables (a new build of the program, converted from the running
//! one's) take over between two cycles, after a cycle published its image and before the
//! next exchange, so no value is a cycle old and the I/O never stops.
//!
//! The conversion is prepared off the cycle thread by whoever sends the [`Swap`] (a host such
//! as `plc run`); the cycle only runs it, then follows the new variables with what depends
//! on them, when their layout differs: the I/O's bindings ([`IoBackend::rebind`](crate::IoBackend::rebind)), the
//! segment (made again: tools attach again as after a restart; the forces whose paths remain
//! are held again, the others released and named; traces end, each with a message), the retain writer (the file follows the new
//! declaration) and the alarms (evaluated afresh). A new program is on probation for
//! [`Swap::probation`] cycles: a panic in them swaps the previous one back before that
//! cycle's outputs are written.

use std::sync::mpsc::Sender;
use std::time::Duration;

/// The conversion of the running variables into new ones (or back).
pub type Convert<T> = Box<dyn FnOnce(&T) -> Result<T, String> + Send>;

/// A change the cycle makes between two cycles, taken from
/// [`RuntimeBuilder::swaps`](crate::RuntimeBuilder::swaps): the conversion runs on the cycle
/// thread; when the layout differs, the I/O is bound again and the segment, the retain writer
/// and the alarms follow; the new program is on probation for `probation` cycles.
pub struct Swap<T> {
    /// The new variables from the running ones: run on the cycle thread, so only the
    /// conversion itself (everything else prepared).
    pub convert: Convert<T>,
    /// The previous variables from the new ones, if the new program panics on probation.
    pub back: Convert<T>,
    /// Cycles on probation, the first new one included.
    pub probation: u64,
    /// Where the cycle tells what happened.
    pub report: Sender<SwapEvent>,
}

/// What became of a [`Swap`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SwapEvent {
    /// Not made; the running program goes on as it was.
    Refused(String),
    /// The new variables run from cycle `cycle` on; the swap took `took` on the cycle thread.
    Swapped {
        /// The first cycle of the new program.
        cycle: u64,
        /// The work on the cycle thread.
        took: Duration,
        /// Whether the variables' layout changed (the segment was made again).
        relaid: bool,
        /// The paths of the forces it released: the new program has no such value, or not
        /// of a type the forced value fits. The others are held again.
        released_forces: Vec<String>,
    },
    /// Its probation passed: it stays.
    Kept {
        /// The last cycle of the probation.
        cycle: u64,
    },
    /// It panicked in cycle `cycle` of its probation and the previous program was swapped
    /// back before that cycle's outputs went out.
    SwappedBack {
        /// The cycle it panicked in.
        cycle: u64,
        /// The panic's message.
        message: String,
    },
}

/// A change on probation: until which cycle, and the way back.
pub(super) struct Probation<T> {
    pub until: u64,
    pub back: Convert<T>,
    pub report: Sender<SwapEvent>,
}

/// What the cycle needs to follow a change of layout: how the retain writer and the segment
/// were made at start.
pub(super) struct Remake {
    pub retain: Option<(std::path::PathBuf, Duration)>,
    pub sharing: plc_shm::Sharing,
    pub max_shelve: plc_core::Time,
}
