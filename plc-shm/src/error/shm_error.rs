//! The crate's one error: every way a shared-memory operation fails, each naming its segment
//! or variable (what each says is in `message`).

use super::cause::Cause;
use plc_core::ValueError;

/// Why a shared-memory operation failed.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum ShmError {
    /// The segment name has characters other than letters, digits, `_`, `-`, `.`.
    BadName(String),
    /// No segment of this name exists.
    NotFound(String),
    /// Another live process owns the segment.
    OwnerAlive {
        /// Segment.
        name: String,
        /// Its owner's pid (0 if unknown).
        pid: u64,
    },
    /// The operating system refused, or what was found stopped the attempt.
    Os {
        /// Segment.
        name: String,
        /// What was attempted.
        what: String,
        /// Why: the operating system's error (the error's [`source`](std::error::Error::source)),
        /// or what was found.
        error: Cause,
    },
    /// The segment is not a plc-vars segment of this format version.
    Format {
        /// Segment.
        name: String,
        /// What was found.
        found: String,
    },
    /// The segment holds another declaration than this program was compiled with.
    LayoutMismatch {
        /// Segment.
        name: String,
        /// This program's layout hash.
        expected: u64,
        /// The segment's.
        found: u64,
    },
    /// The segment is smaller than its header says.
    TooSmall {
        /// Segment.
        name: String,
        /// Its length.
        len: usize,
        /// The length needed.
        needed: usize,
    },
    /// The segment's header or descriptor is damaged (numbers that do not fit together, JSON
    /// that does not parse, a hash that does not match).
    Corrupt {
        /// Segment.
        name: String,
        /// What is wrong.
        why: String,
    },
    /// The owning program is gone (no live process holds the segment's lock).
    OwnerGone(String),
    /// The segment's header names another generation than the one this handle attached to:
    /// the segment was replaced under it (as an online change with a changed layout will).
    Replaced(String),
    /// The owner stopped (cleanly, or after a fault) and removed the segment since this handle
    /// attached: nothing is published into it and no write is applied any more.
    Closed {
        /// Segment.
        name: String,
        /// The owner stopped because its program faulted (a panic in its cycle).
        faulted: bool,
    },
    /// The owner stayed in the middle of a write for longer than a reader waits.
    Stuck(String),
    /// No variable of this name.
    UnknownVariable {
        /// Segment.
        name: String,
        /// The name asked for.
        variable: String,
    },
    /// A path that names no basic value of the segment.
    BadPath {
        /// Segment.
        name: String,
        /// The path given.
        path: String,
        /// Why it names nothing.
        reason: String,
    },
    /// The variable may not be written from outside.
    NotWritable {
        /// Variable.
        variable: String,
        /// Why: read-only, input or status.
        reason: &'static str,
    },
    /// The value does not fit the variable.
    Value {
        /// Variable.
        variable: String,
        /// What is wrong.
        error: ValueError,
    },
    /// The element is beyond the array.
    ElementOutOfRange {
        /// Variable.
        variable: String,
        /// The element asked for.
        element: usize,
        /// Elements of the variable.
        len: usize,
    },
    /// Too many requests wait for the owner already (it has not applied earlier ones yet).
    QueueFull(String),
    /// The owner cannot take the request now and said why (as "4 traces run already").
    Busy {
        /// Segment.
        name: String,
        /// The owner's reason.
        reason: String,
    },
    /// Only the owner may do this.
    NotOwner(String),
    /// The operating system refused access to the segment's file.
    PermissionDenied {
        /// Segment.
        name: String,
        /// The file.
        path: std::path::PathBuf,
    },
    /// A file or directory of the segment is a symbolic link, is not a regular file, belongs
    /// to another user or is open to other users: it is not used.
    Unsafe {
        /// Segment.
        name: String,
        /// The file or directory.
        path: std::path::PathBuf,
        /// What is wrong with it.
        problem: String,
        /// What to do.
        fix: String,
    },
    /// The program refused a write: its declaration (not writable from outside, element, value)
    /// or its `set`. Nothing of the request was applied.
    WriteRejected {
        /// Segment.
        name: String,
        /// The variable of the refused write.
        variable: String,
        /// The program's reason.
        reason: String,
    },
    /// The program refused a write to a value that is forced (`plc force`): the reason names
    /// who forced it and since when. Nothing of the request was applied.
    Forced {
        /// Segment.
        name: String,
        /// The forced value of the refused write.
        variable: String,
        /// The program's reason.
        reason: String,
    },
    /// The program's policy does not let this process write.
    WriteRefused {
        /// Segment.
        name: String,
        /// The rule, as the program states it (who may write, and where that is set).
        rule: String,
    },
    /// The owner did not answer a write in time (it is stalled, or too busy).
    NoAnswer {
        /// Segment.
        name: String,
        /// How long the tool waited.
        waited: std::time::Duration,
    },
    /// The segment's socket would have a longer path than a Unix socket may.
    SocketPathTooLong {
        /// Segment.
        name: String,
        /// The socket's path.
        path: std::path::PathBuf,
        /// The longest path a Unix socket may have, in bytes.
        most: usize,
    },
    /// The owner did not send its greeting in time.
    NoGreeting {
        /// Segment.
        name: String,
        /// The socket.
        path: std::path::PathBuf,
        /// How long the tool waited.
        waited: std::time::Duration,
    },
    /// The owner turned the connection away (it has as many as it takes).
    TurnedAway {
        /// Segment.
        name: String,
        /// The owner's reason.
        reason: String,
    },
    /// A request of no values, or of more than one request holds.
    RequestCount {
        /// Segment.
        name: String,
        /// What was counted: writes, forces, releases, traced values.
        what: &'static str,
        /// How many were given.
        count: usize,
        /// How many one request holds at most.
        most: usize,
    },
    /// Writes whose texts take more bytes than one message holds.
    RequestTooLarge {
        /// Segment.
        name: String,
        /// The bytes the request would take.
        bytes: usize,
        /// The bytes a message holds at most.
        most: usize,
    },
    /// A value a trace cannot record (a STRING).
    NotTraceable {
        /// Segment.
        name: String,
        /// The value's path.
        path: String,
    },
    /// A path that names no alarm of the program.
    UnknownAlarm {
        /// Segment.
        name: String,
        /// The path given.
        path: String,
        /// Whether a variable has that path (it declares no alarm).
        is_variable: bool,
    },
    /// The program refused an operator's action on an alarm; nothing of the request was
    /// done.
    AlarmRefused {
        /// Segment.
        name: String,
        /// The alarm's path.
        alarm: String,
        /// What was asked (`acknowledge`, `reset`, `shelve`, `unshelve`).
        action: &'static str,
        /// The program's reason.
        reason: String,
    },
    /// The owner sent something that is not the segment protocol.
    Protocol {
        /// Segment.
        name: String,
        /// What was wrong.
        why: String,
    },
}

impl std::error::Error for ShmError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            ShmError::Value { error, .. } => Some(error),
            ShmError::Os {
                error: Cause::System(e),
                ..
            } => Some(&**e),
            _ => None,
        }
    }
}
