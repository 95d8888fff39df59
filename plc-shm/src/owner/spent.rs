//! What the cycle thread is done with and leaves to the server's threads to free: a departed
//! tool's trace ring (unmapping 64 columns costs milliseconds) and a request's values (a
//! request of 1,024 values is some 280 KiB, and freeing it can give pages back to the kernel,
//! a system call). Only if the server's threads fell behind (the channel is full) is one freed
//! on the cycle thread.

use super::recording::Recording;
use plc_core::write::Checked;
use std::sync::atomic::Ordering;
use std::sync::mpsc::{Receiver, SyncSender};

/// Requests' values in the channel at most, besides the rings: the server's threads empty it
/// after every request, so more wait only while they are starved.
const VALUES_WAITING: usize = 16;

/// One thing to free.
pub(crate) enum Spent {
    /// A departed tool's trace.
    Ring(Recording),
    /// A request's values, applied or refused.
    Values(Vec<Checked>),
}

impl Spent {
    /// Frees it (on the server's threads).
    pub fn free(self) {
        match self {
            Spent::Ring(ring) => drop(ring),
            Spent::Values(values) => drop(values),
        }
    }
}

/// The cycle thread's end.
#[derive(Clone)]
pub(crate) struct SpentTx(SyncSender<Spent>);

impl SpentTx {
    /// A channel that holds every trace that can exist twice over, and [`VALUES_WAITING`]
    /// requests' values.
    pub fn channel(traces: usize) -> (SpentTx, Receiver<Spent>) {
        let (tx, rx) = std::sync::mpsc::sync_channel(2 * traces + VALUES_WAITING);
        (SpentTx(tx), rx)
    }

    /// Hands `spent` to the server's threads to free (or frees it here if they fell behind).
    #[inline]
    pub fn leave(&self, spent: Spent) {
        let _ = self.0.try_send(spent);
    }
}

/// Takes the traces whose tools left out of `recordings` and hands them to the server's
/// threads through `spent` to be freed: unmapping a ring of 64 columns costs milliseconds,
/// which the cycle must not spend. Only if they cannot take one (the channel holds twice
/// [`MAX_TRACES`], more than can exist) is it freed here.
///
/// [`MAX_TRACES`]: crate::limits::MAX_TRACES
pub(crate) fn retire_departed(recordings: &mut Vec<Recording>, spent: &SpentTx) {
    let mut k = 0;
    while k < recordings.len() {
        if recordings[k].left.load(Ordering::Relaxed) {
            // The order of the traces does not matter: each writes its own ring.
            spent.leave(Spent::Ring(recordings.swap_remove(k)));
        } else {
            k += 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::Arc;

    #[test]
    fn the_cycle_hands_a_departed_tools_trace_to_the_server_instead_of_freeing_it() {
        let ring = || {
            Recording::create("retire-test", &[], &[], 1, 1_000_000)
                .unwrap()
                .0
        };
        let mut recordings = vec![ring(), ring(), ring()];
        recordings[0].left.store(true, Ordering::Relaxed);
        recordings[2].left.store(true, Ordering::Relaxed);
        let kept = Arc::as_ptr(&recordings[1].left);
        let (spent, server) = SpentTx::channel(4);
        retire_departed(&mut recordings, &spent);
        assert_eq!(recordings.len(), 1);
        assert_eq!(
            Arc::as_ptr(&recordings[0].left),
            kept,
            "the running trace stays"
        );
        let handed: Vec<Recording> = (server.try_iter())
            .filter_map(|s| match s {
                Spent::Ring(r) => Some(r),
                Spent::Values(_) => None,
            })
            .collect();
        assert_eq!(
            handed.len(),
            2,
            "both departed rings reach the server, still mapped"
        );
        assert!(handed.iter().all(|r| r.left.load(Ordering::Relaxed)));
    }
}
