//! Errors of shared memory, each naming the segment or variable and what to do.

use plc_core::ValueError;
use std::fmt;
use std::sync::Arc;

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
    /// The owner sent something that is not the segment protocol.
    Protocol {
        /// Segment.
        name: String,
        /// What was wrong.
        why: String,
    },
}

impl fmt::Display for ShmError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ShmError::BadName(n) => write!(
                f,
                "invalid segment name `{n}`: use letters, digits, `_`, `-` and `.`"
            ),
            ShmError::NotFound(n) => write!(
                f,
                "no segment `{n}`: is the program running? (`plc list` shows the running segments)"
            ),
            ShmError::OwnerAlive { name, pid } => write!(
                f,
                "segment `{name}` is owned by a running process (pid {pid}): stop it first or \
                 choose another segment name"
            ),
            ShmError::Os { name, what, error } => write!(f, "segment `{name}`: {what}: {error}"),
            ShmError::Format { name, found } => write!(
                f,
                "segment `{name}` is not a plc-vars segment of format {}: {found}; rebuild the \
                 tool and the program from the same plc-vars version",
                plc_rules::layout::FORMAT_VERSION
            ),
            ShmError::LayoutMismatch {
                name,
                expected,
                found,
            } => write!(
                f,
                "segment `{name}` holds another variable layout (hash {found:016x}, this program \
                 expects {expected:016x}): rebuild this program from the running program's \
                 declaration, or use a tool that reads the descriptor (`plc`)"
            ),
            ShmError::TooSmall { name, len, needed } => write!(
                f,
                "segment `{name}` is {len} bytes but its header needs {needed}: it is damaged; \
                 restart the program that owns it"
            ),
            ShmError::Corrupt { name, why } => write!(
                f,
                "segment `{name}` is damaged ({why}): restart the program that owns it"
            ),
            ShmError::OwnerGone(n) => write!(
                f,
                "the program that owned segment `{n}` is gone; restart it (a new owner takes the \
                 segment over)"
            ),
            ShmError::Replaced(n) => write!(
                f,
                "segment `{n}` was replaced since this tool attached to it: attach again"
            ),
            ShmError::Closed {
                name,
                faulted: false,
            } => write!(
                f,
                "the program that owned segment `{name}` stopped and removed it: attach again \
                 once it runs again"
            ),
            ShmError::Closed {
                name,
                faulted: true,
            } => write!(
                f,
                "the program that owned segment `{name}` faulted (a panic in its cycle; its \
                 error output says where) and stopped: attach again once it is restarted"
            ),
            ShmError::Stuck(n) => write!(
                f,
                "segment `{n}`: the owner stayed in the middle of a write (it may have died \
                 while publishing); attach again once it is restarted"
            ),
            ShmError::UnknownVariable { name, variable } => write!(
                f,
                "segment `{name}` has no variable `{variable}` (`plc list {name}` shows them)"
            ),
            ShmError::BadPath { name, path, reason } => write!(
                f,
                "segment `{name}`: `{path}`: {reason} (`plc list {name}` shows the variables)"
            ),
            ShmError::NotWritable { variable, reason } => {
                write!(f, "`{variable}` cannot be written: {reason}")
            }
            ShmError::Value { variable, error } => write!(f, "`{variable}`: {error}"),
            ShmError::ElementOutOfRange {
                variable,
                element,
                len,
            } => write!(
                f,
                "`{variable}` has {len} elements: element {element} is out of range 0..{len}"
            ),
            ShmError::QueueFull(n) => write!(
                f,
                "segment `{n}`: too many writes wait for the program already (is it running? \
                 `plc list` shows its state); try again"
            ),
            ShmError::NotOwner(n) => {
                write!(f, "only the program that created segment `{n}` may do this")
            }
            ShmError::PermissionDenied { name, path } => write!(
                f,
                "segment `{name}`: permission denied opening {}: run this as the program's user, \
                 root, or a member of its read group (RuntimeBuilder::read_group)",
                path.display()
            ),
            ShmError::Unsafe {
                name,
                path,
                problem,
                fix,
            } => write!(
                f,
                "segment `{name}`: refusing {}: it {problem}; {fix}",
                path.display()
            ),
            ShmError::Forced { name, reason, .. } => write!(
                f,
                "segment `{name}`: the program refused the write: {reason}; nothing of the \
                 request was written"
            ),
            ShmError::WriteRejected {
                name,
                variable,
                reason,
            } => write!(
                f,
                "segment `{name}`: the program refused the write of `{variable}`: {reason}; \
                 nothing of the request was written"
            ),
            ShmError::WriteRefused { name, rule } => {
                write!(f, "segment `{name}`: write refused: {rule}")
            }
            ShmError::NoAnswer { name, waited } => write!(
                f,
                "segment `{name}`: the program did not answer the write within {:.1} s (is it \
                 running? `plc list` shows its state); it may still apply it",
                waited.as_secs_f64()
            ),
            ShmError::SocketPathTooLong { name, path, most } => write!(
                f,
                "segment `{name}`: cannot make the socket {}: a Unix socket's path has at most \
                 {most} bytes: choose a shorter segment name, or a shorter directory ({})",
                path.display(),
                crate::env::RUNTIME_DIR_ENV
            ),
            ShmError::NoGreeting { name, path, waited } => write!(
                f,
                "segment `{name}`: the program did not answer at {} within {waited:?} (no \
                 greeting): it is stopped, stalled or too busy (`plc list` shows its state); \
                 try again",
                path.display()
            ),
            ShmError::TurnedAway { name, reason } => write!(
                f,
                "segment `{name}`: {reason}; close another tool of this program, or try again"
            ),
            ShmError::RequestCount {
                name,
                what,
                count,
                most,
            } => {
                write!(
                    f,
                    "segment `{name}`: cannot send {count} {what} as one request: a request \
                     holds 1 to {most}"
                )?;
                if *count > *most {
                    write!(f, "; send them in parts")?;
                }
                Ok(())
            }
            ShmError::RequestTooLarge { name, bytes, most } => write!(
                f,
                "segment `{name}`: the writes take {bytes} bytes and a request at most {most}: \
                 send the texts in parts"
            ),
            ShmError::NotTraceable { name, path } => write!(
                f,
                "segment `{name}`: cannot trace `{path}`: it is a STRING, and a trace records \
                 numbers, BOOLs and times; leave it out"
            ),
            ShmError::Protocol { name, why } => write!(
                f,
                "segment `{name}`: the program's socket does not speak this tool's protocol \
                 ({why}); rebuild the tool and the program from the same plc-vars version"
            ),
        }
    }
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

/// Why an [`ShmError::Os`] attempt failed.
#[derive(Clone, Debug)]
pub enum Cause {
    /// The operating system's error, kept whole.
    System(Arc<std::io::Error>),
    /// What was found instead of what was needed (a path too long, no such group, no answer).
    Reason(String),
}

impl Cause {
    /// The operating system's error.
    pub fn system(error: std::io::Error) -> Cause {
        Cause::System(Arc::new(error))
    }
}

impl From<std::io::Error> for Cause {
    fn from(error: std::io::Error) -> Cause {
        Cause::system(error)
    }
}

impl From<String> for Cause {
    fn from(reason: String) -> Cause {
        Cause::Reason(reason)
    }
}

impl From<&str> for Cause {
    fn from(reason: &str) -> Cause {
        Cause::Reason(reason.to_string())
    }
}

/// Equal when they say the same: the same OS error (kind and number), or the same reason.
impl PartialEq for Cause {
    fn eq(&self, other: &Cause) -> bool {
        match (self, other) {
            (Cause::System(a), Cause::System(b)) => {
                a.kind() == b.kind() && a.raw_os_error() == b.raw_os_error()
            }
            (Cause::Reason(a), Cause::Reason(b)) => a == b,
            _ => false,
        }
    }
}

impl fmt::Display for Cause {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Cause::System(e) => fmt::Display::fmt(e, f),
            Cause::Reason(r) => f.write_str(r),
        }
    }
}
