//! [`TimeError`]: why a text is not a duration literal, and what to write instead.

use super::duration::Time;
use core::fmt;

/// Why a text is not a duration literal. Each message says what to write instead.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TimeError {
    /// The text does not start with `T#`, `TIME#`, `LT#` or `LTIME#`.
    NoPrefix,
    /// Nothing (or only a sign) after the prefix.
    Empty,
    /// A character that does not belong where it is.
    Unexpected {
        /// Byte offset of the character in the text.
        at: usize,
    },
    /// A number without a unit after it.
    MissingUnit {
        /// Byte offset of the end of the number.
        at: usize,
    },
    /// A unit after a smaller one or the same one again (`T#1s1m`, `T#1s2s`).
    UnitOrder {
        /// The unit out of order.
        unit: &'static str,
        /// The unit before it.
        after: &'static str,
    },
    /// A part after the first that reaches the next larger unit (`T#1h75m`).
    PartTooLarge {
        /// The part's whole number.
        value: u64,
        /// Its unit.
        unit: &'static str,
        /// The smallest value that is too large (60 for minutes).
        limit: u64,
    },
    /// A fraction on a part that is not the last (`T#1.5m30s`).
    FractionNotLast,
    /// A fraction finer than a nanosecond, the resolution of `LTIME` (`T#1.5ns`).
    FinerThanNanosecond,
    /// The duration is beyond `LTIME`'s range.
    Overflow,
}

impl fmt::Display for TimeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        const PARTS: &str = "a duration is T#, TIME#, LT# or LTIME#, an optional sign, then \
                             parts of a number and a unit (d, h, m, s, ms, us, ns), such as \
                             T#1h_30m or LTIME#-2.5s";
        match *self {
            TimeError::NoPrefix => f.write_str(
                "a duration starts with T#, TIME#, LT# or LTIME#, such as T#1h_30m or \
                 LTIME#-2.5s",
            ),
            TimeError::Empty => write!(f, "no duration after `#`: {PARTS}"),
            TimeError::Unexpected { at } => {
                write!(f, "unexpected character at byte {at}: {PARTS}")
            }
            TimeError::MissingUnit { at } => {
                write!(f, "the number ending at byte {at} has no unit: {PARTS}")
            }
            TimeError::UnitOrder { unit, after } => write!(
                f,
                "`{unit}` comes after `{after}`: the parts go from days to nanoseconds (d, h, \
                 m, s, ms, us, ns), each at most once"
            ),
            TimeError::PartTooLarge { value, unit, limit } => write!(
                f,
                "{value}{unit} after a larger unit must be below {limit}{unit}: carry it into \
                 the larger unit (only the first part may exceed its unit, as in T#90m)"
            ),
            TimeError::FractionNotLast => f.write_str(
                "only the last part may have a fraction (T#1.5s): write the rest as smaller \
                 parts (T#1m30s, not T#1.5m30s)",
            ),
            TimeError::FinerThanNanosecond => f.write_str(
                "the fraction is finer than a nanosecond, the resolution of LTIME: drop the \
                 extra digits",
            ),
            TimeError::Overflow => write!(
                f,
                "beyond the range of LTIME, {} to {}",
                Time::MIN,
                Time::MAX
            ),
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for TimeError {}
