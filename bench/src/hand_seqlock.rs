//! The hand-written baseline's shared-memory side: the seqlock a careful user would write
//! without plc-vars (a sequence word, the image as relaxed atomic words, fences), so that
//! `cycle_1k_vs_handwritten` compares the same work on both sides: snapshot in, unpack, pack,
//! image out, publish. It has no owner liveness, heartbeat, generation or layout checks: those
//! are the framework's, and their cost is counted against it. The words live in process
//! memory; copying them costs the same in a shared mapping.

use std::sync::atomic::{AtomicU64, Ordering, fence};

/// A seqlock over `len` bytes.
pub struct HandSeqlock {
    seq: AtomicU64,
    words: Box<[AtomicU64]>,
}

impl HandSeqlock {
    /// A zeroed image of `len` bytes (`len` a multiple of 8, as the benchmark images are).
    pub fn new(len: usize) -> Self {
        assert!(len.is_multiple_of(8), "the baseline copies whole words");
        HandSeqlock {
            seq: AtomicU64::new(0),
            words: (0..len / 8).map(|_| AtomicU64::new(0)).collect(),
        }
    }

    /// Writes `image` under the seqlock (single writer).
    pub fn publish(&self, image: &[u8]) {
        let s = self.seq.load(Ordering::Relaxed);
        self.seq.store(s + 1, Ordering::Relaxed);
        fence(Ordering::Release);
        for (w, chunk) in self.words.iter().zip(image.as_chunks::<8>().0) {
            w.store(u64::from_le_bytes(*chunk), Ordering::Relaxed);
        }
        self.seq.store(s + 2, Ordering::Release);
    }

    /// Reads a consistent image into `out`, retrying while the writer writes.
    pub fn snapshot(&self, out: &mut [u8]) {
        loop {
            let s1 = self.seq.load(Ordering::Acquire);
            if s1.is_multiple_of(2) {
                for (chunk, w) in out.as_chunks_mut::<8>().0.iter_mut().zip(self.words.iter()) {
                    *chunk = w.load(Ordering::Relaxed).to_le_bytes();
                }
                fence(Ordering::Acquire);
                if self.seq.load(Ordering::Relaxed) == s1 {
                    return;
                }
            }
            std::hint::spin_loop();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_snapshot_returns_the_published_image() {
        let lock = HandSeqlock::new(24);
        let image: Vec<u8> = (1..=24).collect();
        lock.publish(&image);
        let mut out = vec![0u8; 24];
        lock.snapshot(&mut out);
        assert_eq!(out, image);
    }
}
