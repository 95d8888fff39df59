//! IEC 61131-3 durations: [`Time`], the `LTIME` type (a signed 64-bit count of nanoseconds),
//! and the duration literal grammar (`T#1s500ms`, `LTIME#-2h_30m`, `T#1.5s`) that the derive's
//! `initial`, the importer and `Value::parse` (`plc set`) share.
//!
//! # The literal grammar
//!
//! IEC 61131-3 (3rd edition, duration literals) as plc-vars reads it:
//!
//! - a prefix `T#`, `TIME#`, `LT#` or `LTIME#`, in any case. plc-vars has one duration type,
//!   `LTIME`; a `T#`/`TIME#` literal is a `TIME` value, which IEC 61131-3 widens to `LTIME`
//!   implicitly, so all four prefixes give the same value;
//! - an optional sign, `+` or `-`, right after `#`;
//! - one or more parts, each a number and a unit, the units in this order and each at most
//!   once: `d` (days), `h`, `m`, `s`, `ms`, `us` (microseconds), `ns`; units in any case;
//! - `_` between digits (`1_000ms`) and after a part's unit (`2h_30m`), nowhere else;
//! - only the first part may exceed its unit (`T#90m`, `T#25h_15m`); a later part must be
//!   below the next larger unit (`T#1h75m` is an error: write `T#2h15m`);
//! - the last part, and only the last, may have a fraction: `T#1.5s` is `T#1s500ms`,
//!   `T#0.25h` is `T#15m` (IEC 61131-3's `fix_point`). A fraction finer than a nanosecond,
//!   the resolution of `LTIME`, is an error rather than rounded;
//! - a value beyond `LTIME`'s range (±2^63 ns, about ±106,751 days) is an error.
//!
//! Parsing never panics and never allocates; it reads the text once.
//!
//! ```
//! use plc_rules::time::Time;
//! assert_eq!("T#1s500ms".parse::<Time>(), Ok(Time::from_millis(1500)));
//! assert_eq!("t#1.5S".parse::<Time>(), Ok(Time::from_millis(1500)));
//! assert_eq!(Time::parse("LTIME#-2h_30m"), Ok(Time::from_secs(-9000)));
//! assert_eq!(Time::from_millis(1500).to_string(), "LTIME#1s500ms");
//! assert!(Time::parse("T#1h75m").is_err());
//! assert!(Time::parse("LT#106752d").is_err());
//! ```

use core::fmt;
use core::str::FromStr;

const NS_PER_US: i64 = 1_000;
const NS_PER_MS: i64 = 1_000_000;
const NS_PER_S: i64 = 1_000_000_000;

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

    /// Parses an IEC duration literal (see the [module documentation](self) for the
    /// grammar). Surrounding whitespace is not part of a literal.
    pub fn parse(text: &str) -> Result<Time, TimeError> {
        parse_literal(text)
    }
}

impl fmt::Debug for Time {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}

impl fmt::Display for Time {
    /// The IEC literal: `LTIME#`, a `-` if negative, then every non-zero part from days to
    /// nanoseconds without separators (`LTIME#1d2h`), or `LTIME#0s` for zero.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("LTIME#")?;
        if self.0 < 0 {
            f.write_str("-")?;
        }
        // `unsigned_abs` holds |MIN| = 2^63, which `abs` cannot.
        let mut rest = self.0.unsigned_abs();
        if rest == 0 {
            return f.write_str("0s");
        }
        for unit in UNITS {
            let count = rest / unit.ns;
            rest %= unit.ns;
            if count != 0 {
                write!(f, "{count}{}", unit.symbol)?;
            }
        }
        Ok(())
    }
}

impl FromStr for Time {
    type Err = TimeError;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Time::parse(s)
    }
}

impl TryFrom<core::time::Duration> for Time {
    type Error = TimeError;

    /// A [`Duration`](core::time::Duration) as an `LTIME`: an error beyond [`Time::MAX`].
    fn try_from(d: core::time::Duration) -> Result<Self, Self::Error> {
        i64::try_from(d.as_nanos())
            .map(Time)
            .map_err(|_| TimeError::Overflow)
    }
}

/// Serialized as its IEC literal (`"LTIME#1s500ms"`); read back from any literal the grammar
/// accepts.
#[cfg(feature = "serde")]
impl serde::Serialize for Time {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_str(self)
    }
}

#[cfg(feature = "serde")]
impl<'de> serde::Deserialize<'de> for Time {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Visitor;
        impl serde::de::Visitor<'_> for Visitor {
            type Value = Time;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("an IEC duration literal such as \"T#1s500ms\"")
            }
            fn visit_str<E: serde::de::Error>(self, v: &str) -> Result<Time, E> {
                Time::parse(v).map_err(E::custom)
            }
        }
        deserializer.deserialize_str(Visitor)
    }
}

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

/// A unit of the grammar: its symbol, its length in nanoseconds, and the value a later part
/// of it must stay below (the next larger unit; none for days).
struct Unit {
    symbol: &'static str,
    ns: u64,
    limit: u64,
}

/// The units, largest first: the order the parts must come in.
const UNITS: [Unit; 7] = [
    Unit {
        symbol: "d",
        ns: 86_400 * NS_PER_S as u64,
        limit: u64::MAX,
    },
    Unit {
        symbol: "h",
        ns: 3_600 * NS_PER_S as u64,
        limit: 24,
    },
    Unit {
        symbol: "m",
        ns: 60 * NS_PER_S as u64,
        limit: 60,
    },
    Unit {
        symbol: "s",
        ns: NS_PER_S as u64,
        limit: 60,
    },
    Unit {
        symbol: "ms",
        ns: NS_PER_MS as u64,
        limit: 1000,
    },
    Unit {
        symbol: "us",
        ns: NS_PER_US as u64,
        limit: 1000,
    },
    Unit {
        symbol: "ns",
        ns: 1,
        limit: 1000,
    },
];

/// |i64::MIN| in nanoseconds: the largest magnitude any literal may reach.
const MAX_MAGNITUDE: u128 = 1 << 63;

/// A fraction's digits beyond this many (after trailing zeros are dropped) cannot be a whole
/// number of nanoseconds: a day is 2^16 * 3^3 * 5^11 ns, so 10^k divides no multiple of a unit
/// by a number without the factor 10 once k > 16.
const MAX_FRACTION_DIGITS: u32 = 16;

fn parse_literal(text: &str) -> Result<Time, TimeError> {
    let bytes = text.as_bytes();
    let hash = bytes
        .iter()
        .position(|&b| b == b'#')
        .ok_or(TimeError::NoPrefix)?;
    let prefix = &text[..hash];
    if !["T", "TIME", "LT", "LTIME"]
        .iter()
        .any(|p| prefix.eq_ignore_ascii_case(p))
    {
        return Err(TimeError::NoPrefix);
    }
    let mut at = hash + 1;
    let negative = match bytes.get(at) {
        Some(b'-') => {
            at += 1;
            true
        }
        Some(b'+') => {
            at += 1;
            false
        }
        _ => false,
    };
    if at >= bytes.len() {
        return Err(TimeError::Empty);
    }
    let mut total: u128 = 0;
    // Index into UNITS of the previous part, `None` before the first.
    let mut previous: Option<usize> = None;
    while at < bytes.len() {
        let whole = digits(bytes, &mut at)?;
        let fraction = if bytes.get(at) == Some(&b'.') {
            at += 1;
            Some(fraction_digits(bytes, &mut at)?)
        } else {
            None
        };
        let unit_index = unit_at(bytes, &mut at)?;
        let unit = &UNITS[unit_index];
        if let Some(p) = previous {
            if unit_index <= p {
                return Err(TimeError::UnitOrder {
                    unit: unit.symbol,
                    after: UNITS[p].symbol,
                });
            }
            if whole >= u128::from(unit.limit) {
                return Err(TimeError::PartTooLarge {
                    value: u64::try_from(whole).unwrap_or(u64::MAX),
                    unit: unit.symbol,
                    limit: unit.limit,
                });
            }
        }
        previous = Some(unit_index);
        let mut part = whole
            .checked_mul(u128::from(unit.ns))
            .ok_or(TimeError::Overflow)?;
        if let Some((numerator, places)) = fraction {
            // numerator / 10^places of a unit, which must be whole nanoseconds.
            let scaled = numerator * u128::from(unit.ns);
            let denominator = 10u128.pow(places);
            if scaled % denominator != 0 {
                return Err(TimeError::FinerThanNanosecond);
            }
            part += scaled / denominator;
        }
        total = total
            .checked_add(part)
            .filter(|&t| t <= MAX_MAGNITUDE)
            .ok_or(TimeError::Overflow)?;
        if bytes.get(at) == Some(&b'_') {
            at += 1;
            if !bytes.get(at).is_some_and(u8::is_ascii_digit) {
                return Err(TimeError::Unexpected { at });
            }
        }
        if fraction.is_some() && at < bytes.len() {
            return Err(TimeError::FractionNotLast);
        }
    }
    let ns = if negative {
        // 0 <= total <= 2^63, so -total fits an i64.
        (-(total as i128)) as i64
    } else {
        i64::try_from(total).map_err(|_| TimeError::Overflow)?
    };
    Ok(Time(ns))
}

/// A whole number with `_` between digits. It saturates at `u128::MAX`, which overflows
/// `LTIME` in any unit, so the caller's range checks report it. Leaves `at` after the last
/// digit.
fn digits(bytes: &[u8], at: &mut usize) -> Result<u128, TimeError> {
    if !bytes.get(*at).is_some_and(u8::is_ascii_digit) {
        return Err(TimeError::Unexpected { at: *at });
    }
    let mut n: u128 = 0;
    while let Some(&b) = bytes.get(*at) {
        match b {
            b'0'..=b'9' => n = n.saturating_mul(10).saturating_add(u128::from(b - b'0')),
            b'_' if bytes.get(*at + 1).is_some_and(u8::is_ascii_digit) => {}
            _ => break,
        }
        *at += 1;
    }
    Ok(n)
}

/// The digits after a decimal point (with `_` between digits) as `numerator / 10^places`,
/// trailing zeros dropped. Too many significant digits cannot be whole nanoseconds.
fn fraction_digits(bytes: &[u8], at: &mut usize) -> Result<(u128, u32), TimeError> {
    if !bytes.get(*at).is_some_and(u8::is_ascii_digit) {
        return Err(TimeError::Unexpected { at: *at });
    }
    let (mut numerator, mut places) = (0u128, 0u32);
    // Zeros seen since the last non-zero digit, applied only when another non-zero follows.
    let mut zeros = 0u32;
    while let Some(&b) = bytes.get(*at) {
        match b {
            b'0' => zeros += 1,
            b'1'..=b'9' => {
                places += zeros + 1;
                if places > MAX_FRACTION_DIGITS {
                    return Err(TimeError::FinerThanNanosecond);
                }
                numerator = numerator * 10u128.pow(zeros + 1) + u128::from(b - b'0');
                zeros = 0;
            }
            b'_' if bytes.get(*at + 1).is_some_and(u8::is_ascii_digit) => {}
            _ => break,
        }
        // A run of zeros alone may be long; cap it so the counter cannot overflow.
        zeros = zeros.min(MAX_FRACTION_DIGITS + 1);
        *at += 1;
    }
    Ok((numerator, places))
}

/// The unit at `at` (longest match, any case), as an index into [`UNITS`].
fn unit_at(bytes: &[u8], at: &mut usize) -> Result<usize, TimeError> {
    let lower = |i: usize| bytes.get(i).map(u8::to_ascii_lowercase);
    let (index, len) = match (lower(*at), lower(*at + 1)) {
        (Some(b'm'), Some(b's')) => (4, 2),
        (Some(b'u'), Some(b's')) => (5, 2),
        (Some(b'n'), Some(b's')) => (6, 2),
        (Some(b'd'), _) => (0, 1),
        (Some(b'h'), _) => (1, 1),
        (Some(b'm'), _) => (2, 1),
        (Some(b's'), _) => (3, 1),
        (None, _) => return Err(TimeError::MissingUnit { at: *at }),
        _ => return Err(TimeError::Unexpected { at: *at }),
    };
    *at += len;
    Ok(index)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use std::string::ToString;

    fn ms(n: i64) -> Result<Time, TimeError> {
        Ok(Time::from_millis(n))
    }

    #[test]
    fn every_prefix_in_any_case() {
        for prefix in [
            "T#", "t#", "TIME#", "time#", "LT#", "lt#", "LTIME#", "LTime#",
        ] {
            assert_eq!(Time::parse(&std::format!("{prefix}1s500ms")), ms(1500));
        }
        for bad in ["1s", "#1s", "D#1s", "TOD#1s", "LTIMES#1s", "T1s", " T#1s"] {
            assert_eq!(Time::parse(bad), Err(TimeError::NoPrefix), "{bad}");
        }
    }

    #[test]
    fn parts_signs_and_separators() {
        assert_eq!(Time::parse("LTIME#-2h_30m"), Ok(Time::from_secs(-9000)));
        assert_eq!(Time::parse("T#+1d"), Ok(Time::from_secs(86_400)));
        assert_eq!(Time::parse("T#1_000ms"), ms(1000));
        assert_eq!(
            Time::parse("LT#1d2h3m4s5ms6us7ns"),
            Ok(Time::from_nanos(
                ((((86_400 + 2 * 3600 + 3 * 60 + 4) * 1000 + 5) * 1000 + 6) * 1000) + 7
            ))
        );
        assert_eq!(Time::parse("T#1H_2M_3S"), Ok(Time::from_secs(3723)));
        assert_eq!(
            Time::parse("T#1MS"),
            ms(1),
            "ms is one unit, not minutes and s"
        );
        assert_eq!(Time::parse("T#-0s"), Ok(Time::ZERO));
    }

    #[test]
    fn only_the_first_part_may_exceed_its_unit() {
        assert_eq!(Time::parse("T#90m"), Ok(Time::from_secs(5400)));
        assert_eq!(
            Time::parse("T#25h_15m"),
            Ok(Time::from_secs(25 * 3600 + 900))
        );
        assert_eq!(
            Time::parse("T#1h75m"),
            Err(TimeError::PartTooLarge {
                value: 75,
                unit: "m",
                limit: 60
            })
        );
        assert!(matches!(
            Time::parse("T#1s1000ms"),
            Err(TimeError::PartTooLarge { .. })
        ));
        assert_eq!(Time::parse("T#1s999ms"), ms(1999));
    }

    #[test]
    fn units_in_order_each_once() {
        assert_eq!(
            Time::parse("T#1s1m"),
            Err(TimeError::UnitOrder {
                unit: "m",
                after: "s"
            })
        );
        assert_eq!(
            Time::parse("T#1s2s"),
            Err(TimeError::UnitOrder {
                unit: "s",
                after: "s"
            })
        );
    }

    #[test]
    fn a_fraction_on_the_last_part_only() {
        assert_eq!(Time::parse("T#1.5s"), ms(1500));
        assert_eq!(Time::parse("T#0.25h"), Ok(Time::from_secs(900)));
        assert_eq!(Time::parse("T#1m0.5s"), ms(60_500));
        assert_eq!(Time::parse("T#1.000_000_000_0s"), ms(1000));
        assert_eq!(Time::parse("T#1.5us"), Ok(Time::from_nanos(1500)));
        assert_eq!(Time::parse("T#1.5m30s"), Err(TimeError::FractionNotLast));
        assert_eq!(Time::parse("T#1.5ns"), Err(TimeError::FinerThanNanosecond));
        assert_eq!(
            Time::parse("T#0.0000000001s"),
            Err(TimeError::FinerThanNanosecond)
        );
        // 5e-11 min is 3 ns exactly: not rounded, not refused.
        assert_eq!(Time::parse("T#0.00000000005m"), Ok(Time::from_nanos(3)));
        assert_eq!(Time::parse("T#1.s"), Err(TimeError::Unexpected { at: 4 }));
    }

    #[test]
    fn malformed_texts_are_errors() {
        assert_eq!(Time::parse("T#"), Err(TimeError::Empty));
        assert_eq!(Time::parse("T#-"), Err(TimeError::Empty));
        assert_eq!(Time::parse("T#5"), Err(TimeError::MissingUnit { at: 3 }));
        assert_eq!(Time::parse("T#5x"), Err(TimeError::Unexpected { at: 3 }));
        assert_eq!(Time::parse("T#_5s"), Err(TimeError::Unexpected { at: 2 }));
        assert_eq!(Time::parse("T#5_s"), Err(TimeError::Unexpected { at: 3 }));
        assert_eq!(Time::parse("T#5s_"), Err(TimeError::Unexpected { at: 5 }));
        assert_eq!(
            Time::parse("T#5s__3ms"),
            Err(TimeError::Unexpected { at: 5 })
        );
        assert_eq!(Time::parse("T#--5s"), Err(TimeError::Unexpected { at: 3 }));
        assert_eq!(Time::parse("T#5s "), Err(TimeError::Unexpected { at: 4 }));
    }

    #[test]
    fn the_range_of_ltime_exactly() {
        let max = "LTIME#106751d23h47m16s854ms775us807ns";
        let min = "LTIME#-106751d23h47m16s854ms775us808ns";
        assert_eq!(Time::parse(max), Ok(Time::MAX));
        assert_eq!(Time::parse(min), Ok(Time::MIN));
        assert_eq!(
            (Time::MAX.to_string(), Time::MIN.to_string()),
            (max.into(), min.into())
        );
        assert_eq!(
            Time::parse("LTIME#106751d23h47m16s854ms775us808ns"),
            Err(TimeError::Overflow)
        );
        assert_eq!(Time::parse("T#106752d"), Err(TimeError::Overflow));
        assert_eq!(Time::parse("T#9223372036854775807ns"), Ok(Time::MAX));
        assert_eq!(Time::parse("T#-9223372036854775808ns"), Ok(Time::MIN));
        let huge = std::format!("T#{}s", "9".repeat(100));
        assert_eq!(Time::parse(&huge), Err(TimeError::Overflow));
    }

    #[test]
    fn display_is_a_literal_of_every_non_zero_part() {
        assert_eq!(Time::ZERO.to_string(), "LTIME#0s");
        assert_eq!(Time::from_millis(-500).to_string(), "LTIME#-500ms");
        assert_eq!(Time::from_secs(86_400 + 7200).to_string(), "LTIME#1d2h");
        assert_eq!(Time::from_nanos(1_001).to_string(), "LTIME#1us1ns");
        assert_eq!(std::format!("{:?}", Time::from_secs(90)), "LTIME#1m30s");
    }

    #[test]
    fn conversions_truncate_toward_zero_and_construction_saturates() {
        let t = Time::from_nanos(-1_999_999_999);
        assert_eq!(
            (t.as_secs(), t.as_millis(), t.as_micros()),
            (-1, -1999, -1_999_999)
        );
        assert_eq!(Time::from_millis(i64::MAX), Time::MAX);
        assert_eq!(Time::from_secs(i64::MIN), Time::MIN);
        assert_eq!(Time::MIN.checked_neg(), None);
        assert_eq!(Time::MIN.checked_sub(Time::from_nanos(1)), None);
        assert_eq!(Time::from_secs(2).checked_mul(3), Some(Time::from_secs(6)));
        assert_eq!(Time::MIN.saturating_sub(Time::MAX), Time::MIN);
        assert_eq!(
            Time::try_from(core::time::Duration::from_millis(1500)),
            Ok(Time::from_millis(1500))
        );
        assert_eq!(
            Time::try_from(core::time::Duration::from_secs(u64::MAX)),
            Err(TimeError::Overflow)
        );
    }

    #[test]
    fn errors_say_what_to_write() {
        let order = TimeError::UnitOrder {
            unit: "m",
            after: "s",
        };
        assert!(order.to_string().contains("from days to nanoseconds"));
        let overflow = TimeError::Overflow.to_string();
        assert!(overflow.contains("LTIME#106751d"), "{overflow}");
    }

    proptest! {
        #[test]
        fn arbitrary_text_never_panics(text in "\\PC{0,40}") {
            let _ = Time::parse(&text);
        }

        #[test]
        fn literal_like_text_never_panics(
            text in "(T|LT|TIME|LTIME)#[+-]?([0-9_.]{0,25}(d|h|m|s|ms|us|ns|x)?_?){0,8}"
        ) {
            let _ = Time::parse(&text);
        }

        #[test]
        fn display_parses_back_to_the_same_value(ns in any::<i64>()) {
            let t = Time::from_nanos(ns);
            prop_assert_eq!(Time::parse(&t.to_string()), Ok(t));
        }

        #[test]
        fn a_fraction_of_seconds_is_its_milliseconds(s in 0i64..100_000, frac in 0i64..1000) {
            let text = std::format!("T#{s}.{frac:03}s");
            prop_assert_eq!(Time::parse(&text), Ok(Time::from_millis(s * 1000 + frac)));
        }
    }
}
