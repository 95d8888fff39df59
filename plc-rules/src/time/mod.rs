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

mod convert;
mod display;
mod duration;
mod error;
mod parse;
mod unit;

pub use duration::Time;
pub use error::TimeError;

#[cfg(test)]
mod tests;
