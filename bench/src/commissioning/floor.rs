//! The least any implementation can make a cycle pay for forces and a trace: the values'
//! bytes moved at offsets known in advance, with no lookup, no check and no ring. Measured
//! beside the real steps so the cost figures can be read against what is possible at all on
//! this machine: a force must be stored twice a cycle (at both boundaries) and a traced value
//! loaded and stored once, whatever the code around it.

use super::super::timing::median_per_iter;
use std::hint::black_box;
use std::time::Duration;

/// A basic value's place in the image: byte offset and size (at most 8 bytes is all a force
/// or trace of a number or BOOL moves).
pub type Place = (usize, usize);

/// `forced` stored into `image` twice (the cycle's two boundaries), each as one 8-byte
/// read-modify-write with a mask where 8 bytes follow it (the cheapest store of a 1 to 8 byte
/// value at an arbitrary offset), per application of the pair.
pub fn forces(image: &mut [u8], forced: &[Place], batches: usize, iters: u32) -> Duration {
    let held: Vec<(usize, u64, u64)> = forced
        .iter()
        .filter(|&&(offset, _)| offset + 8 <= image.len())
        .map(|&(offset, size)| {
            let mask = u64::MAX >> (64 - 8 * size.clamp(1, 8));
            (offset, mask, word(image, offset) & mask)
        })
        .collect();
    median_per_iter(batches, iters, || {
        let image = black_box(&mut *image);
        for _ in 0..2 {
            for &(offset, mask, bits) in &held {
                let w = (word(image, offset) & !mask) | bits;
                image[offset..offset + 8].copy_from_slice(&w.to_le_bytes());
            }
        }
    })
}

/// `traced` gathered from `image` into one row of words that stays in the cache (a ring
/// can only add to this: its rows are new memory).
pub fn trace(image: &[u8], traced: &[Place], batches: usize, iters: u32) -> Duration {
    let slots: Vec<(usize, u64)> = traced
        .iter()
        .filter(|&&(offset, _)| offset + 8 <= image.len())
        .map(|&(offset, size)| (offset, u64::MAX >> (64 - 8 * size.clamp(1, 8))))
        .collect();
    let mut row = vec![0u64; slots.len()];
    median_per_iter(batches, iters, || {
        let image = black_box(image);
        for (out, &(offset, mask)) in row.iter_mut().zip(&slots) {
            *out = word(image, offset) & mask;
        }
        black_box(&mut row);
    })
}

fn word(image: &[u8], offset: usize) -> u64 {
    let mut w = [0u8; 8];
    w.copy_from_slice(&image[offset..offset + 8]);
    u64::from_le_bytes(w)
}
