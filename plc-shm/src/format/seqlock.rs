//! The image's seqlock as a reader takes it: the sequence word is odd while the owner writes,
//! and a copy is good only if the word was even and unchanged around it.

use super::layout::H_SEQ;
use crate::error::ShmError;
use crate::sys::base::Base;
use std::sync::atomic::{Ordering, fence};
use std::time::{Duration, Instant};

/// How long a reader waits for a consistent image before it reports the owner stuck.
pub const SNAPSHOT_PATIENCE: Duration = Duration::from_millis(500);
/// Tries between looks at the clock (and yields of the thread).
const SPINS_PER_CHECK: u32 = 64;

/// Reads a consistent image of segment `name` with `read`, retrying while the owner writes;
/// after [`SNAPSHOT_PATIENCE`] asks `owner_ok` whether the owner is still there, and reports it
/// stuck if it is.
pub fn read<R>(
    base: &Base,
    name: &str,
    mut read: impl FnMut() -> R,
    owner_ok: impl Fn() -> Result<(), ShmError>,
) -> Result<R, ShmError> {
    let seq = base.word(H_SEQ);
    // The clock is read only once the owner made us wait: most snapshots succeed at once.
    let mut start = None;
    let mut spins = 0u32;
    loop {
        let s1 = seq.load(Ordering::Acquire);
        if s1.is_multiple_of(2) {
            let r = read();
            fence(Ordering::Acquire);
            if seq.load(Ordering::Relaxed) == s1 {
                return Ok(r);
            }
        }
        spins += 1;
        if spins.is_multiple_of(SPINS_PER_CHECK) {
            if start.get_or_insert_with(Instant::now).elapsed() > SNAPSHOT_PATIENCE {
                owner_ok()?;
                return Err(ShmError::Stuck(name.to_string()));
            }
            std::thread::yield_now();
        } else {
            std::hint::spin_loop();
        }
    }
}
