//! A trace as a tool reads it: the ring the owner passed with its answer, mapped read-only and
//! drained row by row. Row `k`'s stamp says whether the owner wrote over it before or while
//! the tool copied it: such rows are lost, and said to be, never skipped in silence.

use super::paths::PathLocation;
use crate::error::ShmError;
use crate::format::trace_ring::{
    self, MAGIC, MAX_RING, ROW_HEAD, ROWS, T_CAPACITY, T_COLUMNS, T_ENDED, T_HEAD,
};
use crate::sys::base::Base;
use crate::sys::memfd::Mapping;
use plc_core::{IecType, Value};
use std::os::fd::OwnedFd;
use std::sync::atomic::{Ordering, fence};

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

/// A trace as a tool reads it: from [`DynSegment::trace`](crate::DynSegment::trace). The owner
/// records while the segment's connection is open.
pub struct Trace {
    _mapping: Mapping,
    base: Base,
    types: Vec<IecType>,
    capacity: u64,
    next: u64,
}

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
            .checked_mul(trace_ring::stride(values.len()))
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
        while self.next < head && out.len() - before < max {
            // Rows older than the ring's length are gone already.
            let oldest = head.saturating_sub(self.capacity);
            if self.next < oldest {
                out.push(TraceEvent::Lost(oldest - self.next));
                self.next = oldest;
                continue;
            }
            let k = self.next;
            let at = trace_ring::row_at(k, self.capacity, self.types.len());
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
                .map(|(j, &t)| trace_ring::decode(word(ROW_HEAD + j), t))
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

#[cfg(test)]
mod tests {
    use super::*;

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
