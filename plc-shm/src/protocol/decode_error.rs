//! Why a message could not be decoded, as the owner answers a tool (and a tool reports an
//! owner) that does not speak the protocol.

use crate::limits::{MAX_MESSAGE, MAX_WRITES};

/// Why a message could not be decoded: what of it was wrong, as the owner answers a tool (and
/// a tool reports an owner) that does not speak the protocol.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum DecodeError {
    /// Longer than [`MAX_MESSAGE`].
    TooLong {
        /// Its length, if known (a message cut by the socket's buffer is longer than that).
        len: Option<usize>,
    },
    /// It ends inside a field.
    Truncated {
        /// The field.
        what: &'static str,
        /// Bytes that were left.
        left: usize,
        /// Bytes the field needs.
        needed: usize,
    },
    /// Bytes follow its end.
    Trailing {
        /// How many.
        bytes: usize,
    },
    /// A text field that is not UTF-8 (the error is its [`source`](std::error::Error::source)).
    NotUtf8 {
        /// The field.
        what: &'static str,
        /// Where the valid text ends.
        error: std::str::Utf8Error,
    },
    /// A text holding a NUL character.
    Nul,
    /// Not the greeting's magic bytes.
    NotAGreeting,
    /// A byte that is none of the values its field may hold (a tag, a kind, a code, a bool).
    Unknown {
        /// The field.
        what: &'static str,
        /// The byte.
        byte: u8,
    },
    /// A request of no writes or more than [`MAX_WRITES`].
    WriteCount {
        /// The count it gives.
        count: usize,
    },
    /// A release or trace of too few or too many values, or a trace of every 0th cycle.
    Count {
        /// What was counted.
        what: &'static str,
        /// The count it gives.
        count: usize,
        /// The fewest allowed.
        min: usize,
        /// The most allowed.
        max: usize,
    },
    /// A reply's reason longer than the protocol carries
    /// ([`MAX_REASON`](crate::limits::MAX_REASON) bytes).
    ReasonTooLong {
        /// The length it gives.
        len: usize,
    },
}

impl std::fmt::Display for DecodeError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            DecodeError::TooLong { len: Some(len) } => write!(
                f,
                "the message is {len} bytes, more than the {MAX_MESSAGE} allowed"
            ),
            DecodeError::TooLong { len: None } => write!(
                f,
                "the message is longer than the {MAX_MESSAGE} bytes allowed"
            ),
            DecodeError::Truncated { what, left, needed } => write!(
                f,
                "the message ends inside the {what} ({left} bytes left, {needed} needed)"
            ),
            DecodeError::Trailing { bytes } => {
                write!(f, "{bytes} bytes follow the end of the message")
            }
            DecodeError::NotUtf8 { what, error } => write!(f, "the {what} is not UTF-8: {error}"),
            DecodeError::Nul => f.write_str("a text holds a NUL character"),
            DecodeError::NotAGreeting => f.write_str("not a plc-vars greeting"),
            DecodeError::Unknown { what, byte } => write!(f, "{what} {byte}"),
            DecodeError::WriteCount { count } => {
                write!(f, "a request holds 1 to {MAX_WRITES} writes, not {count}")
            }
            DecodeError::Count {
                what,
                count,
                min,
                max,
            } => write!(f, "{what} must be {min} to {max}, not {count}"),
            DecodeError::ReasonTooLong { len } => write!(f, "a reason of {len} bytes"),
        }
    }
}

impl std::error::Error for DecodeError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            DecodeError::NotUtf8 { error, .. } => Some(error),
            _ => None,
        }
    }
}
