//! `alarm_eval_ns_per_alarm`: what 1,000 declared alarms, none changing, cost the runtime's
//! cycle, per alarm (target 5 ns at most).
//!
//! The real `plc_io::Runtime` runs [`Alarmed1k`] and [`Plain1k`] (the same variables without
//! alarms) at a 1 ms period, in alternating blocks of cycles, each block a runtime of its own
//! on this thread; the tick only puts the temperatures inside their limits in the first
//! cycle. The runtime's cycle probe gives each cycle's time, start to end: with alarms it
//! includes the alarm step as the cycle calls it (the cycle's UTC time set before the tick,
//! `RuntimeAlarms::evaluate` after it, each alarm's value read from the struct through
//! `GlobalMemory::get`). No segment and no journal: neither is touched in a cycle where no
//! alarm changes, and both would only add their noise to the difference. The figure is the
//! median over the block pairs of the difference of the blocks' median cycles, divided by
//! 1,000; `_blocks` gives the smallest and largest pair, `alarm_eval_mean_ns_per_alarm` the
//! same from the blocks' mean cycles (which a preempted cycle moves by as much as all the
//! others: context only).
//!
//! Why the whole runtime rather than its step alone: the step's state (per alarm its
//! condition, its state and where its value lies, some 170 bytes: 170 KB for 1,000) is
//! touched once a millisecond, and what the machine did meanwhile decides whether it is
//! still in the core's caches. Only a cycle at a real period pays that, and a 1,000-alarm
//! step of a few microseconds stands well above the spread of a block's median cycle. The
//! price: the figure moves with the machine's load (other work on the core between two
//! cycles evicts the step's state), which the blocks' range shows.
//!
//! Where the time goes, two more figures: `alarm_eval_hot_ns_per_alarm`, the same comparison
//! at period zero (cycle after cycle, the step's state hot in the caches: the code's own
//! cost); and `alarm_evaluator_alone_ns_per_alarm`, the group's earlier figure:
//! `plc_core::alarm::Alarms::evaluate` alone in a loop, each sample read from the struct's
//! fields directly, against those reads alone. The hot figure less the evaluator alone is the
//! runtime's way of reading a sample (a `Value` per alarm through `get`); the 1 ms figure less
//! the hot one is the caches.

use super::{Alarmed1k, Plain1k, TEMPERATURE, median};
use crate::timing::side_by_side;
use plc_core::GlobalMemory;
use plc_core::alarm::{AlarmEvent, Alarms, Sample};
use plc_io::probe::CycleTimes;
use plc_io::{Context, Runtime};
use std::fmt::Write as _;
use std::hint::black_box;
use std::sync::{Arc, Mutex};
use std::time::Duration;

/// The period the runtimes run at for the figure.
const PERIOD: Duration = Duration::from_millis(1);
/// Cycles of a block at [`PERIOD`]: a quarter of a second, so that a block pair sees one
/// state of the machine and many pairs see many.
const CYCLES: u64 = 250;
/// Cycles of a block at period zero, a few tens of milliseconds.
const HOT_CYCLES: u64 = 10_000;
/// Cycles at the start of each block left out: the first ones take the program's state, its
/// caches and the probe's vector from cold.
const WARM_UP: usize = 50;
/// Iterations of the evaluator alone per batch.
const ITERS: u32 = 2000;

/// Runs `blocks` blocks each side at 1 ms and at period zero, and the evaluator alone in
/// `batches` batches each side; the figures' `name: value` lines.
pub fn run(blocks: usize, batches: usize) -> Result<String, String> {
    if Alarmed1k::ALARMS.len() != 1000 || !Plain1k::ALARMS.is_empty() {
        return Err(format!(
            "{} and {} alarms declared, not 1,000 and none",
            Alarmed1k::ALARMS.len(),
            Plain1k::ALARMS.len()
        ));
    }
    let timed = compare(PERIOD, CYCLES, blocks)?;
    let hot = compare(Duration::ZERO, HOT_CYCLES, blocks)?;
    let alone = evaluator_alone(batches)?;
    let per_alarm = |ns: f64| ns / Alarmed1k::ALARMS.len() as f64;

    let mut out = String::new();
    let _ = writeln!(
        out,
        "alarm_eval_samples: {} blocks of {CYCLES} cycles each side at {} ms and of \
         {HOT_CYCLES} at period zero, alternating, the first {WARM_UP} of each block left \
         out; the evaluator alone {batches} batches of {ITERS} each side",
        timed.diffs.len(),
        PERIOD.as_millis()
    );
    let _ = writeln!(out, "alarm_cycle_1000_alarms_ns: {}", timed.alarmed);
    let _ = writeln!(out, "alarm_cycle_no_alarms_ns: {}", timed.plain);
    let _ = writeln!(
        out,
        "alarm_eval_ns_per_alarm: {:.2}",
        per_alarm(timed.diff() as f64)
    );
    let (lowest, highest) = timed.range();
    let _ = writeln!(
        out,
        "alarm_eval_ns_per_alarm_blocks: {:.2} to {:.2}",
        per_alarm(lowest as f64),
        per_alarm(highest as f64)
    );
    let _ = writeln!(
        out,
        "alarm_eval_mean_ns_per_alarm: {:.2}",
        per_alarm(timed.mean_diff)
    );
    let _ = writeln!(
        out,
        "alarm_eval_hot_ns_per_alarm: {:.2} ({} ns a cycle against {})",
        per_alarm(hot.diff() as f64),
        hot.alarmed,
        hot.plain
    );
    let _ = writeln!(out, "alarm_evaluator_alone_ns_per_alarm: {alone:.2}");
    Ok(out)
}

/// Both programs in alternating blocks at one period.
struct Comparison {
    /// The median of the blocks' median cycles, ns.
    alarmed: u64,
    plain: u64,
    /// Each block pair's difference of median cycles, ns, sorted.
    diffs: Vec<i64>,
    /// The difference of the blocks' mean cycles, averaged, ns.
    mean_diff: f64,
}

impl Comparison {
    /// The median difference, ns.
    fn diff(&self) -> i64 {
        self.diffs.get(self.diffs.len() / 2).copied().unwrap_or(0)
    }

    /// The smallest and largest difference, ns.
    fn range(&self) -> (i64, i64) {
        let first = self.diffs.first().copied().unwrap_or(0);
        (first, self.diffs.last().copied().unwrap_or(0))
    }
}

/// `blocks` blocks of `cycles` cycles of each program at `period`, alternating.
fn compare(period: Duration, cycles: u64, blocks: usize) -> Result<Comparison, String> {
    let (mut alarmed, mut plain) = (Vec::new(), Vec::new());
    let (mut diffs, mut mean_diff) = (Vec::new(), 0.0);
    for _ in 0..blocks.max(1) {
        // The same tick for both: the temperatures inside their limits from the first cycle.
        let a = block::<Alarmed1k>(period, cycles, |ctx| {
            if ctx.cycle == 1 {
                ctx.gm.temperatures = [TEMPERATURE; 100];
            }
        })?;
        let p = block::<Plain1k>(period, cycles, |ctx| {
            if ctx.cycle == 1 {
                ctx.gm.temperatures = [TEMPERATURE; 100];
            }
        })?;
        diffs.push(a.median as i64 - p.median as i64);
        mean_diff += a.mean - p.mean;
        alarmed.push(a.median);
        plain.push(p.median);
    }
    diffs.sort_unstable();
    Ok(Comparison {
        alarmed: median(&mut alarmed),
        plain: median(&mut plain),
        mean_diff: mean_diff / diffs.len().max(1) as f64,
        diffs,
    })
}

/// One block's cycles after the warm-up: the median and the mean of their times, ns.
struct Block {
    median: u64,
    mean: f64,
}

/// A runtime of `T` for `cycles` cycles at `period` on this thread, `tick` its tick.
fn block<T>(
    period: Duration,
    cycles: u64,
    tick: impl FnMut(&mut Context<T>),
) -> Result<Block, String>
where
    T: GlobalMemory + Default + Clone + Send + 'static,
    T::Image: Send,
{
    let times = Arc::new(Mutex::new(Vec::<u64>::with_capacity(cycles as usize)));
    let sink = times.clone();
    let runtime = Runtime::<T>::builder()
        .period(period)
        .handle_signals(false)
        .max_cycles(cycles)
        .cycle_probe(move |t: &CycleTimes| {
            if let Ok(mut v) = sink.lock() {
                v.push(u64::try_from((t.end - t.start).as_nanos()).unwrap_or(u64::MAX));
            }
        })
        .build()
        .map_err(|e| format!("the runtime's settings: {e}"))?;
    runtime.run(tick).map_err(|e| format!("the runtime: {e}"))?;
    let mut times = times.lock().map_err(|_| "the probe panicked")?;
    let kept = times.get_mut(WARM_UP..).unwrap_or_default();
    if kept.is_empty() {
        return Err(format!(
            "{} cycles probed, no more than the warm-up",
            times.len()
        ));
    }
    let mean = kept.iter().sum::<u64>() as f64 / kept.len() as f64;
    Ok(Block {
        median: median(kept),
        mean,
    })
}

/// The evaluator alone over [`Alarmed1k`]'s alarms, none changing, against the same reads
/// without it, in alternating batches: the difference per alarm, ns.
fn evaluator_alone(batches: usize) -> Result<f64, String> {
    let gm = Alarmed1k {
        temperatures: [TEMPERATURE; 100],
        ..Alarmed1k::default()
    };
    let decls = Alarmed1k::ALARMS;
    let mut alarms = Alarms::from_decls(decls);
    let mut events: Vec<AlarmEvent> = Vec::new();
    let sample = |gm: &Alarmed1k, k: usize| -> Sample {
        let d = &decls[k];
        match d.index {
            0 => Sample::bool(gm.doors[d.leaf], false),
            _ => Sample {
                value: f64::from(gm.temperatures[d.leaf]),
                suppressed: false,
            },
        }
    };
    let mut now = 1_000_000_000i64;
    let (with, without) = side_by_side(
        batches,
        ITERS,
        || {
            now += 1_000_000;
            let gm = black_box(&gm);
            alarms.evaluate(now, |k| sample(gm, k), &mut events);
        },
        || {
            let gm = black_box(&gm);
            let mut sum = 0.0;
            for k in 0..decls.len() {
                sum += sample(gm, k).value;
            }
            black_box(sum);
        },
    );
    if !events.is_empty() {
        return Err(format!("{} transitions where none was due", events.len()));
    }
    Ok((with.as_secs_f64() - without.as_secs_f64()) * 1e9 / decls.len() as f64)
}
