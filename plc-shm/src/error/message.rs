//! What each error says to the person who reads it: the segment or variable, what happened,
//! and what to do.

use super::shm_error::ShmError;
use std::fmt;

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
            ShmError::Busy { name, reason } => {
                write!(f, "segment `{name}`: {reason}; try again later")
            }
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
            ShmError::UnknownAlarm {
                name,
                path,
                is_variable: true,
            } => write!(
                f,
                "segment `{name}`: `{path}` is a variable without an alarm (`plc alarms {name} \
                 --all` lists the alarms)"
            ),
            ShmError::UnknownAlarm { name, path, .. } => write!(
                f,
                "segment `{name}` has no alarm `{path}`: an alarm is named by the path of the \
                 value it watches (`plc alarms {name} --all` lists them)"
            ),
            ShmError::AlarmRefused {
                name,
                alarm,
                action,
                reason,
            } => write!(
                f,
                "segment `{name}`: cannot {action} alarm `{alarm}`: {reason}; nothing was done"
            ),
            ShmError::Protocol { name, why } => write!(
                f,
                "segment `{name}`: the program's socket does not speak this tool's protocol \
                 ({why}); rebuild the tool and the program from the same plc-vars version"
            ),
        }
    }
}
