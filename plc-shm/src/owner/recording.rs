//! A trace as the owner's cycle records it: the ring made on the server's thread when a tool
//! asks (and passed to it with the answer), one row written per recorded cycle.

use super::refused::Refused;
use crate::format::trace_ring::{
    self, MAGIC, ROW_HEAD, ROWS, T_CAPACITY, T_COLUMNS, T_ENDED, T_EVERY, T_HEAD,
};
use crate::naming::path_of;
use crate::sys::base::Base;
use crate::sys::memfd::Mapping;
use plc_core::{IecType, VarInfo};
use std::os::fd::OwnedFd;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering, fence};

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
    ) -> Result<(Recording, OwnedFd), Refused> {
        let mut slots = Vec::with_capacity(values.len());
        for (k, &(index, leaf)) in values.iter().enumerate() {
            let Some(found) = plc_rules::path::leaf(vars, index, leaf) else {
                return Err(Refused::rejected(
                    k,
                    format!("no value {index}/{leaf}: the program has none"),
                ));
            };
            let var = found.node;
            if var.iec_type == IecType::String {
                return Err(Refused::rejected(
                    k,
                    format!(
                        "`{}` is a STRING: a trace records numbers, BOOLs and times",
                        path_of(vars, index, leaf)
                    ),
                ));
            }
            slots.push(Slot::new(found.offset, var.element_size()));
        }
        let capacity = trace_ring::capacity(period_ns, every);
        let len = ROWS + capacity as usize * trace_ring::stride(values.len());
        let mapping = Mapping::create(&format!("{name}.trace"), len)
            .map_err(|e| Refused::rejected(0, format!("no memory for the trace: {e}")))?;
        let base = mapping.base();
        base.store(T_COLUMNS, values.len() as u64);
        base.store(T_CAPACITY, capacity);
        base.store(T_EVERY, u64::from(every));
        base.store(0, MAGIC);
        let fd = mapping
            .fd()
            .try_clone()
            .map_err(|e| Refused::rejected(0, format!("the trace cannot be passed on: {e}")))?;
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
        let at = trace_ring::row_at(k, self.capacity, self.slots.len());
        let b = &self.base;
        // One bounds check for the row, not one per value.
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

#[cfg(test)]
mod tests {
    use super::*;

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
}
