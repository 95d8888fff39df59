//! The cycle's queue to the journal's writer: a vector under a lock that the cycle only ever
//! tries, a bounded number of times, and the writer holds only to swap it for an empty one.
//!
//! Why not a channel: std's bounded channel makes a sender spin, without yielding, while the
//! receiver is between taking a slot and releasing it, and with a full queue that slot is the
//! one the sender needs. A realtime cycle that preempted the (normal priority) writer in that
//! window, on the same core, spun until the kernel moved the writer away: the alarm flood of
//! `plc-bench --only alarms` had cycles of 2 to 19 ms that way. Here the cycle never waits:
//! if the writer holds the lock (for a swap of two vectors) through every try, or the queue is
//! full, the transition is counted and the journal summarises it.

use super::message::Msg;
use std::sync::{Mutex, TryLockError};

/// Tries of the lock before a transition is counted instead: the writer holds it for a few
/// nanoseconds, unless it was preempted right then.
const TRIES: usize = 64;

/// Transitions waiting for the writer, at most `capacity`.
pub(super) struct Handoff {
    queued: Mutex<Vec<Msg>>,
    capacity: usize,
}

impl Handoff {
    /// An empty queue of `capacity` messages, allocated now: offering allocates nothing.
    pub(super) fn new(capacity: usize) -> Handoff {
        Handoff {
            queued: Mutex::new(Vec::with_capacity(capacity)),
            capacity,
        }
    }

    /// Queues `msg`, or gives it back if the queue is full or the writer holds it: never
    /// waits.
    pub(super) fn offer(&self, msg: Msg) -> Result<(), Msg> {
        for _ in 0..TRIES {
            let mut queued = match self.queued.try_lock() {
                Ok(q) => q,
                // A panic elsewhere while holding it left a whole vector: go on with it.
                Err(TryLockError::Poisoned(p)) => p.into_inner(),
                Err(TryLockError::WouldBlock) => {
                    std::hint::spin_loop();
                    continue;
                }
            };
            if queued.len() >= self.capacity {
                return Err(msg);
            }
            queued.push(msg);
            return Ok(());
        }
        Err(msg)
    }

    /// The writer's side: everything queued, moved into `into` (which must be empty and
    /// keeps its capacity for the next swap; the queue gets it).
    pub(super) fn take(&self, into: &mut Vec<Msg>) {
        let mut queued = self.queued.lock().unwrap_or_else(|p| p.into_inner());
        std::mem::swap(&mut *queued, into);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use plc_core::alarm::{AlarmEvent, EventKind, Level};
    use std::sync::Arc;

    fn event(n: usize) -> Msg {
        Msg::Event {
            paths: Arc::from(vec!["door".to_string()]),
            event: AlarmEvent {
                alarm: 0,
                time_ns: n as i64,
                kind: EventKind::Raised {
                    level: Level::Active,
                },
            },
            value: 1.0,
        }
    }

    #[test]
    fn a_full_queue_gives_the_message_back_and_a_take_empties_it_keeping_capacities() {
        let h = Handoff::new(3);
        for n in 0..3 {
            assert!(h.offer(event(n)).is_ok());
        }
        assert!(h.offer(event(3)).is_err(), "full");
        let mut taken = Vec::with_capacity(3);
        h.take(&mut taken);
        assert_eq!(taken.len(), 3);
        taken.clear();
        assert!(h.offer(event(4)).is_ok(), "room again");
        // Held by the writer through every try: given back at once, not waited for.
        let held = h.queued.lock().unwrap();
        assert!(h.offer(event(5)).is_err());
        drop(held);
        h.take(&mut taken);
        assert_eq!(taken.len(), 1);
        assert!(taken.capacity() >= 3);
    }
}
