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
//!
//! An I/O with a clock of its own (EtherCAT with distributed clocks: SYNC0) tells where each
//! exchange fell against that clock ([`CyclePhase`]); the next deadline then moves by
//! [`correction`], so the cycle follows the bus's time rather than the host's, whose
//! crystals differ by up to 100 ppm (0.1 ms per 1000 cycles of 1 ms, a whole period within
//! a minute). Why a small, bounded step each cycle instead of ethercrab's example's full
//! `next_cycle_wait`: the measurement carries the exchange's own jitter (a preempted frame
//! thread reads as a late SYNC0 phase); a quarter of the error per cycle averages that
//! jitter out while still following any real crystal (the loop settles at four times the
//! drift per cycle: 0.4 us at 100 ppm and 1 ms), and a cap of a sixteenth of the period
//! means no value, however wrong, moves a cycle's start by more than that nor makes a
//! deadline go backwards. A missed deadline is handled as without DC (the next cycle at
//! once, no catch-up; the overruns counted stay the cycles that took too long), except that
//! the deadlines after it stay on their grid against the I/O's clock, and the phase of the
//! cycle that started at once, off its deadline, is not corrected for.

use super::clock::monotonic_ns;
use crate::CyclePhase;
use std::time::Duration;

/// The share of the measured phase error corrected per cycle: one quarter.
const GAIN_DIVISOR: i128 = 4;

/// The largest correction per cycle: a sixteenth of the period (62.5 us at 1 ms).
const MAX_CORRECTION_DIVISOR: u64 = 16;

/// How much to move the next deadline (signed ns: negative is earlier) so the exchanges of a
/// cycle of `period` ns meet the I/O's clock where it wants them: a quarter of the phase
/// error, at most a sixteenth of the period. The error is `phase.offset - phase.target`
/// modulo the period, taken the short way round (within half a period): a cycle that came
/// late is pulled earlier, one that came early pushed later. Nothing without a measurement
/// or with a zero period (a loop running flat out has no deadline to move).
pub(super) fn correction(period: u64, phase: Option<CyclePhase>) -> i64 {
    let Some(phase) = phase else { return 0 };
    if period == 0 {
        return 0;
    }
    let p = i128::from(period);
    // Both below the period after the modulo, so the difference is within (-p, p).
    let offset = (phase.offset.as_nanos() % period as u128) as i128;
    let target = (phase.target.as_nanos() % period as u128) as i128;
    let mut error = offset - target;
    if error > p / 2 {
        error -= p;
    } else if error <= -(p / 2) {
        error += p;
    }
    let max = i128::from(period / MAX_CORRECTION_DIVISOR);
    // Within ±u64::MAX / 16: fits an i64.
    (-error / GAIN_DIVISOR).clamp(-max, max) as i64
}

/// The deadline of the next cycle.
pub(super) struct Schedule {
    /// Nanoseconds on CLOCK_MONOTONIC.
    next: u64,
    period: u64,
    /// The cycle now running started at its deadline (it did not follow a late one at
    /// once): only such a cycle's phase says where the deadlines stand against the I/O's
    /// clock.
    on_deadline: bool,
    /// The I/O has measured a phase: the deadlines keep their grid against its clock from
    /// then on, also through cycles that measured none (a lost frame) or did not count.
    locked: bool,
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
            on_deadline: true,
            locked: false,
        }
    }

    /// After a cycle that ended at `now` (CLOCK_MONOTONIC nanoseconds, from the cycle's own
    /// end time: no clock read here): waits for the next one's deadline, one period after the
    /// last one's moved by the [`correction`] for `phase` (where the I/O measured this
    /// cycle's exchange, if it did), and says whether it slept. A late cycle is followed at
    /// once: no burst of catch-up cycles. Without any `phase` so far the schedule goes on
    /// from then; once the I/O has measured one, the deadlines keep their place against the
    /// I/O's clock (the next one is the first a whole number of periods on that is still
    /// ahead), so a late cycle does not throw the lock away and take a dozen cycles to win
    /// it back.
    pub(super) fn wait(&mut self, now: u64, phase: Option<CyclePhase>) -> bool {
        self.locked |= phase.is_some();
        // A cycle that followed a late one at once started off its deadline: its phase
        // tells where that cycle fell, not where the deadlines are.
        let phase = phase.filter(|_| self.on_deadline);
        let step = correction(self.period, phase);
        // At most a sixteenth of the period either way: the deadline always moves forward.
        self.next = self
            .next
            .saturating_add(self.period)
            .saturating_add_signed(step);
        if self.next <= now {
            self.on_deadline = false;
            if self.locked && self.period > 0 {
                // The last deadline on the grid not after `now`: the one after it is ahead.
                let behind = now - self.next;
                self.next += behind - behind % self.period;
            } else {
                self.next = now;
            }
            return false;
        }
        self.on_deadline = true;
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
    use super::{CyclePhase, Schedule, correction, monotonic_ns};
    use std::time::Duration;

    fn phase(offset_us: u64, target_us: u64) -> Option<CyclePhase> {
        Some(CyclePhase {
            offset: Duration::from_micros(offset_us),
            target: Duration::from_micros(target_us),
        })
    }

    const MS: u64 = 1_000_000;

    #[test]
    fn a_late_exchange_pulls_the_next_deadline_earlier_by_a_quarter_of_the_error() {
        assert_eq!(correction(MS, phase(290, 250)), -10_000);
        assert_eq!(correction(MS, phase(210, 250)), 10_000);
        assert_eq!(correction(MS, phase(250, 250)), 0);
        assert_eq!(correction(MS, None), 0, "no measurement, no correction");
    }

    #[test]
    fn the_error_is_taken_the_short_way_round_the_period() {
        // 950 us after SYNC0 with a target of 50 us: 100 us early, not 900 us late.
        assert_eq!(correction(MS, phase(950, 50)), 25_000);
        // 50 us after with a target of 950 us: 100 us late.
        assert_eq!(correction(MS, phase(50, 950)), -25_000);
        // SYNC0 every 2 ms, cycles of 1 ms: 1.3 ms after SYNC0 is 0.3 ms into a cycle.
        assert_eq!(correction(MS, phase(1_300, 250)), -12_500);
    }

    #[test]
    fn a_correction_never_exceeds_a_sixteenth_of_the_period() {
        assert_eq!(correction(MS, phase(700, 250)), -(MS as i64) / 16);
        assert_eq!(correction(MS, phase(0, 400)), MS as i64 / 16);
    }

    #[test]
    fn wild_values_give_a_bounded_correction_and_no_panic() {
        let huge = Duration::MAX;
        for period in [0, 1, 3, MS, u64::MAX] {
            for (offset, target) in [
                (huge, Duration::ZERO),
                (Duration::ZERO, huge),
                (huge, huge),
                (Duration::from_nanos(u64::MAX), Duration::from_nanos(1)),
            ] {
                let c = correction(period, Some(CyclePhase { offset, target }));
                assert!(c.unsigned_abs() <= period / 16, "{period} {c}");
            }
        }
        assert_eq!(
            correction(0, phase(700, 250)),
            0,
            "a zero period moves nothing"
        );
    }

    #[test]
    fn a_late_cycle_under_a_lock_keeps_the_deadlines_on_their_grid() {
        let mut schedule = Schedule::start(Duration::from_millis(2));
        let first = schedule.next;
        // Ended 2.5 periods after the first deadline, exchanged exactly on phase.
        let late = first + 5_000_000;
        assert!(!schedule.wait(late, phase(0, 0)), "followed at once");
        assert_eq!(
            schedule.next,
            first + 4_000_000,
            "the last grid point passed"
        );
        // The cycle that followed at once measured an odd phase: not corrected for, and the
        // next deadline is the grid's.
        assert!(schedule.wait(late + 100_000, phase(1_500, 0)));
        assert_eq!(schedule.next, first + 6_000_000);
        // On its deadline again: corrections resume.
        schedule.wait(schedule.next, phase(100, 0));
        assert_eq!(schedule.next, first + 8_000_000 - 25_000);
        // Late again, this time with no measurement (a lost frame): still on the grid.
        let grid = schedule.next;
        assert!(!schedule.wait(grid + 2_500_000, None));
        assert_eq!(schedule.next, grid + 2_000_000);
    }

    #[test]
    fn a_corrected_deadline_still_moves_forward() {
        let mut schedule = Schedule::start(Duration::from_millis(2));
        let first = schedule.next;
        // An offset that wants the cycle much earlier: the deadline moves at most 1/16 less
        // than a period, and a deadline already passed is not slept to.
        schedule.wait(first, phase(900, 0));
        assert_eq!(schedule.next, first + 2_000_000 - 125_000);
        let second = schedule.next;
        schedule.wait(second, phase(100, 0));
        assert_eq!(schedule.next, second + 2_000_000 - 25_000);
    }

    // The schedule's deadlines, not the machine's timing: a loaded machine may wake a sleeper
    // late, but the deadlines stay a period apart.
    #[test]
    fn deadlines_are_a_period_apart_and_a_late_cycle_is_not_caught_up() {
        let period = Duration::from_millis(2);
        let mut schedule = Schedule::start(period);
        let first = schedule.next;
        assert!(
            schedule.wait(monotonic_ns(), None),
            "a cycle on time sleeps"
        );
        schedule.wait(monotonic_ns(), None);
        assert_eq!(schedule.next, first + 4_000_000);
        assert!(monotonic_ns() >= schedule.next, "it slept to the deadline");
        // A cycle that takes three periods: the next starts at once and the schedule goes on
        // from then, not from the missed deadlines.
        std::thread::sleep(period * 3);
        let late = monotonic_ns();
        assert!(
            !schedule.wait(late, None),
            "a late cycle is followed at once"
        );
        assert!(schedule.next >= late, "the missed deadlines are dropped");
        let resumed = schedule.next;
        schedule.wait(monotonic_ns(), None);
        assert_eq!(schedule.next, resumed + 2_000_000);
    }
}
