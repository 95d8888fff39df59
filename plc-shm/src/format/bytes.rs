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
//!
//! On x86-64 both copies are one string move of quadwords (`rep movsq`, the width every
//! process uses), which the processor performs a cache line at a time, at `memcpy`'s speed:
//! the owner's publish of a 4.5 KB image, once per cycle, takes about 30 ns against about 75 ns
//! for the loop (the repository's BENCHMARKS.md, "The runtime's cycle"), and a tool's snapshot likewise.

use crate::sys::base::Base;
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
    load_words(words, chunks);
    for (b, src) in rest.iter_mut().zip(tail) {
        *b = src.load(Relaxed);
    }
}

/// `chunks[i] = words[i]` (little endian), each word with a relaxed atomic load.
#[cfg(not(target_arch = "x86_64"))]
#[inline]
fn load_words(words: &[AtomicU64], chunks: &mut [[u8; 8]]) {
    for (chunk, word) in chunks.iter_mut().zip(words) {
        *chunk = word.load(Relaxed).to_le_bytes();
    }
}

/// `chunks[i] = words[i]`: the loop of relaxed word loads as one string move, by the argument
/// of [`store_words`]: each quadword read from `words` is an aligned 8-byte load (atomic on
/// x86-64), relaxed loads of different words promise no order among themselves, and the
/// `lfence` on each side keeps them after the loads before (the seqlock's first counter read)
/// and ahead of the loads after (its second).
#[cfg(target_arch = "x86_64")]
#[inline]
fn load_words(words: &[AtomicU64], chunks: &mut [[u8; 8]]) {
    let n = words.len().min(chunks.len());
    if n == 0 {
        return;
    }
    // SAFETY: `rep movsq` reads `n` quadwords from `words` (8-aligned, an `AtomicU64` slice)
    // and writes `n` into `chunks`, both live and at least `n` long, and touches nothing
    // else; the loads are relaxed word loads by the argument above. rsi, rdi and rcx are
    // declared clobbered; no stack, flags unchanged.
    unsafe {
        std::arch::asm!(
            "lfence",
            "rep movsq",
            "lfence",
            inout("rsi") words.as_ptr() => _,
            inout("rdi") chunks.as_mut_ptr() => _,
            inout("rcx") n => _,
            options(nostack, preserves_flags),
        );
    }
}

/// Writes `data` at `offset` (8-aligned) with relaxed atomic stores.
#[inline]
pub fn store(base: &Base, offset: usize, data: &[u8]) {
    let (chunks, rest) = data.as_chunks::<8>();
    let (words, tail) = region(base, offset, chunks.len(), rest.len());
    store_words(words, chunks);
    for (b, dst) in rest.iter().zip(tail) {
        dst.store(*b, Relaxed);
    }
}

/// `words[i] = chunks[i]` (little endian), each word with a relaxed atomic store.
#[cfg(not(target_arch = "x86_64"))]
#[inline]
fn store_words(words: &[AtomicU64], chunks: &[[u8; 8]]) {
    for (chunk, word) in chunks.iter().zip(words) {
        word.store(u64::from_le_bytes(*chunk), Relaxed);
    }
}

/// `words[i] = chunks[i]`: what the loop of relaxed word stores does, as one string move.
///
/// Why this is the same operation: each quadword of `rep movsq` is an aligned 8-byte store,
/// which x86-64 performs atomically (a fast string writes whole cache lines, and no aligned
/// quadword straddles one), and relaxed stores to different words promise no order among
/// themselves, which is the one freedom a string move takes (its stores may become visible
/// out of order). The order that matters, these stores after the seqlock's odd counter and
/// before its even one, is what the `sfence` on each side gives: the processor's manuals
/// exempt string stores from the usual store order, and a fence orders every store before
/// it ahead of every store after it. The direction flag is clear on entry to inline assembly
/// (Rust's rule), so the move goes upwards.
#[cfg(target_arch = "x86_64")]
#[inline]
fn store_words(words: &[AtomicU64], chunks: &[[u8; 8]]) {
    let n = words.len().min(chunks.len());
    if n == 0 {
        return;
    }
    // SAFETY: `rep movsq` reads `n` quadwords from `chunks` and writes `n` to `words`, both
    // live slices at least `n` long (the `min` above), and touches nothing else; `words` is
    // 8-aligned (an `AtomicU64` slice). The stores are relaxed word stores by the argument
    // above. rsi, rdi and rcx are declared clobbered; no stack, flags unchanged.
    unsafe {
        std::arch::asm!(
            "sfence",
            "rep movsq",
            "sfence",
            inout("rsi") chunks.as_ptr() => _,
            inout("rdi") words.as_ptr() => _,
            inout("rcx") n => _,
            options(nostack, preserves_flags),
        );
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
