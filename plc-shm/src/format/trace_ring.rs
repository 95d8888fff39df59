//! A trace's ring, as TwinCAT Scope and CODESYS Trace record: the owner's cycle writes the values a tool
//! asked for into a ring of rows, every cycle (or every Nth), and the tool drains it. A tool at
//! normal priority cannot sample every cycle of a 4 kHz program by polling; it can drain a ring
//! a few times a second. The ring is a sealed memory file of its own, made by the server's
//! thread when the tool asks and passed to it with the answer, so a trace costs the segment
//! nothing and ends when the tool's connection does.
//!
//! ```text
//! 0    magic "PLCTRACE", columns, capacity (rows), every (cycles), head (rows written),
//!      ended (1 once the owner stopped), 2 words unused                (8 x u64)
//! 64   rows, `capacity` of them, each: stamp, cycle, time (ns since the program started),
//!      then one word per column (the value's image bytes, little endian) (3 + columns) x u64
//! ```
//! Row `k` (counting from 0) lives in slot `k % capacity`; its stamp is `2k + 1` while the
//! owner writes it and `2k + 2` once written. A reader that finds another stamp, before or
//! after copying the row, knows the owner has written over it: those rows are lost, and said
//! to be, never skipped in silence.

use crate::limits::{MAX_TRACE_ROWS, MAX_TRACED, MIN_TRACE_ROWS};
use plc_core::{IecType, TypeFamily, Value};

/// The ring's first word: "PLCTRACE".
pub const MAGIC: u64 = u64::from_le_bytes(*b"PLCTRACE");
/// Where the ring's header words are.
pub const T_COLUMNS: usize = 8;
/// Rows the ring holds.
pub const T_CAPACITY: usize = 16;
/// Cycles between rows.
pub const T_EVERY: usize = 24;
/// Rows written so far.
pub const T_HEAD: usize = 32;
/// 1 once the owner stopped.
pub const T_ENDED: usize = 40;
/// Where the rows start: after the header's 8 words.
pub const ROWS: usize = 64;
/// Words of a row before its values: stamp, cycle, time.
pub const ROW_HEAD: usize = 3;
/// The largest ring a tool maps: [`MAX_TRACE_ROWS`] rows of [`MAX_TRACED`] values and the
/// header.
pub const MAX_RING: usize = ROWS + MAX_TRACE_ROWS as usize * 8 * (ROW_HEAD + MAX_TRACED);

/// Rows a ring holds: two seconds of the program's rows, at least [`MIN_TRACE_ROWS`] and at
/// most [`MAX_TRACE_ROWS`]. The tool drains it every few milliseconds; two seconds let it be
/// descheduled, swapped in or written to a slow disk without losing a row.
pub fn capacity(period_ns: u64, every: u32) -> u64 {
    let row_ns = period_ns.max(1).saturating_mul(u64::from(every));
    (2_000_000_000 / row_ns).clamp(MIN_TRACE_ROWS, MAX_TRACE_ROWS)
}

/// Bytes of a row of `columns` values.
pub fn stride(columns: usize) -> usize {
    8 * (ROW_HEAD + columns)
}

/// Where row `k` lives in a ring of `capacity` rows of `columns` values.
pub fn row_at(k: u64, capacity: u64, columns: usize) -> usize {
    ROWS + (k % capacity) as usize * stride(columns)
}

/// A column's word as its type's value (a BOOL is any non-zero byte).
pub fn decode(word: u64, t: IecType) -> Value {
    match t.family() {
        TypeFamily::Bool => Value::Bool(word & 0xff != 0),
        _ => Value::from_raw_bits(word, t, t.bits()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rings_hold_two_seconds_within_bounds() {
        assert_eq!(capacity(1_000_000, 1), 2000);
        assert_eq!(capacity(250_000, 1), 8000);
        assert_eq!(capacity(10_000_000, 1), 1024);
        assert_eq!(capacity(10_000, 1), 16_384);
        assert_eq!(capacity(0, 1), 16_384);
    }
}
