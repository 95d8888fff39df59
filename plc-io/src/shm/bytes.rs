//! Copying byte ranges in and out of shared memory through atomics only: another process may
//! write the same bytes at any time, so plain loads and stores would be a data race. The
//! seqlock decides whether what was read is consistent.

use super::layout::Base;
use std::sync::atomic::{AtomicU8, Ordering::Relaxed};

fn byte(base: &Base, offset: usize) -> &AtomicU8 {
    assert!(offset < base.len());
    // SAFETY: in bounds (asserted); AtomicU8 has the layout of u8; the mapping outlives `base`.
    unsafe { &*(base.ptr().add(offset) as *const AtomicU8) }
}

/// Reads `out.len()` bytes at `offset` (8-aligned) with relaxed atomic loads.
pub fn load(base: &Base, offset: usize, out: &mut [u8]) {
    assert!(offset.is_multiple_of(8) && offset + out.len() <= base.len());
    let tail_start = offset + (out.len() / 8) * 8;
    let mut chunks = out.chunks_exact_mut(8);
    for (i, chunk) in chunks.by_ref().enumerate() {
        let v = base.word(offset + i * 8).load(Relaxed);
        chunk.copy_from_slice(&v.to_le_bytes());
    }
    for (i, b) in chunks.into_remainder().iter_mut().enumerate() {
        *b = byte(base, tail_start + i).load(Relaxed);
    }
}

/// Writes `data` at `offset` (8-aligned) with relaxed atomic stores.
pub fn store(base: &Base, offset: usize, data: &[u8]) {
    assert!(offset.is_multiple_of(8) && offset + data.len() <= base.len());
    let mut chunks = data.chunks_exact(8);
    for (i, chunk) in chunks.by_ref().enumerate() {
        let mut w = [0u8; 8];
        w.copy_from_slice(chunk);
        base.word(offset + i * 8)
            .store(u64::from_le_bytes(w), Relaxed);
    }
    let tail_start = offset + (data.len() / 8) * 8;
    for (i, b) in chunks.remainder().iter().enumerate() {
        byte(base, tail_start + i).store(*b, Relaxed);
    }
}
