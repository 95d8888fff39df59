//! The duration literal parser: `T#1s500ms` and the rest of the grammar of the
//! [module documentation](crate::time), read once, without allocating or panicking.

use super::duration::Time;
use super::error::TimeError;
use super::unit::UNITS;
use core::str::FromStr;

impl Time {
    /// Parses an IEC duration literal (see the [module documentation](crate::time) for the
    /// grammar). Surrounding whitespace is not part of a literal.
    pub fn parse(text: &str) -> Result<Time, TimeError> {
        parse_literal(text)
    }
}

impl FromStr for Time {
    type Err = TimeError;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Time::parse(s)
    }
}

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
    Ok(Time::from_nanos(ns))
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
