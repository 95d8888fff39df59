//! Traces, as TwinCAT Scope and CODESYS Trace record: the owner's cycle writes the values a tool
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

use super::ShmError;
use super::layout::Base;
use super::memfd::Mapping;
use super::paths::PathLocation;
use plc_core::{IecType, TypeFamily, Value, VarInfo};
use std::os::fd::OwnedFd;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering, fence};

const MAGIC: u64 = u64::from_le_bytes(*b"PLCTRACE");
const T_COLUMNS: usize = 8;
const T_CAPACITY: usize = 16;
const T_EVERY: usize = 24;
const T_HEAD: usize = 32;
const T_ENDED: usize = 40;
const ROWS: usize = 64;
/// Words of a row before its values: stamp, cycle, time.
const ROW_HEAD: usize = 3;

/// Rows a ring holds: two seconds of the program's rows, at least 1,024 and at most 16,384
/// (8.8 MB at 64 values). The tool drains it every few milliseconds; two seconds let it be
/// descheduled, swapped in or written to a slow disk without losing a row.
fn capacity(period_ns: u64, every: u32) -> u64 {
    let row_ns = period_ns.max(1).saturating_mul(u64::from(every));
    (2_000_000_000 / row_ns).clamp(1024, 16_384)
}

fn stride(columns: usize) -> usize {
    8 * (ROW_HEAD + columns)
}

/// A trace as the owner's cycle writes it.
pub(crate) struct Recording {
    /// Kept mapped while the cycle writes.
    _mapping: Mapping,
    base: Base,
    /// Where each column's value is in the image, and which of the 8 bytes read there are
    /// its own.
    slots: Vec<Slot>,
    every: u32,
    /// Cycles to skip before the next row.
    countdown: u32,
    capacity: u64,
    next: u64,
    /// Set by the connection's thread when the tool leaves: the cycle drops the trace.
    pub left: Arc<AtomicBool>,
}

impl Recording {
    /// A ring for `values` of `vars` (each a basic value of at most 8 bytes: no STRING), and
    /// the descriptor to pass to the tool; or which value was refused and why.
    pub fn create(
        name: &str,
        vars: &'static [VarInfo],
        values: &[(usize, usize)],
        every: u32,
        period_ns: u64,
    ) -> Result<(Recording, OwnedFd), (usize, String)> {
        let mut slots = Vec::with_capacity(values.len());
        for (k, &(index, leaf)) in values.iter().enumerate() {
            let Some(found) = plc_rules::path::leaf(vars, index, leaf) else {
                return Err((k, format!("no value {index}/{leaf}: the program has none")));
            };
            let var = found.node;
            if var.iec_type == IecType::String {
                return Err((
                    k,
                    format!(
                        "`{}` is a STRING: a trace records numbers, BOOLs and times",
                        super::forces::path_of(vars, index, leaf)
                    ),
                ));
            }
            slots.push(Slot::new(found.offset, var.element_size()));
        }
        let capacity = capacity(period_ns, every);
        let len = ROWS + capacity as usize * stride(values.len());
        let mapping = Mapping::create(&format!("{name}.trace"), len)
            .map_err(|e| (0, format!("no memory for the trace: {e}")))?;
        let base = mapping.base();
        base.store(T_COLUMNS, values.len() as u64);
        base.store(T_CAPACITY, capacity);
        base.store(T_EVERY, u64::from(every));
        base.store(0, MAGIC);
        let fd = mapping
            .fd()
            .try_clone()
            .map_err(|e| (0, format!("the trace cannot be passed on: {e}")))?;
        Ok((
            Recording {
                _mapping: mapping,
                base,
                slots,
                every,
                countdown: 0,
                capacity,
                next: 0,
                left: Arc::default(),
            },
            fd,
        ))
    }

    /// Writes this cycle's row, if it is one of the rows asked for.
    #[inline]
    pub fn record(&mut self, image: &[u8], cycle: u64, time_ns: u64) {
        if self.countdown > 0 {
            self.countdown -= 1;
            return;
        }
        self.countdown = self.every - 1;
        let k = self.next;
        let at = ROWS + (k % self.capacity) as usize * stride(self.slots.len());
        let b = &self.base;
        let row = b.words(at, ROW_HEAD + self.slots.len());
        let (head, values) = row.split_at(ROW_HEAD);
        head[0].store(2 * k + 1, Ordering::Relaxed);
        fence(Ordering::Release);
        head[1].store(cycle, Ordering::Relaxed);
        head[2].store(time_ns, Ordering::Relaxed);
        for (word, slot) in values.iter().zip(&self.slots) {
            word.store(slot.read(image), Ordering::Relaxed);
        }
        head[0].store(2 * k + 2, Ordering::Release);
        self.next = k + 1;
        b.store(T_HEAD, k + 1);
    }

    /// Tells the tool no more rows come (the program stops).
    pub fn end(&self) {
        self.base.store(T_ENDED, 1);
    }
}

/// Where a column's value is in the image.
#[derive(Clone, Copy, Debug)]
struct Slot {
    offset: usize,
    /// The value's bytes (at most 8) in a little-endian word.
    mask: u64,
    size: usize,
}

impl Slot {
    fn new(offset: usize, size: usize) -> Slot {
        let size = size.min(8);
        Slot {
            offset,
            mask: u64::MAX >> (64 - 8 * size.max(1)),
            size,
        }
    }

    /// The value as a little-endian word. One 8-byte load and a mask where the image has 8
    /// bytes from the value on (all but the last few values): a copy of the value's own length
    /// would be a call to `memcpy` for each column, most of a row's cost.
    #[inline]
    fn read(&self, image: &[u8]) -> u64 {
        match image
            .get(self.offset..)
            .and_then(|rest| rest.first_chunk::<8>())
        {
            Some(word) => u64::from_le_bytes(*word) & self.mask,
            None => {
                let mut w = [0u8; 8];
                let end = self.offset.saturating_add(self.size);
                if let Some(bytes) = image.get(self.offset..end) {
                    w[..self.size].copy_from_slice(bytes);
                }
                u64::from_le_bytes(w)
            }
        }
    }
}

/// What a drain finds, in order.
#[derive(Clone, Debug, PartialEq)]
pub enum TraceEvent {
    /// One recorded cycle.
    Row(TraceRow),
    /// Rows the owner wrote over before the tool read them (it fell behind): how many.
    Lost(u64),
}

/// One recorded cycle.
#[derive(Clone, Debug, PartialEq)]
pub struct TraceRow {
    /// The cycle's number (the status block's cycle count when it ran).
    pub cycle: u64,
    /// The cycle's time: nanoseconds since the program started, as `Context::now`.
    pub time_ns: u64,
    /// The values, in the order the trace was asked for.
    pub values: Vec<Value>,
}

/// A trace as a tool reads it: from [`DynSegment::trace`](super::DynSegment::trace). The owner
/// records while the segment's connection is open.
pub struct Trace {
    _mapping: Mapping,
    base: Base,
    types: Vec<IecType>,
    capacity: u64,
    next: u64,
}

/// The largest ring a tool maps: 16,384 rows of 64 values and the header.
const MAX_RING: usize = ROWS + 16_384 * 8 * (ROW_HEAD + 64);

impl Trace {
    /// Maps the ring the owner passed for `values`, checking what it says of itself.
    pub(crate) fn receive(
        name: &str,
        fd: OwnedFd,
        values: &[PathLocation],
    ) -> Result<Trace, ShmError> {
        let corrupt = |why: String| ShmError::Corrupt {
            name: name.to_string(),
            why: format!("its trace: {why}"),
        };
        let mapping = Mapping::receive(fd, MAX_RING).map_err(|e| corrupt(e.to_string()))?;
        let base = mapping.base();
        if base.len() < ROWS || base.load(0) != MAGIC {
            return Err(corrupt("not a trace ring".into()));
        }
        let columns = base.load(T_COLUMNS);
        let capacity = base.load(T_CAPACITY);
        if columns != values.len() as u64 {
            return Err(corrupt(format!("{columns} columns, not {}", values.len())));
        }
        let needed = (capacity as usize)
            .checked_mul(stride(values.len()))
            .and_then(|n| n.checked_add(ROWS));
        if capacity == 0 || needed.is_none_or(|n| n > base.len()) {
            return Err(corrupt(format!(
                "{capacity} rows do not fit its {} bytes",
                base.len()
            )));
        }
        Ok(Trace {
            _mapping: mapping,
            base,
            types: values.iter().map(|v| v.var.iec_type).collect(),
            capacity,
            next: 0,
        })
    }

    /// Rows the ring holds (how far the tool may fall behind without losing one).
    pub fn capacity(&self) -> u64 {
        self.capacity
    }

    /// Whether the owner stopped: no more rows come once these are drained.
    pub fn ended(&self) -> bool {
        self.base.load(T_ENDED) != 0
    }

    /// Appends every row written since the last drain to `out` (at most `max` rows), with a
    /// [`TraceEvent::Lost`] where rows were written over before they were read. Returns how
    /// many events it appended.
    pub fn drain(&mut self, out: &mut Vec<TraceEvent>, max: usize) -> usize {
        let before = out.len();
        let head = self.base.load(T_HEAD);
        let stride = stride(self.types.len());
        while self.next < head && out.len() - before < max {
            // Rows older than the ring's length are gone already.
            let oldest = head.saturating_sub(self.capacity);
            if self.next < oldest {
                out.push(TraceEvent::Lost(oldest - self.next));
                self.next = oldest;
                continue;
            }
            let k = self.next;
            let at = ROWS + (k % self.capacity) as usize * stride;
            let want = 2 * k + 2;
            let stamp = self.base.word(at);
            if stamp.load(Ordering::Acquire) != want {
                // Written over since `head` was read: lost, as below.
                out.push(TraceEvent::Lost(1));
                self.next += 1;
                continue;
            }
            let word = |n: usize| self.base.word(at + 8 * n).load(Ordering::Relaxed);
            let (cycle, time_ns) = (word(1), word(2));
            let values = self
                .types
                .iter()
                .enumerate()
                .map(|(j, &t)| decode(word(ROW_HEAD + j), t))
                .collect();
            fence(Ordering::Acquire);
            self.next += 1;
            if stamp.load(Ordering::Relaxed) != want {
                out.push(TraceEvent::Lost(1));
                continue;
            }
            out.push(TraceEvent::Row(TraceRow {
                cycle,
                time_ns,
                values,
            }));
        }
        // Lost rows that follow each other count as one gap.
        merge_losses(out, before);
        out.len() - before
    }
}

/// Folds runs of `Lost` events from `from` on into one.
fn merge_losses(out: &mut Vec<TraceEvent>, from: usize) {
    let mut k = from + 1;
    while k < out.len() {
        if let (TraceEvent::Lost(a), TraceEvent::Lost(b)) = (&out[k - 1], &out[k]) {
            let n = a + b;
            out[k - 1] = TraceEvent::Lost(n);
            out.remove(k);
        } else {
            k += 1;
        }
    }
}

/// A column's word as its type's value (a BOOL is any non-zero byte).
fn decode(word: u64, t: IecType) -> Value {
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

    #[test]
    fn a_column_reads_its_own_bytes_only_wherever_it_is() {
        let image: Vec<u8> = (1..=20).collect();
        // In the middle: the 8-byte load, masked.
        assert_eq!(Slot::new(2, 1).read(&image), 3);
        assert_eq!(Slot::new(2, 2).read(&image), 0x0403);
        assert_eq!(Slot::new(4, 4).read(&image), 0x0807_0605);
        assert_eq!(Slot::new(0, 8).read(&image), 0x0807_0605_0403_0201);
        // At the end, fewer than 8 bytes follow: copied.
        assert_eq!(Slot::new(19, 1).read(&image), 20);
        assert_eq!(Slot::new(16, 4).read(&image), 0x1413_1211);
        assert_eq!(Slot::new(12, 8).read(&image), 0x1413_1211_100f_0e0d);
        // Beyond the image (not made by `create`): zero, never a panic.
        assert_eq!(Slot::new(18, 4).read(&image), 0);
        assert_eq!(Slot::new(usize::MAX, 8).read(&image), 0);
    }

    #[test]
    fn runs_of_losses_are_one_gap() {
        let row = TraceEvent::Row(TraceRow {
            cycle: 1,
            time_ns: 0,
            values: vec![],
        });
        let mut out = vec![
            TraceEvent::Lost(1),
            TraceEvent::Lost(2),
            row.clone(),
            TraceEvent::Lost(4),
        ];
        merge_losses(&mut out, 0);
        assert_eq!(out, vec![TraceEvent::Lost(3), row, TraceEvent::Lost(4)]);
    }
}
