//! How `plc get`, `plc watch` and `plc log` print a value: numbers people read, text that
//! stays data.
//!
//! - A REAL is printed as the f32 it is, never with the digits of its widening to f64: REAL
//!   0.1 is `0.1`, not `0.10000000149011612`. At full precision a real gets the fewest digits
//!   that read back as the same value of its type; `--digits N` rounds to N significant digits
//!   and drops trailing zeros. A whole number keeps `.0` (`5.0`), as [`Value`]'s `Display` does.
//! - A real is written plainly (`0.00125`, `1250.0`) unless that takes more than N + 5
//!   characters (N the digits asked for; 9 for a REAL and 17 for an LREAL at full precision),
//!   then as `d.ddde±x` (`1.23457e9`, `1.0e-12`), which reads back as an IEC real literal.
//! - `--hex` and `--bin` write integers and bit strings as IEC literals of all the type's bits
//!   in groups of four digits (`16#00FF`, `16#FFFF_FFFF`, `2#1111_1100`); a negative signed
//!   integer as its two's complement.
//! - For a person (`plc get`, `watch`, `forces`: [`Format::seconds`]) a TIME or LTIME is
//!   seconds, as a real with the digits asked (`4.34 s` where the IEC literal reads
//!   `LTIME#4s340ms4us953ns`), at full precision its exact nanoseconds (`4.340004953 s`).
//!   `plc log`, `trace` and what a tool echoes back of a write keep the literal.
//! - A STRING's control characters are escaped ([`escape_text`]): text a program stored, an ESC
//!   sequence say, must not drive the terminal that shows it. A CSV cell of text that a
//!   spreadsheet would run as a formula is kept text ([`csv_cell`]).

use plc_core::{IecType, Value};
use std::fmt::Write;

/// The most significant digits `--digits` takes: 17 are enough for any LREAL to read back.
pub const MAX_DIGITS: u8 = 17;

/// How integers and bit strings are written.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Radix {
    /// In decimal: `255`, `-1`.
    #[default]
    Decimal,
    /// As IEC hex literals of the type's width: `16#00FF`.
    Hex,
    /// As IEC binary literals of the type's width: `2#0000_0000_1111_1111`.
    Bin,
}

/// How values are printed. The default is full precision, integers in decimal.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Format {
    /// Significant digits of REAL and LREAL values, 1 to [`MAX_DIGITS`] (more count as
    /// [`MAX_DIGITS`], 0 as 1); `None` for as many as it takes to read back as the same value.
    pub digits: Option<u8>,
    /// How integers and bit strings are written.
    pub radix: Radix,
    /// TIME and LTIME as seconds a person reads (`4.34 s`) instead of IEC literals.
    pub seconds: bool,
}

/// The flags that choose a [`Format`], shared by `plc get` and `plc watch`.
#[derive(clap::Args, Clone, Copy, Debug)]
pub struct FormatArgs {
    /// Significant digits of REAL and LREAL values, 1 to 17.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u8).range(1..=MAX_DIGITS as i64))]
    pub digits: Option<u8>,
    /// Integers and bit strings as IEC hex literals of the type's width (16#00FF).
    #[arg(long, conflicts_with = "bin")]
    pub hex: bool,
    /// Integers and bit strings as IEC binary literals of the type's width (2#0000_1111).
    #[arg(long)]
    pub bin: bool,
}

impl FormatArgs {
    /// The format the flags ask for.
    pub fn format(self) -> Format {
        let radix = match (self.hex, self.bin) {
            (true, _) => Radix::Hex,
            (_, true) => Radix::Bin,
            _ => Radix::Decimal,
        };
        Format {
            digits: self.digits,
            radix,
            // The flags are `get`'s, `watch`'s and `forces`': a person reads them.
            seconds: true,
        }
    }
}

/// A value of a variable of type `iec_type` as `f` asks; text escaped by [`escape_text`].
pub fn value(v: &Value, iec_type: IecType, f: &Format) -> String {
    match v {
        Value::Real(r) => real(*r, iec_type, f.digits),
        Value::Int(_) | Value::UInt(_) if iec_type.is_integer() => match f.radix {
            Radix::Decimal => v.to_string(),
            Radix::Hex => {
                let width = iec_type.bits() as usize / 4;
                literal("16#", &format!("{:0width$X}", bits_of(v, iec_type)))
            }
            Radix::Bin => {
                let width = iec_type.bits() as usize;
                literal("2#", &format!("{:0width$b}", bits_of(v, iec_type)))
            }
        },
        Value::Text(t) => escape_text(t.as_str()),
        Value::Time(t) if f.seconds => seconds(t.as_nanos(), f.digits),
        other => other.to_string(),
    }
}

/// `ns` nanoseconds as seconds for a person: rounded to `digits` significant digits as a
/// real is, or exact (trailing zeros dropped, `.0` kept as a real's) without.
fn seconds(ns: i64, digits: Option<u8>) -> String {
    if digits.is_some() {
        return format!("{} s", real(ns as f64 / 1e9, IecType::Lreal, digits));
    }
    let sign = if ns < 0 { "-" } else { "" };
    let abs = ns.unsigned_abs();
    let fraction = format!("{:09}", abs % 1_000_000_000);
    let fraction = match fraction.trim_end_matches('0') {
        "" => "0",
        kept => kept,
    };
    format!("{sign}{}.{fraction} s", abs / 1_000_000_000)
}

/// Text with what could act on a terminal, or hide what it shows, written out: `\n`, `\r`,
/// `\t`, other ASCII control characters as `\x1b`, other control characters and the
/// bidirectional overrides (which can reorder what a reader sees) as `\u{9b}`; a backslash is
/// doubled so an escape the text really holds is told from one added here.
pub fn escape_text(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            c if c.is_ascii_control() => {
                let _ = write!(out, "\\x{:02x}", c as u32);
            }
            c if c.is_control() || is_bidi_control(c) => {
                let _ = write!(out, "\\u{{{:x}}}", c as u32);
            }
            c => out.push(c),
        }
    }
    out
}

/// One CSV cell (RFC 4180: quoted when it holds a comma, quote or line break) of `shown`, a
/// value as [`value`] printed it (a STRING's control characters already escaped). `text` says
/// it is a STRING's: text that starts with `=`, `+`, `-`, `@`, a tab or a CR would run as a
/// formula in a spreadsheet, so it gets a leading `'` inside quotes (OWASP's advice on CSV
/// injection); a number such as `-1.5` is left a number.
pub fn csv_cell(shown: &str, text: bool) -> String {
    let quoted = |s: &str| format!("\"{}\"", s.replace('"', "\"\""));
    if text && shown.starts_with(['=', '+', '-', '@', '\t', '\r']) {
        quoted(&format!("'{shown}"))
    } else if shown.contains([',', '"', '\n', '\r']) {
        quoted(shown)
    } else {
        shown.to_string()
    }
}

/// The Unicode controls that reorder text as displayed ("Trojan Source"), none of which
/// `char::is_control` counts.
fn is_bidi_control(c: char) -> bool {
    matches!(c, '\u{061c}' | '\u{200e}' | '\u{200f}' | '\u{202a}'..='\u{202e}' | '\u{2066}'..='\u{2069}')
}

/// An integer's bits in its type's width: a negative one as its two's complement.
fn bits_of(v: &Value, iec_type: IecType) -> u128 {
    let mask = (1u128 << iec_type.bits()) - 1;
    v.as_i128().unwrap_or(0) as u128 & mask
}

/// `prefix` and the digits in groups of four from the right, `_` between: `2#0000_1111`.
fn literal(prefix: &str, digits: &str) -> String {
    let mut out = String::from(prefix);
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(4) {
            out.push('_');
        }
        out.push(c);
    }
    out
}

/// A real in its own type's precision, to `digits` significant digits (or all it needs).
fn real(r: f64, iec_type: IecType, digits: Option<u8>) -> String {
    if !r.is_finite() {
        return Value::Real(r).to_string();
    }
    let digits = digits.map(|d| d.clamp(1, MAX_DIGITS) as usize);
    // A REAL's value is an f32 widened: its own digits are the f32's.
    let (mantissa, exp, full) = if iec_type == IecType::Real {
        let (m, e) = significant(r.abs() as f32, digits);
        (m, e, 9)
    } else {
        let (m, e) = significant(r.abs(), digits);
        (m, e, 17)
    };
    let sign = if r.is_sign_negative() { "-" } else { "" };
    format!(
        "{sign}{}",
        layout(&mantissa, exp, digits.unwrap_or(full) + 5)
    )
}

/// The significant digits of `x` (at least one), trailing zeros dropped, and its decimal
/// exponent: the shortest that reads back as `x`, rounded to `digits` if that is fewer.
fn significant<T: std::fmt::LowerExp>(x: T, digits: Option<usize>) -> (String, i32) {
    // `{:e}` is Rust's shortest round-trip form of the type; `{:.Ne}` rounds the exact value.
    let shortest = format!("{x:e}");
    let count = shortest
        .split('e')
        .next()
        .map_or(0, |m| m.replace('.', "").len());
    let text = match digits {
        Some(n) if n < count => format!("{x:.*e}", n - 1),
        _ => shortest,
    };
    let (m, e) = text.split_once('e').unwrap_or((&text, "0"));
    let mut m: String = m.chars().filter(char::is_ascii_digit).collect();
    while m.len() > 1 && m.ends_with('0') {
        m.pop();
    }
    (m, e.parse().unwrap_or(0))
}

/// Digits `m` (d.ddd) times 10^`exp`, plainly if that fits in `budget` characters, else in
/// exponent form; either with at least one digit after the point.
fn layout(m: &str, exp: i32, budget: usize) -> String {
    let k = m.len();
    // The plain form's length, known before building it: an exponent of 300 must not build
    // 300 zeros only to throw them away.
    let plain_len = if exp >= 0 {
        let int = exp as usize + 1;
        int + 1 + k.saturating_sub(int).max(1)
    } else {
        1 + exp.unsigned_abs() as usize + k
    };
    if plain_len > budget {
        let rest = if k > 1 { &m[1..] } else { "0" };
        return format!("{}.{rest}e{exp}", &m[..1]);
    }
    if exp < 0 {
        format!("0.{}{m}", "0".repeat(exp.unsigned_abs() as usize - 1))
    } else {
        let int = exp as usize + 1;
        if k <= int {
            format!("{m}{}.0", "0".repeat(int - k))
        } else {
            format!("{}.{}", &m[..int], &m[int..])
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use plc_core::FixedString;

    const FULL: Format = Format {
        digits: None,
        radix: Radix::Decimal,
        seconds: false,
    };

    fn digits(n: u8) -> Format {
        Format {
            digits: Some(n),
            radix: Radix::Decimal,
            seconds: false,
        }
    }

    fn radix(radix: Radix) -> Format {
        Format {
            digits: None,
            radix,
            seconds: false,
        }
    }

    fn text(s: &str) -> Value {
        Value::Text(FixedString::from_str_truncate(s))
    }

    #[test]
    fn a_real_prints_the_shortest_text_of_its_f32_not_of_its_widening() {
        let widened = 0.1f32 as f64;
        assert_eq!(value(&Value::Real(widened), IecType::Real, &FULL), "0.1");
        assert_eq!(
            value(&Value::Real(widened), IecType::Lreal, &FULL),
            "0.10000000149011612"
        );
        assert_eq!(value(&Value::Real(0.1), IecType::Lreal, &FULL), "0.1");
        // More digits than the f32 has add none of the f64's.
        assert_eq!(
            value(&Value::Real(widened), IecType::Real, &digits(17)),
            "0.1"
        );
        let third = (1.0f32 / 3.0) as f64;
        assert_eq!(
            value(&Value::Real(third), IecType::Real, &FULL),
            "0.33333334"
        );
        assert_eq!(
            value(&Value::Real(third), IecType::Real, &digits(3)),
            "0.333"
        );
    }

    #[test]
    fn a_computed_lreal_reads_as_its_rounded_digits() {
        let v = Value::Real(5.033999999999668);
        assert_eq!(value(&v, IecType::Lreal, &digits(6)), "5.034");
        assert_eq!(value(&v, IecType::Lreal, &FULL), "5.033999999999668");
        assert_eq!(value(&v, IecType::Lreal, &digits(17)), "5.033999999999668");
        assert_eq!(value(&v, IecType::Lreal, &digits(1)), "5.0");
        assert_eq!(value(&v, IecType::Lreal, &digits(2)), "5.0");
        assert_eq!(value(&v, IecType::Lreal, &digits(3)), "5.03");
    }

    #[test]
    fn whole_numbers_keep_a_point_and_rounding_carries() {
        for (r, n, shown) in [
            (0.0, 6, "0.0"),
            (-0.0, 6, "-0.0"),
            (250.0, 6, "250.0"),
            (2.0, 1, "2.0"),
            (9.96, 2, "10.0"),
            (-9.96, 2, "-10.0"),
            (99999.96, 6, "100000.0"),
            (-1.5, 6, "-1.5"),
            (0.000123456789, 6, "0.000123457"),
        ] {
            assert_eq!(value(&Value::Real(r), IecType::Lreal, &digits(n)), shown);
        }
    }

    #[test]
    fn large_and_small_magnitudes_take_an_exponent_when_plain_is_too_long() {
        for (r, n, shown) in [
            (1234567890.0, Some(6), "1.23457e9"),
            (123456789.0, Some(6), "123457000.0"),
            (0.0000123456789, Some(6), "1.23457e-5"),
            (1.5e-9, Some(6), "1.5e-9"),
            (1e-7, Some(6), "0.0000001"),
            (1e20, None, "1.0e20"),
            (1e15, None, "1000000000000000.0"),
            (-1e300, Some(3), "-1.0e300"),
            (f64::MIN_POSITIVE, None, "2.2250738585072014e-308"),
        ] {
            let f = Format {
                digits: n,
                radix: Radix::Decimal,
                seconds: false,
            };
            let shown_now = value(&Value::Real(r), IecType::Lreal, &f);
            assert_eq!(shown_now, shown);
            if n.is_none() {
                assert_eq!(shown_now.parse::<f64>(), Ok(r), "{shown_now} reads back");
            }
        }
        assert_eq!(
            value(&Value::Real(f32::MAX as f64), IecType::Real, &FULL),
            "3.4028235e38"
        );
        assert_eq!(
            value(&Value::Real(16777216.0), IecType::Real, &FULL),
            "16777216.0"
        );
    }

    #[test]
    fn full_precision_reads_back_as_the_same_value() {
        for r in [
            0.1,
            1.0 / 3.0,
            5.033999999999668,
            1e-300,
            123456.789,
            -2.5e17,
        ] {
            let shown = value(&Value::Real(r), IecType::Lreal, &FULL);
            assert_eq!(shown.parse::<f64>(), Ok(r), "{shown}");
            assert_eq!(Value::parse(&shown, IecType::Lreal), Ok(Value::Real(r)));
        }
        for r in [0.1f32, 1.0 / 3.0, 3.0e-40, 7.5e12] {
            let shown = value(&Value::Real(r as f64), IecType::Real, &FULL);
            assert_eq!(shown.parse::<f32>(), Ok(r), "{shown}");
        }
    }

    #[test]
    fn not_finite_reals_print_as_before() {
        assert_eq!(
            value(&Value::Real(f64::NAN), IecType::Real, &digits(3)),
            "NaN"
        );
        assert_eq!(
            value(&Value::Real(f64::INFINITY), IecType::Lreal, &FULL),
            "inf"
        );
        assert_eq!(
            value(&Value::Real(f64::NEG_INFINITY), IecType::Lreal, &FULL),
            "-inf"
        );
    }

    #[test]
    fn hex_and_bin_are_padded_to_the_types_width() {
        let hex = radix(Radix::Hex);
        let bin = radix(Radix::Bin);
        assert_eq!(value(&Value::UInt(255), IecType::Word, &hex), "16#00FF");
        assert_eq!(
            value(&Value::UInt(255), IecType::Word, &bin),
            "2#0000_0000_1111_1111"
        );
        assert_eq!(value(&Value::UInt(255), IecType::Byte, &hex), "16#FF");
        assert_eq!(value(&Value::UInt(5), IecType::Usint, &bin), "2#0000_0101");
        assert_eq!(
            value(&Value::UInt(0xDEAD_BEEF), IecType::Dword, &hex),
            "16#DEAD_BEEF"
        );
        assert_eq!(
            value(&Value::UInt(1), IecType::Lword, &hex),
            "16#0000_0000_0000_0001"
        );
        assert_eq!(
            value(&Value::UInt(u64::MAX), IecType::Ulint, &hex),
            "16#FFFF_FFFF_FFFF_FFFF"
        );
        // A negative signed integer: its two's complement in its own width.
        assert_eq!(value(&Value::Int(-1), IecType::Sint, &hex), "16#FF");
        assert_eq!(value(&Value::Int(-4), IecType::Sint, &bin), "2#1111_1100");
        assert_eq!(value(&Value::Int(-4), IecType::Int, &hex), "16#FFFC");
        assert_eq!(
            value(&Value::Int(i64::MIN), IecType::Lint, &hex),
            "16#8000_0000_0000_0000"
        );
        // What they print reads back as the same bits.
        assert_eq!(Value::parse("16#00FF", IecType::Word), Ok(Value::UInt(255)));
        assert_eq!(
            Value::parse("2#0000_0000_1111_1111", IecType::Word),
            Ok(Value::UInt(255))
        );
    }

    #[test]
    fn hex_and_bin_leave_other_kinds_alone() {
        let hex = radix(Radix::Hex);
        assert_eq!(value(&Value::Bool(true), IecType::Bool, &hex), "true");
        assert_eq!(value(&Value::Real(255.0), IecType::Lreal, &hex), "255.0");
        assert_eq!(value(&text("ff"), IecType::String, &hex), "ff");
        let time = Value::Time(plc_core::Time::from_secs(90));
        assert_eq!(value(&time, IecType::Ltime, &hex), "LTIME#1m30s");
        assert_eq!(value(&Value::Int(-4), IecType::Int, &FULL), "-4");
    }

    #[test]
    fn control_characters_and_backslashes_are_escaped() {
        assert_eq!(escape_text("a\nb\tc\r"), "a\\nb\\tc\\r");
        assert_eq!(escape_text("\x1b[2J"), "\\x1b[2J");
        assert_eq!(escape_text("\u{7f}\u{9b}"), "\\x7f\\u{9b}");
        assert_eq!(escape_text("C:\\temp\\n"), "C:\\\\temp\\\\n");
        assert_eq!(escape_text("abc\u{202e}"), "abc\\u{202e}");
        assert_eq!(escape_text("Zugfestigkeit µm ✓"), "Zugfestigkeit µm ✓");
        assert_eq!(
            value(&text("\x1b]0;pwned\x07"), IecType::String, &FULL),
            "\\x1b]0;pwned\\x07"
        );
    }

    #[test]
    fn csv_text_that_a_spreadsheet_would_run_stays_text() {
        assert_eq!(csv_cell("=1+1", true), "\"'=1+1\"");
        assert_eq!(csv_cell("@SUM(A1:A9)", true), "\"'@SUM(A1:A9)\"");
        assert_eq!(csv_cell("-x", true), "\"'-x\"");
        assert_eq!(csv_cell("+1", true), "\"'+1\"");
        assert_eq!(
            csv_cell("=HYPERLINK(\"x\")", true),
            "\"'=HYPERLINK(\"\"x\"\")\""
        );
        // Numbers stay numbers; text elsewhere is quoted only when RFC 4180 needs it.
        assert_eq!(csv_cell("-1.5", false), "-1.5");
        assert_eq!(csv_cell("plain", true), "plain");
        assert_eq!(csv_cell("steel, S235", true), "\"steel, S235\"");
        assert_eq!(csv_cell("[0, -4, 0]", false), "\"[0, -4, 0]\"");
        // A CSV text cell's control characters were escaped by `value`.
        let shown = value(&text("a\nb\x1b"), IecType::String, &FULL);
        assert_eq!(csv_cell(&shown, true), "a\\nb\\x1b");
    }

    #[test]
    fn times_read_as_seconds_for_a_person_and_as_literals_otherwise() {
        use plc_core::Time;
        let elapsed = Value::Time(Time::from_nanos(4_340_004_953));
        let person = |digits| Format {
            digits,
            seconds: true,
            ..FULL
        };
        assert_eq!(value(&elapsed, IecType::Ltime, &person(Some(4))), "4.34 s");
        assert_eq!(value(&elapsed, IecType::Ltime, &person(Some(6))), "4.34 s");
        assert_eq!(
            value(&elapsed, IecType::Ltime, &person(None)),
            "4.340004953 s"
        );
        let whole = Value::Time(Time::from_secs(90));
        assert_eq!(value(&whole, IecType::Ltime, &person(None)), "90.0 s");
        let before = Value::Time(Time::from_millis(-1500));
        assert_eq!(value(&before, IecType::Ltime, &person(Some(3))), "-1.5 s");
        assert_eq!(
            value(&elapsed, IecType::Ltime, &FULL),
            "LTIME#4s340ms4us953ns"
        );
    }
}
