//! [`Time`], the `LTIME` type: a signed count of nanoseconds, its constructors and accessors,
//! and its checked and saturating arithmetic.

use super::unit::{NS_PER_MS, NS_PER_S, NS_PER_US};

/// A duration of IEC 61131-3 type `LTIME`: a signed 64-bit count of nanoseconds, about
/// ±292 years.
///
/// Display writes an IEC literal (`LTIME#1d2h3m`, `LTIME#-500ms`, `LTIME#0s`) that
/// [`Time::parse`] reads back to the same value. Arithmetic is checked (`checked_*`) or
/// saturating (`saturating_*`); nothing here wraps or panics.
///
/// ```
/// use plc_rules::time::Time;
/// let t = Time::from_millis(2500);
/// assert_eq!((t.as_secs(), t.as_millis(), t.as_micros()), (2, 2500, 2_500_000));
/// assert_eq!(t.checked_add(Time::from_secs(1)), Some(Time::from_millis(3500)));
/// assert_eq!(Time::MAX.checked_add(Time::from_nanos(1)), None);
/// assert_eq!(Time::MAX.saturating_add(Time::from_nanos(1)), Time::MAX);
/// ```
#[derive(Clone, Copy, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
#[repr(transparent)]
pub struct Time(i64);

impl Time {
    /// No time: `LTIME#0s`.
    pub const ZERO: Time = Time(0);
    /// The shortest duration, -2^63 ns.
    pub const MIN: Time = Time(i64::MIN);
    /// The longest duration, 2^63 - 1 ns (`LTIME#106751d23h47m16s854ms775us807ns`).
    pub const MAX: Time = Time(i64::MAX);

    /// A duration of `ns` nanoseconds.
    pub const fn from_nanos(ns: i64) -> Time {
        Time(ns)
    }

    /// A duration of `us` microseconds, saturating at [`MIN`](Self::MIN) and
    /// [`MAX`](Self::MAX).
    pub const fn from_micros(us: i64) -> Time {
        Time(us.saturating_mul(NS_PER_US))
    }

    /// A duration of `ms` milliseconds, saturating at [`MIN`](Self::MIN) and
    /// [`MAX`](Self::MAX) (beyond about ±292 years).
    pub const fn from_millis(ms: i64) -> Time {
        Time(ms.saturating_mul(NS_PER_MS))
    }

    /// A duration of `s` seconds, saturating at [`MIN`](Self::MIN) and [`MAX`](Self::MAX).
    pub const fn from_secs(s: i64) -> Time {
        Time(s.saturating_mul(NS_PER_S))
    }

    /// The duration in nanoseconds.
    pub const fn as_nanos(self) -> i64 {
        self.0
    }

    /// The duration in whole microseconds, truncated toward zero.
    pub const fn as_micros(self) -> i64 {
        self.0 / NS_PER_US
    }

    /// The duration in whole milliseconds, truncated toward zero.
    pub const fn as_millis(self) -> i64 {
        self.0 / NS_PER_MS
    }

    /// The duration in whole seconds, truncated toward zero.
    pub const fn as_secs(self) -> i64 {
        self.0 / NS_PER_S
    }

    /// The duration in seconds as a float (for display and arithmetic with reals).
    pub fn as_secs_f64(self) -> f64 {
        self.0 as f64 / NS_PER_S as f64
    }

    /// Whether the duration is below zero.
    pub const fn is_negative(self) -> bool {
        self.0 < 0
    }

    /// `self + other`, `None` on overflow.
    pub const fn checked_add(self, other: Time) -> Option<Time> {
        match self.0.checked_add(other.0) {
            Some(ns) => Some(Time(ns)),
            None => None,
        }
    }

    /// `self - other`, `None` on overflow.
    pub const fn checked_sub(self, other: Time) -> Option<Time> {
        match self.0.checked_sub(other.0) {
            Some(ns) => Some(Time(ns)),
            None => None,
        }
    }

    /// `self * factor`, `None` on overflow.
    pub const fn checked_mul(self, factor: i64) -> Option<Time> {
        match self.0.checked_mul(factor) {
            Some(ns) => Some(Time(ns)),
            None => None,
        }
    }

    /// `-self`, `None` for [`MIN`](Self::MIN), whose negation is beyond `MAX`.
    pub const fn checked_neg(self) -> Option<Time> {
        match self.0.checked_neg() {
            Some(ns) => Some(Time(ns)),
            None => None,
        }
    }

    /// `self + other`, saturating at [`MIN`](Self::MIN) and [`MAX`](Self::MAX).
    pub const fn saturating_add(self, other: Time) -> Time {
        Time(self.0.saturating_add(other.0))
    }

    /// `self - other`, saturating at [`MIN`](Self::MIN) and [`MAX`](Self::MAX).
    pub const fn saturating_sub(self, other: Time) -> Time {
        Time(self.0.saturating_sub(other.0))
    }
}
