//! When the next cycle starts: a deadline on CLOCK_MONOTONIC advanced by one period per
//! cycle and slept to with `clock_nanosleep(TIMER_ABSTIME)`, with the cycle thread's timer
//! slack at its minimum.
//!
//! Why not `std::thread::sleep(next - now)`: a relative sleep oversleeps by whatever passes
//! between reading the clock and the sleep starting (a preemption there delays the cycle by
//! the whole preemption), where an absolute deadline does not move. And Linux lets a normal
//! (not realtime) thread's timers fire up to its timer slack late, 50 us by default, so they
//! can be merged with others: a cycle's start is worth more than that saving. Realtime
//! threads have no slack; setting it changes nothing for them.

use super::clock::monotonic_ns;
use std::time::Duration;

/// The deadline of the next cycle.
pub(super) struct Schedule {
    /// Nanoseconds on CLOCK_MONOTONIC.
    next: u64,
    period: u64,
}

impl Schedule {
    /// The first cycle is due now. Sets the calling thread's timer slack to its minimum (the
    /// cycle's thread, after the threads the start spawned, which keep theirs).
    pub(super) fn start(period: Duration) -> Schedule {
        // SAFETY: PR_SET_TIMERSLACK takes one integer argument; it only sets the calling
        // thread's slack and cannot fail with a valid value (1 ns).
        unsafe { libc::prctl(libc::PR_SET_TIMERSLACK, 1 as libc::c_ulong) };
        Schedule {
            next: monotonic_ns(),
            period: u64::try_from(period.as_nanos()).unwrap_or(u64::MAX),
        }
    }

    /// After a cycle that ended at `now` (CLOCK_MONOTONIC nanoseconds, from the cycle's own
    /// end time: no clock read here): waits for the next one's deadline, one period after the
    /// last one's, and says whether it slept. A late cycle is followed at once, and the
    /// schedule goes on from then: no burst of catch-up cycles.
    pub(super) fn wait(&mut self, now: u64) -> bool {
        self.next = self.next.saturating_add(self.period);
        if self.next <= now {
            self.next = now;
            return false;
        }
        let deadline = libc::timespec {
            tv_sec: (self.next / 1_000_000_000) as libc::time_t,
            tv_nsec: (self.next % 1_000_000_000) as libc::c_long,
        };
        loop {
            // SAFETY: `deadline` is a valid timespec; no remainder is asked for (absolute).
            let rc = unsafe {
                libc::clock_nanosleep(
                    libc::CLOCK_MONOTONIC,
                    libc::TIMER_ABSTIME,
                    &deadline,
                    std::ptr::null_mut(),
                )
            };
            // A signal interrupts the sleep; the deadline stays where it was. No other error
            // can come with a valid deadline on this clock.
            if rc != libc::EINTR {
                break;
            }
        }
        true
    }
}

#[cfg(test)]
mod tests {
    use super::{Schedule, monotonic_ns};
    use std::time::Duration;

    // The schedule's deadlines, not the machine's timing: a loaded machine may wake a sleeper
    // late, but the deadlines stay a period apart.
    #[test]
    fn deadlines_are_a_period_apart_and_a_late_cycle_is_not_caught_up() {
        let period = Duration::from_millis(2);
        let mut schedule = Schedule::start(period);
        let first = schedule.next;
        assert!(schedule.wait(monotonic_ns()), "a cycle on time sleeps");
        schedule.wait(monotonic_ns());
        assert_eq!(schedule.next, first + 4_000_000);
        assert!(monotonic_ns() >= schedule.next, "it slept to the deadline");
        // A cycle that takes three periods: the next starts at once and the schedule goes on
        // from then, not from the missed deadlines.
        std::thread::sleep(period * 3);
        let late = monotonic_ns();
        assert!(!schedule.wait(late), "a late cycle is followed at once");
        assert!(schedule.next >= late, "the missed deadlines are dropped");
        let resumed = schedule.next;
        schedule.wait(monotonic_ns());
        assert_eq!(schedule.next, resumed + 2_000_000);
    }
}
