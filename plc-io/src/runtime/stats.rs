//! Cycle-time statistics: kept by the runtime, seen by the program's tick, published in the
//! status block and read back by the tools, all as this one type.

use std::time::Duration;

/// Cycle-time statistics: the work of one cycle (exchange to publish), not the sleep.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CycleStats {
    /// The configured period.
    pub period: Duration,
    /// Last cycle.
    pub last: Duration,
    /// Shortest cycle.
    pub min: Duration,
    /// Longest cycle.
    pub max: Duration,
    /// Mean cycle.
    pub mean: Duration,
    /// Cycles that did not finish within their period.
    pub overruns: u64,
}

impl CycleStats {
    pub(crate) fn add(&mut self, took: Duration, count: u64) {
        self.last = took;
        if count == 1 || took < self.min {
            self.min = took;
        }
        self.max = self.max.max(took);
        // Running mean without overflow: mean += (x - mean) / n.
        let n = count.max(1) as f64;
        let mean = self.mean.as_secs_f64();
        self.mean = Duration::from_secs_f64(mean + (took.as_secs_f64() - mean) / n);
        if took > self.period && !self.period.is_zero() {
            self.overruns += 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::CycleStats;
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
        for (n, took) in [ms(4), ms(2), ms(12)].into_iter().enumerate() {
            s.add(took, n as u64 + 1);
        }
        assert_eq!((s.last, s.min, s.max), (ms(12), ms(2), ms(12)));
        assert!((s.mean.as_secs_f64() - 0.006).abs() < 1e-9, "{:?}", s.mean);
        assert_eq!(s.overruns, 1);
    }

    #[test]
    fn a_zero_period_counts_no_overruns() {
        let mut s = CycleStats::default();
        s.add(ms(5), 1);
        assert_eq!((s.min, s.overruns), (ms(5), 0));
    }
}
