//! The cycle's clock, read as few times as a cycle can do with: CLOCK_MONOTONIC at its start
//! and at its end, as plain nanoseconds, and nothing more. The schedule's deadlines, the
//! program's `Context::now`, the cycle time and the wall-clock time stamped on the published
//! values are all worked out from those two readings: every clock read costs a cycle
//! 15-25 ns, about what the rest of its bookkeeping costs together (the repository's
//! docs/benchmarks-history.md, "The runtime's cycle"), and integer nanoseconds subtract without `Instant`'s normalising.

use plc_shm::clock_ns;
#[cfg(feature = "cycle-probe")]
use std::time::{Duration, Instant};

/// CLOCK_MONOTONIC in nanoseconds: the clock `std::time::Instant` reads on Linux.
pub(super) fn monotonic_ns() -> u64 {
    clock_ns(libc::CLOCK_MONOTONIC)
}

/// A reading of another clock and the monotonic nanoseconds it was taken at: read back to
/// back between two monotonic readings, and placed midway (an error of half the gap
/// between two reads, tens of nanoseconds).
#[derive(Clone, Copy, Debug)]
struct Pair<C> {
    monotonic: u64,
    other: C,
}

impl<C> Pair<C> {
    fn read(other: impl FnOnce() -> C) -> Pair<C> {
        let before = monotonic_ns();
        let other = other();
        let after = monotonic_ns();
        Pair {
            monotonic: before + after.saturating_sub(before) / 2,
            other,
        }
    }
}

/// How long a wall-clock pairing is trusted. Both clocks run at the same rate (NTP slews
/// both), so the two only part when the time is set: the stamps follow within this.
const WALL_CLOCK_RESYNC_NS: u64 = 100_000_000;

/// The cycle's times, as CLOCK_MONOTONIC nanoseconds, and what they stand for on the
/// program's and the world's clocks.
pub(super) struct CycleClock {
    /// The runtime's start, where `Context::now` counts from.
    epoch: u64,
    wall: Pair<u64>,
    #[cfg(feature = "cycle-probe")]
    instant: Pair<Instant>,
}

impl CycleClock {
    pub(super) fn start() -> CycleClock {
        CycleClock {
            epoch: monotonic_ns(),
            wall: Pair::read(|| clock_ns(libc::CLOCK_REALTIME)),
            #[cfg(feature = "cycle-probe")]
            instant: Pair::read(Instant::now),
        }
    }

    /// The nanoseconds since the runtime started, at `t`.
    pub(super) fn since_start(&self, t: u64) -> u64 {
        t.saturating_sub(self.epoch)
    }

    /// CLOCK_REALTIME at `t`, in nanoseconds since the Unix epoch: the values' time as other
    /// machines read it. Read afresh every 100 ms, so a clock that was set is followed then.
    pub(super) fn utc_ns(&mut self, t: u64) -> u64 {
        if t.wrapping_sub(self.wall.monotonic) >= WALL_CLOCK_RESYNC_NS {
            self.wall = Pair::read(|| clock_ns(libc::CLOCK_REALTIME));
        }
        let Pair { monotonic, other } = self.wall;
        if t >= monotonic {
            other.saturating_add(t - monotonic)
        } else {
            other.saturating_sub(monotonic - t)
        }
    }

    /// `t` as an `Instant`, for the benchmarks' probe (which compares it with instants the
    /// backend takes): off by the same few nanoseconds for every `t`.
    #[cfg(feature = "cycle-probe")]
    pub(super) fn instant(&self, t: u64) -> Instant {
        let Pair { monotonic, other } = self.instant;
        if t >= monotonic {
            other + Duration::from_nanos(t - monotonic)
        } else {
            other - Duration::from_nanos(monotonic - t)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::Duration;

    #[test]
    fn the_wall_clock_is_the_realtime_clock_within_a_few_microseconds() {
        let mut clock = CycleClock::start();
        let before = clock_ns(libc::CLOCK_REALTIME);
        let t = monotonic_ns();
        let after = clock_ns(libc::CLOCK_REALTIME);
        // The pairing's error is tens of nanoseconds; a preempted test gets a margin.
        let slack = 50_000;
        let utc = clock.utc_ns(t);
        assert!(
            before - slack <= utc && utc <= after + slack,
            "{before} {utc} {after}"
        );
        assert!(clock.since_start(t) < 1_000_000_000);
    }

    #[test]
    fn the_wall_clock_is_paired_again_after_its_interval() {
        let mut clock = CycleClock::start();
        let first = clock.wall.monotonic;
        clock.utc_ns(first + WALL_CLOCK_RESYNC_NS / 2);
        assert_eq!(
            clock.wall.monotonic, first,
            "within the interval the pairing stands"
        );
        std::thread::sleep(Duration::from_millis(1));
        clock.utc_ns(first + WALL_CLOCK_RESYNC_NS);
        let paired = clock.wall.monotonic;
        assert_ne!(paired, first, "read afresh");
        std::thread::sleep(Duration::from_millis(1));
        clock.utc_ns(paired - 1);
        assert_ne!(
            clock.wall.monotonic, paired,
            "a time before the pairing reads afresh too"
        );
    }

    #[cfg(feature = "cycle-probe")]
    #[test]
    fn an_instant_is_the_monotonic_time_within_a_few_microseconds() {
        let clock = CycleClock::start();
        let before = std::time::Instant::now();
        let t = monotonic_ns();
        let after = std::time::Instant::now();
        let slack = Duration::from_micros(50);
        let at = clock.instant(t);
        assert!(before - slack <= at && at <= after + slack);
    }
}
