//! The table of forces in a segment: a sequence word (odd while the owner changes the table),
//! the count, then per force its variable index, leaf, uid and since when (UTC ns). The owner
//! stores it after each force or release; tools read it.

use super::layout::Offsets;
use crate::limits::MAX_FORCES;
use crate::sys::base::Base;
use std::sync::atomic::{Ordering, fence};

/// A force as tools read it from the segment; its value is the image's, which holds it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ForceInfo {
    /// Index of the top-level variable.
    pub index: usize,
    /// The basic value within it.
    pub leaf: usize,
    /// Who forced it.
    pub uid: u32,
    /// When, in nanoseconds since the Unix epoch (UTC).
    pub since_utc_ns: u64,
}

/// Stores `forces` under the table's own sequence word (odd while it changes).
pub fn store(base: &Base, off: &Offsets, forces: impl ExactSizeIterator<Item = ForceInfo>) {
    let seq = base.word(off.f_seq());
    let s = seq.load(Ordering::Relaxed);
    seq.store(s.wrapping_add(1), Ordering::Relaxed);
    fence(Ordering::Release);
    base.store(off.f_count(), forces.len() as u64);
    for (n, f) in forces.enumerate() {
        let words = [
            f.index as u64,
            f.leaf as u64,
            u64::from(f.uid),
            f.since_utc_ns,
        ];
        for (k, v) in words.into_iter().enumerate() {
            base.store(off.f_entry(n, k), v);
        }
    }
    seq.store(s.wrapping_add(2), Ordering::Release);
}

/// Reads the table of forces a segment holds, retrying while its owner changes it. The words
/// come from another process: the count is bounded and a table still changing after many tries
/// is reported as none rather than waited for.
pub fn read(base: &Base, off: &Offsets) -> Option<Vec<ForceInfo>> {
    let seq = base.word(off.f_seq());
    for _ in 0..1000 {
        let s1 = seq.load(Ordering::Acquire);
        if s1 % 2 == 1 {
            std::hint::spin_loop();
            continue;
        }
        let count = (base.load(off.f_count()) as usize).min(MAX_FORCES);
        let mut out = Vec::with_capacity(count);
        for n in 0..count {
            let w = |k| base.load(off.f_entry(n, k));
            out.push(ForceInfo {
                index: usize::try_from(w(0)).unwrap_or(usize::MAX),
                leaf: usize::try_from(w(1)).unwrap_or(usize::MAX),
                uid: u32::try_from(w(2)).unwrap_or(u32::MAX),
                since_utc_ns: w(3),
            });
        }
        fence(Ordering::Acquire);
        if seq.load(Ordering::Relaxed) == s1 {
            return Some(out);
        }
    }
    None
}
