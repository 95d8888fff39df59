//! `Value`: one variable's value without its Rust type, for tools, the mailbox and `plc set`.

use crate::FixedString;
use core::fmt;
use plc_rules::{IecType, Time, TimeError, TypeFamily};

/// A value of any plc-vars type, `no_std` and without allocation.
///
/// Integers and bit strings are `Int` or `UInt` (either is accepted for either kind when in
/// range), reals `Real`, strings `Text`, durations (`LTIME`) `Time`.
///
/// ```
/// use plc_core::{IecType, Value};
/// assert_eq!(Value::parse("-5", IecType::Dint), Ok(Value::Int(-5)));
/// assert_eq!(Value::parse("1", IecType::Bool), Ok(Value::Bool(true)));
/// assert!(Value::parse("300", IecType::Usint).is_err());
/// assert_eq!(Value::parse("\"TEST 1\"", IecType::String).unwrap().to_string(), "TEST 1");
/// let delay = Value::parse("T#1m30s", IecType::Ltime).unwrap();
/// assert_eq!(delay, Value::Time(plc_core::Time::from_secs(90)));
/// assert_eq!(delay.to_string(), "LTIME#1m30s");
/// ```
// Text is stored inline (no allocator in `no_std`); a Value is 264 bytes by design.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Value {
    /// `BOOL`.
    Bool(bool),
    /// A signed whole number.
    Int(i64),
    /// An unsigned whole number.
    UInt(u64),
    /// `REAL` or `LREAL`.
    Real(f64),
    /// `STRING` (at most 255 bytes).
    Text(FixedString<255>),
    /// `LTIME`: a duration.
    Time(Time),
}

/// Why a value does not fit a type.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ValueError {
    /// The value is of another kind (e.g. text for an integer).
    WrongKind {
        /// The type that was expected.
        expected: IecType,
        /// The kind that was given: "bool", "integer", "real" or "text".
        found: &'static str,
    },
    /// The number is outside the type's range.
    OutOfRange {
        /// The type whose range was exceeded.
        expected: IecType,
    },
    /// The text is longer than the string's capacity.
    TooLong {
        /// Bytes of the text.
        len: usize,
        /// The capacity in bytes.
        capacity: usize,
    },
    /// Text with a NUL (zero) byte: a stored string ends at its first zero byte, so what
    /// follows would be lost.
    Nul {
        /// Byte offset of the NUL in the text as given.
        at: usize,
    },
    /// Text that does not parse as a value of the type.
    Syntax {
        /// The type that was expected.
        expected: IecType,
    },
    /// NaN or an infinity for a REAL or LREAL written from a tool: a setpoint is a number.
    NotFinite {
        /// The type written.
        expected: IecType,
    },
    /// Text that is not a duration literal, for an `LTIME` (one beyond its range is
    /// [`OutOfRange`](Self::OutOfRange)).
    Duration {
        /// What is wrong with it.
        error: TimeError,
    },
}

impl fmt::Display for ValueError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            ValueError::WrongKind { expected, found } => {
                write!(f, "expected a {expected} value, found {found}")
            }
            ValueError::OutOfRange { expected } => match expected.int_range() {
                Some((lo, hi)) => write!(f, "out of range for {expected} ({lo}..={hi})"),
                None if expected == IecType::Ltime => {
                    write!(f, "out of range for LTIME ({}..={})", Time::MIN, Time::MAX)
                }
                None => write!(f, "out of range for {expected}"),
            },
            ValueError::TooLong { len, capacity } => write!(
                f,
                "text of {len} bytes is longer than the capacity of {capacity} bytes"
            ),
            ValueError::Nul { at } => write!(
                f,
                "text has a NUL (zero) byte at byte {at}, where a stored string ends: remove it"
            ),
            ValueError::Syntax { expected } => match expected {
                IecType::Bool => f.write_str("expected a BOOL: true, false, 1 or 0"),
                t if t.is_integer() => write!(f, "expected a whole number for {t}"),
                t if t.is_real() => write!(f, "expected a number for {t}"),
                t => write!(f, "expected a {t} value"),
            },
            ValueError::Duration { error } => write!(f, "expected an LTIME: {error}"),
            ValueError::NotFinite { expected } => write!(
                f,
                "not a finite number: {expected} takes no NaN or infinity from a tool"
            ),
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for ValueError {}

impl Value {
    /// The kind of value, as error messages name it.
    pub fn kind(&self) -> &'static str {
        match self {
            Value::Bool(_) => "bool",
            Value::Int(_) | Value::UInt(_) => "integer",
            Value::Real(_) => "real",
            Value::Text(_) => "text",
            Value::Time(_) => "duration",
        }
    }

    /// The whole number, if this is `Int` or `UInt`.
    pub fn as_i128(&self) -> Option<i128> {
        match *self {
            Value::Int(v) => Some(v as i128),
            Value::UInt(v) => Some(v as i128),
            _ => None,
        }
    }

    /// Checks that the value fits `ty` (kind and range; `capacity` for strings) and returns it in
    /// its canonical form: `Int` for signed, `UInt` for unsigned integers and bit strings, `Real`
    /// for reals (a whole number is accepted for a real, IEC 61131-3's untyped literals). An
    /// `LTIME` takes only a `Time`: a bare number's unit would be a guess.
    pub fn fit(self, ty: IecType, capacity: usize) -> Result<Value, ValueError> {
        let wrong = |v: &Value| ValueError::WrongKind {
            expected: ty,
            found: v.kind(),
        };
        match ty.family() {
            TypeFamily::Bool => match self {
                Value::Bool(_) => Ok(self),
                other => Err(wrong(&other)),
            },
            TypeFamily::SignedInt | TypeFamily::UnsignedInt | TypeFamily::BitString => {
                let v = self.as_i128().ok_or_else(|| wrong(&self))?;
                let (lo, hi) = ty.int_range().unwrap_or((0, 0));
                if v < lo || v > hi {
                    return Err(ValueError::OutOfRange { expected: ty });
                }
                Ok(if ty.is_signed() {
                    Value::Int(v as i64)
                } else {
                    Value::UInt(v as u64)
                })
            }
            TypeFamily::Real => {
                let v = match self {
                    Value::Real(v) => v,
                    Value::Int(i) => i as f64,
                    Value::UInt(u) => u as f64,
                    other => return Err(wrong(&other)),
                };
                if ty == IecType::Real && v.is_finite() && v.abs() > f32::MAX as f64 {
                    return Err(ValueError::OutOfRange { expected: ty });
                }
                Ok(Value::Real(v))
            }
            TypeFamily::String => match self {
                Value::Text(t) if t.len() <= capacity => Ok(self),
                Value::Text(t) => Err(ValueError::TooLong {
                    len: t.len(),
                    capacity,
                }),
                other => Err(wrong(&other)),
            },
            TypeFamily::Time => match self {
                Value::Time(_) => Ok(self),
                other => Err(wrong(&other)),
            },
        }
    }

    /// Parses text as a value of `ty`, as a person types it (`plc set`): bools `true`/`false`/
    /// `1`/`0`; integers in decimal, `0x`/`16#` hex, `2#` binary, `8#` octal, with `_` separators; reals in
    /// decimal or exponent notation; strings as plain text or in double quotes (with `\"`, `\\`,
    /// `\n`, `\t` escapes); durations as IEC literals (`T#1m30s`, `LTIME#-2.5s`: the grammar
    /// of [`Time::parse`]). Strings are checked against the largest capacity, 255 bytes; check
    /// a variable's own capacity with [`fit`](Self::fit).
    pub fn parse(text: &str, ty: IecType) -> Result<Value, ValueError> {
        let syntax = ValueError::Syntax { expected: ty };
        let t = text.trim();
        let value = match ty.family() {
            TypeFamily::Bool => {
                if t.eq_ignore_ascii_case("true") || t == "1" {
                    Value::Bool(true)
                } else if t.eq_ignore_ascii_case("false") || t == "0" {
                    Value::Bool(false)
                } else {
                    return Err(syntax);
                }
            }
            TypeFamily::SignedInt | TypeFamily::UnsignedInt | TypeFamily::BitString => {
                let n = parse_integer(t).ok_or(syntax)?;
                let (lo, hi) = ty.int_range().unwrap_or((0, 0));
                if n < lo || n > hi {
                    return Err(ValueError::OutOfRange { expected: ty });
                }
                if n < 0 {
                    Value::Int(n as i64)
                } else {
                    Value::UInt(n as u64)
                }
            }
            TypeFamily::Real => Value::Real(t.parse().map_err(|_| syntax)?),
            TypeFamily::String => {
                let unquoted = unquote(text).ok_or(syntax)?;
                let len = unquoted.len();
                if len > 255 {
                    return Err(ValueError::TooLong { len, capacity: 255 });
                }
                // Where the user typed it: an escape cannot make a NUL, so it is in `text`.
                if let Some(at) = text.find('\0') {
                    return Err(ValueError::Nul { at });
                }
                Value::Text(FixedString::from_str_truncate(unquoted.as_ref()))
            }
            TypeFamily::Time => Value::Time(Time::parse(t).map_err(|error| match error {
                TimeError::Overflow => ValueError::OutOfRange { expected: ty },
                error => ValueError::Duration { error },
            })?),
        };
        value.fit(ty, 255)
    }
}

/// Parses a whole number: decimal, `0x`/`16#` hex, `0b`/`2#` binary, `8#` octal, `_` separators.
/// Written without allocation (plc-core is `no_std` without `alloc`).
fn parse_integer(t: &str) -> Option<i128> {
    let (negative, digits) = match t.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, t.strip_prefix('+').unwrap_or(t)),
    };
    let strip = |prefix: &str| {
        (digits.len() >= prefix.len() && digits[..prefix.len()].eq_ignore_ascii_case(prefix))
            .then(|| &digits[prefix.len()..])
    };
    let (radix, body) = if let Some(b) = strip("0x").or_else(|| strip("16#")) {
        (16, b)
    } else if let Some(b) = strip("0b").or_else(|| strip("2#")) {
        (2, b)
    } else if let Some(b) = strip("8#") {
        (8, b)
    } else {
        (10, digits)
    };
    let mut n: i128 = 0;
    let mut any = false;
    for c in body.chars() {
        if c == '_' && any {
            continue;
        }
        let d = c.to_digit(radix)?;
        n = n.checked_mul(radix as i128)?.checked_add(d as i128)?;
        any = true;
    }
    any.then_some(if negative { -n } else { n })
}

/// Strips surrounding double quotes and resolves escapes; plain text is taken as it is.
fn unquote(text: &str) -> Option<StrOrOwned<'_>> {
    let trimmed = text.trim();
    let Some(inner) = trimmed
        .strip_prefix('"')
        .and_then(|r| r.strip_suffix('"'))
        .filter(|_| trimmed.len() >= 2)
    else {
        return Some(StrOrOwned::Borrowed(text));
    };
    let mut out = FixedString::<255>::new();
    let mut buf = [0u8; 4];
    let mut chars = inner.chars();
    let mut total = 0usize;
    while let Some(c) = chars.next() {
        let c = if c == '\\' {
            match chars.next()? {
                'n' => '\n',
                't' => '\t',
                other => other,
            }
        } else {
            c
        };
        total += c.len_utf8();
        // Keep counting past the capacity so the caller reports the real length.
        let _ = fmt::Write::write_str(&mut out, c.encode_utf8(&mut buf));
    }
    Some(StrOrOwned::Owned(out, total))
}

#[allow(clippy::large_enum_variant)]
enum StrOrOwned<'a> {
    Borrowed(&'a str),
    Owned(FixedString<255>, usize),
}

impl StrOrOwned<'_> {
    fn len(&self) -> usize {
        match self {
            StrOrOwned::Borrowed(s) => s.len(),
            StrOrOwned::Owned(_, len) => *len,
        }
    }
}

impl AsRef<str> for StrOrOwned<'_> {
    fn as_ref(&self) -> &str {
        match self {
            StrOrOwned::Borrowed(s) => s,
            StrOrOwned::Owned(s, _) => s.as_str(),
        }
    }
}

impl fmt::Display for Value {
    /// Booleans as `true`/`false`, numbers in decimal (reals always with a point or exponent),
    /// text as it is, durations as IEC literals (`LTIME#1m30s`).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Value::Bool(b) => write!(f, "{b}"),
            Value::Int(i) => write!(f, "{i}"),
            Value::UInt(u) => write!(f, "{u}"),
            Value::Real(r) if r.abs() < 1e15 && (*r as i64) as f64 == *r => {
                write!(f, "{r:.1}")
            }
            Value::Real(r) => write!(f, "{r}"),
            Value::Text(t) => f.write_str(t.as_str()),
            Value::Time(t) => fmt::Display::fmt(t, f),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn text(s: &str) -> Value {
        Value::Text(FixedString::from_str_truncate(s))
    }

    #[test]
    fn bools_accept_words_and_digits() {
        for (t, v) in [
            ("true", true),
            ("TRUE", true),
            ("1", true),
            ("false", false),
            ("0", false),
        ] {
            assert_eq!(Value::parse(t, IecType::Bool), Ok(Value::Bool(v)));
        }
        assert!(Value::parse("yes", IecType::Bool).is_err());
    }

    #[test]
    fn integers_check_the_range_of_their_type() {
        assert_eq!(Value::parse("255", IecType::Usint), Ok(Value::UInt(255)));
        assert_eq!(
            Value::parse("256", IecType::Usint),
            Err(ValueError::OutOfRange {
                expected: IecType::Usint
            })
        );
        assert_eq!(Value::parse("-128", IecType::Sint), Ok(Value::Int(-128)));
        assert!(Value::parse("-1", IecType::Word).is_err());
        assert_eq!(
            Value::parse("16#FF_FF", IecType::Word),
            Ok(Value::UInt(0xFFFF))
        );
        assert_eq!(Value::parse("0x10", IecType::Int), Ok(Value::Int(16)));
        assert_eq!(Value::parse("2#101", IecType::Byte), Ok(Value::UInt(5)));
        assert_eq!(
            Value::parse("18446744073709551615", IecType::Ulint),
            Ok(Value::UInt(u64::MAX))
        );
        assert!(Value::parse("1.5", IecType::Dint).is_err());
        assert!(Value::parse("--1", IecType::Dint).is_err());
        assert!(Value::parse("", IecType::Dint).is_err());
    }

    #[test]
    fn reals_take_decimals_exponents_and_whole_numbers() {
        assert_eq!(Value::parse("12.5", IecType::Lreal), Ok(Value::Real(12.5)));
        assert_eq!(
            Value::parse("-1e3", IecType::Real),
            Ok(Value::Real(-1000.0))
        );
        assert_eq!(Value::Int(3).fit(IecType::Real, 0), Ok(Value::Real(3.0)));
        assert!(Value::parse("1e39", IecType::Real).is_err());
        assert!(Value::parse("1e39", IecType::Lreal).is_ok());
        assert!(Value::parse("abc", IecType::Real).is_err());
    }

    #[test]
    fn strings_plain_or_quoted() {
        assert_eq!(
            Value::parse("hello world", IecType::String),
            Ok(text("hello world"))
        );
        assert_eq!(
            Value::parse("\"a \\\"b\\\"\"", IecType::String),
            Ok(text("a \"b\""))
        );
        assert_eq!(Value::parse("\"\"", IecType::String), Ok(text("")));
        // Text after a NUL would be cut off when stored: refused, plain or quoted.
        assert_eq!(
            Value::parse("ab\0cd", IecType::String),
            Err(ValueError::Nul { at: 2 })
        );
        assert_eq!(
            Value::parse("\"x\0\"", IecType::String),
            Err(ValueError::Nul { at: 2 })
        );
        let e = ValueError::Nul { at: 2 }.to_string();
        assert!(e.contains("NUL (zero) byte at byte 2"), "{e}");
        let long = "x".repeat(256);
        assert_eq!(
            Value::parse(&long, IecType::String),
            Err(ValueError::TooLong {
                len: 256,
                capacity: 255
            })
        );
        assert_eq!(
            text("abcdef").fit(IecType::String, 4),
            Err(ValueError::TooLong {
                len: 6,
                capacity: 4
            })
        );
    }

    #[test]
    fn durations_parse_as_literals_and_take_only_durations() {
        assert_eq!(
            Value::parse(" T#1s500ms ", IecType::Ltime),
            Ok(Value::Time(Time::from_millis(1500)))
        );
        assert_eq!(
            Value::parse("5000", IecType::Ltime),
            Err(ValueError::Duration {
                error: TimeError::NoPrefix
            })
        );
        let overflow = Value::parse("T#106752d", IecType::Ltime).unwrap_err();
        assert_eq!(
            overflow,
            ValueError::OutOfRange {
                expected: IecType::Ltime
            }
        );
        assert!(
            overflow.to_string().contains("LTIME#106751d23h"),
            "{overflow}"
        );
        let order = Value::parse("T#1s1m", IecType::Ltime)
            .unwrap_err()
            .to_string();
        assert!(
            order.starts_with("expected an LTIME: `m` comes after `s`"),
            "{order}"
        );
        assert_eq!(
            Value::Int(5).fit(IecType::Ltime, 0),
            Err(ValueError::WrongKind {
                expected: IecType::Ltime,
                found: "integer"
            })
        );
        assert!(Value::Time(Time::ZERO).fit(IecType::Lint, 0).is_err());
    }

    #[test]
    fn kinds_are_checked() {
        assert_eq!(
            Value::Bool(true).fit(IecType::Dint, 0),
            Err(ValueError::WrongKind {
                expected: IecType::Dint,
                found: "bool"
            })
        );
        assert!(Value::Real(1.0).fit(IecType::Int, 0).is_err());
        assert!(Value::Int(1).fit(IecType::Bool, 0).is_err());
        assert!(Value::Int(1).fit(IecType::String, 8).is_err());
        assert_eq!(Value::Int(5).fit(IecType::Udint, 0), Ok(Value::UInt(5)));
        assert_eq!(Value::UInt(5).fit(IecType::Lint, 0), Ok(Value::Int(5)));
    }

    #[test]
    fn display_is_parseable_again() {
        for (v, t) in [
            (Value::Bool(true), IecType::Bool),
            (Value::Int(-7), IecType::Dint),
            (Value::UInt(9), IecType::Udint),
            (Value::Real(2.0), IecType::Lreal),
            (Value::Real(0.1), IecType::Lreal),
            (Value::Time(Time::from_millis(-1500)), IecType::Ltime),
            (Value::Time(Time::MIN), IecType::Ltime),
        ] {
            assert_eq!(Value::parse(&v.to_string(), t), Ok(v));
        }
        assert_eq!(Value::Real(2.0).to_string(), "2.0");
    }
}
