//! Timing side by side on a shared, noisy machine: medians of batches, ratios from one run.

use std::time::{Duration, Instant};

/// Median time per iteration of `f` over `batches` batches of `iters` iterations.
pub fn median_per_iter(batches: usize, iters: u32, mut f: impl FnMut()) -> Duration {
    let mut t: Vec<Duration> = (0..batches.max(1))
        .map(|_| {
            let start = Instant::now();
            for _ in 0..iters {
                f();
            }
            start.elapsed() / iters.max(1)
        })
        .collect();
    t.sort();
    t[t.len() / 2]
}

/// Runs two candidates in alternating batches (so both see the same machine load) and returns
/// the median time per iteration of each.
pub fn side_by_side(
    batches: usize,
    iters: u32,
    mut a: impl FnMut(),
    mut b: impl FnMut(),
) -> (Duration, Duration) {
    let (mut ta, mut tb) = (Vec::new(), Vec::new());
    for _ in 0..batches.max(1) {
        ta.push(median_per_iter(1, iters, &mut a));
        tb.push(median_per_iter(1, iters, &mut b));
    }
    ta.sort();
    tb.sort();
    (ta[ta.len() / 2], tb[tb.len() / 2])
}

/// `a / b` as a float.
pub fn ratio(a: Duration, b: Duration) -> f64 {
    a.as_secs_f64() / b.as_secs_f64()
}
