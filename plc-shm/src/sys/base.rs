//! A mapping's words, shared with other processes: every access is atomic, so no process
//! ever holds a plain reference into memory another process writes.

use std::sync::atomic::{AtomicU64, Ordering};

/// A mapped segment's base address; all access goes through atomics.
#[derive(Clone, Copy, Debug)]
pub struct Base {
    ptr: *mut u8,
    len: usize,
}

// SAFETY: `Base` is an address into a shared mapping that every user touches only through
// atomic operations; sending it to another thread is as safe as sharing the mapping itself.
unsafe impl Send for Base {}
// SAFETY: as above: no plain reads or writes are done through it.
unsafe impl Sync for Base {}

// Small and on every publish and snapshot, which are generic and so compiled in the user's
// crate: without `#[inline]` each of these would be a call across crates.
impl Base {
    /// # Safety
    /// `ptr` must point to a mapping of at least `len` bytes, 8-byte aligned, that stays mapped
    /// while this `Base` is used.
    pub unsafe fn new(ptr: *mut u8, len: usize) -> Self {
        Base { ptr, len }
    }

    #[inline]
    pub fn len(&self) -> usize {
        self.len
    }

    #[inline]
    pub fn ptr(&self) -> *mut u8 {
        self.ptr
    }

    /// The `u64` at `offset` as an atomic.
    #[inline]
    pub fn word(&self, offset: usize) -> &AtomicU64 {
        assert!(
            offset.is_multiple_of(8) && offset + 8 <= self.len,
            "word {offset} outside segment"
        );
        // SAFETY: in bounds and 8-aligned (checked above; the mapping is page aligned), and the
        // mapping outlives `self` (contract of `new`). AtomicU64 has the layout of u64, and
        // every process accesses these bytes only atomically.
        unsafe { &*(self.ptr.add(offset) as *const AtomicU64) }
    }

    /// The `count` words from `offset` as atomics: one bounds check for a whole row of a
    /// trace, where [`word`](Self::word) would check each.
    #[inline]
    pub fn words(&self, offset: usize, count: usize) -> &[AtomicU64] {
        assert!(
            offset.is_multiple_of(8)
                && count
                    .checked_mul(8)
                    .and_then(|n| n.checked_add(offset))
                    .is_some_and(|end| end <= self.len),
            "words {offset} (+{count}) outside segment"
        );
        // SAFETY: as in `word`, for each of the `count` words, all in bounds and 8-aligned
        // (checked above).
        unsafe { std::slice::from_raw_parts(self.ptr.add(offset) as *const AtomicU64, count) }
    }

    #[inline]
    pub fn load(&self, offset: usize) -> u64 {
        self.word(offset).load(Ordering::Acquire)
    }

    #[inline]
    pub fn store(&self, offset: usize, v: u64) {
        self.word(offset).store(v, Ordering::Release)
    }
}
