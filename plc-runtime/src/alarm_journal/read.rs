//! Reading a journal's bytes: every line checked on its own, so a damaged one is reported
//! (which, where, why) and the others still read, and a last line without its newline (a
//! write cut short by a crash) is reported as torn and never taken for a record.

use super::frame::{Item, decode};
use super::record::Record;
use super::replay;
use plc_core::alarm::Snapshot;
use std::collections::BTreeMap;
use std::fmt;

/// A line that is no record: which line, where in the file, and why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Damage {
    /// Its line number, from 1.
    pub line: usize,
    /// Its first byte's offset in the file.
    pub offset: u64,
    /// Its length in bytes, without the newline.
    pub len: usize,
    /// The number (`seq`) of the last whole record before it, if any: the damaged one was
    /// most likely the next.
    pub after: Option<u64>,
    /// What is wrong with it.
    pub why: String,
}

impl fmt::Display for Damage {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "line {} (byte {}, {} bytes",
            self.line, self.offset, self.len
        )?;
        if let Some(seq) = self.after {
            write!(f, ", after record #{seq}")?;
        }
        write!(f, ") is damaged: {}", self.why)
    }
}

/// The end of a file that is not a whole line: a write a crash cut short. It is no record.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Torn {
    /// Its first byte's offset in the file.
    pub offset: u64,
    /// Its length in bytes.
    pub len: usize,
}

/// One line as read: where it is and what it holds.
pub(super) struct Line {
    pub offset: u64,
    pub len: usize,
    pub item: Result<Item, String>,
}

/// Splits `bytes` into checked lines, and the torn end if the last has no newline. Each step
/// moves past at least one byte, so the loop ends on any input.
pub(super) fn lines(bytes: &[u8]) -> (Vec<Line>, Option<Torn>) {
    let mut out = Vec::new();
    let mut start = 0;
    while start < bytes.len() {
        let Some(n) = bytes[start..].iter().position(|&b| b == b'\n') else {
            let torn = Torn {
                offset: start as u64,
                len: bytes.len() - start,
            };
            return (out, Some(torn));
        };
        out.push(Line {
            offset: start as u64,
            len: n,
            item: decode(&bytes[start..start + n]),
        });
        start += n + 1;
    }
    (out, None)
}

/// What a journal holds: its last records (at most its capacity), how many older ones were
/// dropped, the state of every alarm it names, and what was damaged.
///
/// ```
/// use plc_runtime::alarm_journal::Contents;
/// let c = Contents::from_bytes(b"", 10_000);
/// assert_eq!((c.records().len(), c.dropped()), (0, 0));
/// assert!(c.damage().is_empty() && c.torn().is_none());
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Contents {
    records: Vec<Record>,
    dropped: u64,
    damage: Vec<Damage>,
    torn: Option<Torn>,
    states: BTreeMap<String, Snapshot>,
    next_seq: u64,
    records_in_file: usize,
}

impl Contents {
    /// Reads a journal's bytes; `capacity` the records it keeps (older ones count as
    /// dropped, as the next compaction will drop them). Any bytes give an answer, never a
    /// panic: what is not a record is reported in [`damage`](Self::damage) or
    /// [`torn`](Self::torn).
    pub fn from_bytes(bytes: &[u8], capacity: usize) -> Contents {
        let (lines, torn) = lines(bytes);
        let mut c = Contents {
            torn,
            next_seq: 1,
            ..Contents::default()
        };
        for (i, line) in lines.into_iter().enumerate() {
            match line.item {
                // Only the first line says what was dropped before it; one further on was
                // copied there by hand, and counting it would invent drops.
                Ok(Item::Header { dropped }) if i == 0 => c.dropped = dropped,
                Ok(Item::Header { .. }) => c.damage.push(Damage {
                    line: i + 1,
                    offset: line.offset,
                    len: line.len,
                    after: c.records.last().map(|r| r.seq),
                    why: "a header that is not the first line".into(),
                }),
                Ok(Item::State { path, state }) => {
                    c.states.insert(path, state);
                }
                Ok(Item::Record(r)) => {
                    replay::apply(&mut c.states, &r);
                    c.next_seq = c.next_seq.max(r.seq.saturating_add(1));
                    c.records.push(r);
                }
                Err(why) => c.damage.push(Damage {
                    line: i + 1,
                    offset: line.offset,
                    len: line.len,
                    after: c.records.last().map(|r| r.seq),
                    why,
                }),
            }
        }
        c.records_in_file = c.records.len();
        if c.records.len() > capacity {
            let excess = c.records.len() - capacity;
            c.records.drain(..excess);
            c.dropped = c.dropped.saturating_add(excess as u64);
        }
        c
    }

    /// The records kept, oldest first.
    pub fn records(&self) -> &[Record] {
        &self.records
    }

    /// The records from `since_ns` (UTC nanoseconds) on, oldest first: what
    /// `plc alarms --history --since T` shows.
    ///
    /// ```
    /// use plc_runtime::alarm_journal::Contents;
    /// let c = Contents::from_bytes(b"", 100);
    /// assert_eq!(c.history(Some(0)).count(), 0);
    /// ```
    pub fn history(&self, since_ns: Option<i64>) -> impl Iterator<Item = &Record> + '_ {
        let since = since_ns.unwrap_or(i64::MIN);
        // Every record looked at: the wall clock can be set back, so times in the file need
        // not be in order (the records are, by `seq`).
        self.records.iter().filter(move |r| r.time_ns >= since)
    }

    /// Records dropped by the bound, oldest first, in all the journal's history.
    pub fn dropped(&self) -> u64 {
        self.dropped
    }

    /// The lines that are no record.
    pub fn damage(&self) -> &[Damage] {
        &self.damage
    }

    /// The torn end of the file, if a write was cut short.
    pub fn torn(&self) -> Option<Torn> {
        self.torn
    }

    /// Each alarm's last state by path, for [`restore`](super::restore): older records than
    /// those kept count too, through the states a compaction wrote.
    pub fn states(&self) -> &BTreeMap<String, Snapshot> {
        &self.states
    }

    /// The sequence number the next record gets.
    pub fn next_seq(&self) -> u64 {
        self.next_seq
    }

    /// Records in the file, with those over the capacity that a compaction will drop.
    pub(super) fn records_in_file(&self) -> usize {
        self.records_in_file
    }

    /// Logs what is damaged or torn (target `plc_runtime::alarm_journal`), naming `file`.
    pub fn log(&self, file: &std::path::Path) {
        for d in &self.damage {
            log::warn!(target: "plc_runtime::alarm_journal",
                "alarm journal {}: {d}; it is skipped, the other records are read",
                file.display());
        }
        if let Some(t) = self.torn {
            log::warn!(target: "plc_runtime::alarm_journal",
                "alarm journal {}: the last {} bytes (from byte {}) are a record cut short by a \
                 crash; they were dropped",
                file.display(), t.len, t.offset);
        }
    }
}
