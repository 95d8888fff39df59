//! From one block's cycle timestamps to its figures: the period deviation (each cycle's start
//! minus `t0 + k * T`), overruns, and the time per cycle outside the bus exchange and the tick.

use plc_io::probe::CycleTimes;
use std::time::{Duration, Instant};

/// The figures of one block of cycles, in microseconds where they are times.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Block {
    /// Median period deviation.
    pub p50: f64,
    /// 99th percentile of the period deviation.
    pub p99: f64,
    /// Largest period deviation.
    pub max: f64,
    /// Cycles that ended after the next one was due.
    pub overruns: usize,
    /// Median of the cycle's time minus the bus exchange and the tick.
    pub own: f64,
    /// Median bus exchange (the frame's round trip).
    pub exchange: f64,
}

/// The figures of `times`, cycles meant to start every `period`.
///
/// The grid's origin `t0` is the loop's own schedule, which only the loop knows; since a sleep
/// never returns early, no cycle starts before it is due, so `t0` is taken as the latest origin
/// no cycle starts before: the smallest `start_k - k * T`. Both loops measured follow a late
/// cycle at once and time the next from there (no burst of catch-up cycles), so after an
/// overrun (a cycle that ended after the next was due) the grid starts again at the late
/// cycle: its lateness is counted once, against the old grid, and not again in every later
/// cycle.
pub fn analyse(times: &[CycleTimes], period: Duration) -> Block {
    let Some(base) = times.first().map(|t| t.start) else {
        return Block {
            p50: f64::NAN,
            p99: f64::NAN,
            max: f64::NAN,
            overruns: 0,
            own: f64::NAN,
            exchange: f64::NAN,
        };
    };
    // In whole nanoseconds, so the grid's sums are exact.
    let t = i64::try_from(period.as_nanos()).unwrap_or(i64::MAX);
    let start: Vec<i64> = times.iter().map(|c| signed_ns(c.start, base)).collect();
    let end: Vec<i64> = times.iter().map(|c| signed_ns(c.end, base)).collect();
    // Where the grid starts again: found against a grid anchored at each run's first start,
    // which is the loop's schedule to within one wake-up's latency.
    let mut runs = vec![0];
    let (mut anchor, mut k) = (0, 0);
    for i in 1..times.len() {
        k += 1;
        if end[i - 1] >= anchor + k * t {
            runs.push(i);
            (anchor, k) = (start[i], 0);
        }
    }
    runs.push(times.len());
    let mut deviations = Vec::with_capacity(times.len());
    let mut previous: Option<(i64, usize)> = None;
    for run in runs.windows(2) {
        let (first, past) = (run[0], run[1]);
        let steps = |i: usize, from: usize| (i - from) as i64 * t;
        let origin = (first..past)
            .map(|i| start[i] - steps(i, first))
            .min()
            .unwrap_or(0);
        for (i, &at) in start.iter().enumerate().take(past).skip(first) {
            let due = match previous {
                Some((o, f)) if i == first => o + steps(i, f),
                _ => origin + steps(i, first),
            };
            deviations.push((at - due) as f64 / 1e3);
        }
        previous = Some((origin, first));
    }
    let us = |d: Duration| d.as_secs_f64() * 1e6;
    let own: Vec<f64> = times.iter().map(|t| us(t.framework())).collect();
    let exchange: Vec<f64> = times.iter().map(|t| us(t.bus_end - t.bus_start)).collect();
    Block {
        p50: percentile(&deviations, 50.0),
        p99: percentile(&deviations, 99.0),
        max: percentile(&deviations, 100.0),
        overruns: runs.len() - 2,
        own: percentile(&own, 50.0),
        exchange: percentile(&exchange, 50.0),
    }
}

/// `a - b` in nanoseconds, negative when `a` is earlier (a block lasts seconds, far from
/// the 292 years an `i64` holds).
fn signed_ns(a: Instant, b: Instant) -> i64 {
    let ns = |d: Duration| i64::try_from(d.as_nanos()).unwrap_or(i64::MAX);
    if a >= b { ns(a - b) } else { -ns(b - a) }
}

/// The `p`-th percentile of `values` (nearest rank); NaN when there are none.
pub fn percentile(values: &[f64], p: f64) -> f64 {
    if values.is_empty() {
        return f64::NAN;
    }
    let mut v = values.to_vec();
    v.sort_by(f64::total_cmp);
    let rank = ((p / 100.0) * v.len() as f64).ceil() as usize;
    v[rank.clamp(1, v.len()) - 1]
}

/// The median of `blocks`' figure `f`.
pub fn median(blocks: &[Block], f: impl Fn(&Block) -> f64) -> f64 {
    percentile(&blocks.iter().map(f).collect::<Vec<_>>(), 50.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cycle(t0: Instant, start_us: u64, took_us: u64) -> CycleTimes {
        let at = |us| t0 + Duration::from_micros(us);
        CycleTimes {
            start: at(start_us),
            bus_start: at(start_us + 1),
            bus_end: at(start_us + 21),
            tick_start: at(start_us + 22),
            tick_end: at(start_us + 24),
            end: at(start_us + took_us),
        }
    }

    #[test]
    fn the_deviation_is_each_start_against_the_grid() {
        let t0 = Instant::now();
        let times: Vec<_> = [0, 1_010, 2_000, 3_050]
            .into_iter()
            .map(|s| cycle(t0, s, 30))
            .collect();
        let b = analyse(&times, Duration::from_millis(1));
        assert_eq!((b.p50, b.max, b.overruns), (0.0, 50.0, 0));
        assert_eq!((b.own, b.exchange), (8.0, 20.0));
    }

    #[test]
    fn a_late_first_cycle_does_not_set_the_grid() {
        let t0 = Instant::now();
        // The first cycle woke 20 us late, the others 5 us: the grid is the earliest one
        // no cycle starts before.
        let times: Vec<_> = [20, 1_005, 2_005, 3_005]
            .into_iter()
            .map(|s| cycle(t0, s, 30))
            .collect();
        let b = analyse(&times, Duration::from_millis(1));
        assert_eq!((b.p50, b.max), (0.0, 15.0));
    }

    #[test]
    fn an_overrun_is_counted_once_and_the_grid_follows_the_late_cycle() {
        let t0 = Instant::now();
        // The second cycle runs 1.5 ms, so the third starts 500 us late and the fourth is due
        // a period after it.
        let times = vec![
            cycle(t0, 0, 30),
            cycle(t0, 1_000, 1_500),
            cycle(t0, 2_500, 30),
            cycle(t0, 3_500, 30),
        ];
        let b = analyse(&times, Duration::from_millis(1));
        assert_eq!((b.p50, b.max, b.overruns), (0.0, 500.0, 1));
    }

    #[test]
    fn percentiles_take_the_nearest_rank() {
        let v: Vec<f64> = (1..=100).map(f64::from).collect();
        assert_eq!(
            (
                percentile(&v, 50.0),
                percentile(&v, 99.0),
                percentile(&v, 100.0)
            ),
            (50.0, 99.0, 100.0)
        );
        assert!(percentile(&[], 50.0).is_nan());
        assert!(analyse(&[], Duration::from_millis(1)).p99.is_nan());
    }
}
