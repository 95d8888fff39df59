//! Cycle-time statistics as the runtime keeps them: each cycle's time added to the
//! [`CycleStats`] that the tick sees and the status block publishes.

use plc_shm::CycleStats;
use std::time::Duration;

/// Counts cycle number `count` (from 1), which took `took_ns` nanoseconds; `mean` is the
/// running mean the caller keeps beside these figures.
pub(crate) fn add(stats: &mut CycleStats, took_ns: u64, count: u64, mean: &mut RunningMean) {
    let took = Duration::from_nanos(took_ns);
    stats.last = took;
    if count == 1 || took < stats.min {
        stats.min = took;
    }
    stats.max = stats.max.max(took);
    stats.mean = Duration::from_nanos(mean.add(took_ns, count));
    if took > stats.period && !stats.period.is_zero() {
        stats.overruns += 1;
    }
}

/// The exact mean of the cycles' times, in whole nanoseconds (rounded down), without a
/// division per cycle: the sum of `n` times is kept as `quotient * n + remainder`. A new
/// time moves the quotient by at most one in nearly every cycle (a time within one mean of
/// the mean), which an addition does; only a time far from the mean divides. A division per
/// cycle cost the runtime's cycle 6-7 ns, more than all its other figures together
/// (the repository's docs/benchmarks-history.md, "The runtime's cycle"); a floating-point mean drifts.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct RunningMean {
    quotient: u64,
    /// Below the count.
    remainder: u64,
}

impl RunningMean {
    /// Adds time number `n` (from 1) and returns the mean of all `n`.
    pub(crate) fn add(&mut self, time: u64, n: u64) -> u64 {
        let n = i128::from(n.max(1));
        let (q, r) = (i128::from(self.quotient), i128::from(self.remainder));
        // The old sum q * (n - 1) + r plus `time` is q * n + d.
        let d = r + i128::from(time) - q;
        let (q, r) = if (0..n).contains(&d) {
            (q, d)
        } else if (n..2 * n).contains(&d) {
            (q + 1, d - n)
        } else if (-n..0).contains(&d) {
            (q - 1, d + n)
        } else {
            let sum = q * n + d;
            (sum / n, sum % n)
        };
        // The mean of u64 times fits a u64, and the remainder is below a u64 count.
        self.quotient = u64::try_from(q).unwrap_or(u64::MAX);
        self.remainder = u64::try_from(r).unwrap_or(0);
        self.quotient
    }
}

#[cfg(test)]
mod tests {
    use super::{CycleStats, RunningMean, add};
    use std::time::Duration;

    fn ms(n: u64) -> Duration {
        Duration::from_millis(n)
    }

    #[test]
    fn min_max_mean_and_overruns_follow_the_cycles() {
        let mut s = CycleStats {
            period: ms(10),
            ..CycleStats::default()
        };
        let mut mean = RunningMean::default();
        for (n, took) in [ms(4), ms(2), ms(12)].into_iter().enumerate() {
            add(&mut s, took.as_nanos() as u64, n as u64 + 1, &mut mean);
        }
        assert_eq!((s.last, s.min, s.max), (ms(12), ms(2), ms(12)));
        assert_eq!(s.mean, ms(6));
        assert_eq!(s.overruns, 1);
    }

    proptest::proptest! {
        // Times near the mean, far from it, and at the extremes: always the sum over the
        // count, rounded down.
        #[test]
        fn the_running_mean_is_the_sum_over_the_count(
            times in proptest::collection::vec(
                proptest::prop_oneof![
                    990u64..1010,
                    0u64..100_000_000,
                    proptest::strategy::Just(0u64),
                    proptest::strategy::Just(u64::MAX),
                ],
                1..300,
            )
        ) {
            let mut mean = RunningMean::default();
            let mut sum = 0u128;
            for (i, &t) in times.iter().enumerate() {
                let n = i as u64 + 1;
                sum += u128::from(t);
                proptest::prop_assert_eq!(u128::from(mean.add(t, n)), sum / u128::from(n));
            }
        }
    }

    #[test]
    fn a_zero_period_counts_no_overruns() {
        let mut s = CycleStats::default();
        add(&mut s, 5_000_000, 1, &mut RunningMean::default());
        assert_eq!((s.min, s.overruns), (ms(5), 0));
    }
}
