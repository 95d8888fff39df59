//! Copying byte ranges in and out of shared memory through atomics only: another process may
//! write the same bytes at any time, so plain loads and stores would be a data race. The
//! seqlock decides whether what was read is consistent.
//!
//! Every process copies with the same granularity (8-byte words from an 8-aligned offset, then
//! single bytes for the tail), so concurrent accesses never mix atomic sizes. This is also why
//! the image does not go through `atomic-memcpy`: its granularity depends on the type's size
//! and alignment, while tools without the Rust type (`DynSegment`) copy the same bytes by
//! length. Relaxed word loads and stores compile to plain moves; the loop over one pre-checked
//! slice keeps the copy within a small factor of `memcpy`.

use super::layout::Base;
use std::sync::atomic::{AtomicU8, AtomicU64, Ordering::Relaxed};

/// The `n` words from `offset` (8-aligned) and the `tail` bytes after them, bounds checked once.
#[inline]
fn region(base: &Base, offset: usize, words: usize, tail: usize) -> (&[AtomicU64], &[AtomicU8]) {
    let end = offset + words * 8 + tail;
    assert!(
        offset.is_multiple_of(8) && end <= base.len(),
        "bytes {offset}..{end} outside segment"
    );
    // SAFETY: in bounds (asserted), 8-aligned (the mapping is page aligned and `offset` is a
    // multiple of 8); AtomicU64/AtomicU8 have the layout of u64/u8; the mapping outlives `base`
    // (contract of `Base::new`), and every process accesses these bytes only atomically.
    unsafe {
        let p = base.ptr().add(offset);
        (
            std::slice::from_raw_parts(p as *const AtomicU64, words),
            std::slice::from_raw_parts(p.add(words * 8) as *const AtomicU8, tail),
        )
    }
}

/// Reads `out.len()` bytes at `offset` (8-aligned) with relaxed atomic loads.
#[inline]
pub fn load(base: &Base, offset: usize, out: &mut [u8]) {
    let (chunks, rest) = out.as_chunks_mut::<8>();
    let (words, tail) = region(base, offset, chunks.len(), rest.len());
    for (chunk, word) in chunks.iter_mut().zip(words) {
        *chunk = word.load(Relaxed).to_le_bytes();
    }
    for (b, src) in rest.iter_mut().zip(tail) {
        *b = src.load(Relaxed);
    }
}

/// Writes `data` at `offset` (8-aligned) with relaxed atomic stores.
#[inline]
pub fn store(base: &Base, offset: usize, data: &[u8]) {
    let (chunks, rest) = data.as_chunks::<8>();
    let (words, tail) = region(base, offset, chunks.len(), rest.len());
    for (chunk, word) in chunks.iter().zip(words) {
        word.store(u64::from_le_bytes(*chunk), Relaxed);
    }
    for (b, dst) in rest.iter().zip(tail) {
        dst.store(*b, Relaxed);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn load_returns_what_store_wrote_for_every_length_and_tail() {
        let mut mem = vec![0u64; 16];
        // SAFETY: a live, 8-aligned allocation of 128 bytes used only through this Base.
        let base = unsafe { Base::new(mem.as_mut_ptr() as *mut u8, 128) };
        for len in 0..=120 {
            let data: Vec<u8> = (0..len)
                .map(|i| (i as u8).wrapping_mul(37) ^ len as u8)
                .collect();
            store(&base, 8, &data);
            let mut back = vec![0u8; len];
            load(&base, 8, &mut back);
            assert_eq!(back, data, "length {len}");
        }
    }

    #[test]
    #[should_panic(expected = "outside segment")]
    fn a_range_past_the_mapping_is_refused() {
        let mut mem = vec![0u64; 2];
        // SAFETY: as above, 16 bytes.
        let base = unsafe { Base::new(mem.as_mut_ptr() as *mut u8, 16) };
        load(&base, 8, &mut [0u8; 9]);
    }
}
