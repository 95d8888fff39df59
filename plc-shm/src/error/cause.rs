//! Why an attempt the operating system refused failed: its error kept whole, or what was found
//! instead of what was needed.

use std::fmt;
use std::sync::Arc;

/// Why an [`ShmError::Os`](crate::ShmError::Os) attempt failed.
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
