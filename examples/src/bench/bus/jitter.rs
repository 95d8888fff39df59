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
/// Both loops measured follow a late cycle at once and time the next from there (no burst of
/// catch-up cycles), so after an overrun the grid `t0 + k * T` is anchored again at the late
/// cycle's start: that cycle's lateness is counted once, not again in every later cycle.
pub fn analyse(times: &[CycleTimes], period: Duration) -> Block {
    let mut deviations = Vec::with_capacity(times.len());
    let mut overruns = 0;
    let mut anchor = times.first().map(|t| t.start);
    let mut k = 0u32;
    let mut previous_end: Option<Instant> = None;
    for t in times {
        let Some(t0) = anchor else { break };
        let due = t0 + period * k;
        deviations.push(signed_us(t.start, due));
        k += 1;
        if previous_end.is_some_and(|end| end >= due) {
            overruns += 1;
            anchor = Some(t.start);
            k = 1;
        }
        previous_end = Some(t.end);
    }
    let us = |d: Duration| d.as_secs_f64() * 1e6;
    let own: Vec<f64> = times.iter().map(|t| us(t.framework())).collect();
    let exchange: Vec<f64> = times.iter().map(|t| us(t.bus_end - t.bus_start)).collect();
    Block {
        p50: percentile(&deviations, 50.0),
        p99: percentile(&deviations, 99.0),
        max: percentile(&deviations, 100.0),
        overruns,
        own: percentile(&own, 50.0),
        exchange: percentile(&exchange, 50.0),
    }
}

/// `a - b` in microseconds, negative when `a` is earlier.
fn signed_us(a: Instant, b: Instant) -> f64 {
    if a >= b {
        (a - b).as_secs_f64() * 1e6
    } else {
        -((b - a).as_secs_f64() * 1e6)
    }
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
        assert_eq!((b.max, b.overruns), (500.0, 1));
        assert_eq!(percentile(&[0.0, 0.0, 500.0, 0.0], 50.0), 0.0);
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
    }
}
