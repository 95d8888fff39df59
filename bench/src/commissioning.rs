//! Group `commissioning`: what forces and traces cost a running program's cycle, and whether a
//! trace at 4 kHz loses a row.
//!
//! - `cycle_1k_traced_64_vs_untraced`: `plc_io::Runtime` on `Gm1k` (a segment, no I/O, an
//!   empty tick, period zero, as `cycle_1k_runtime_vs_memcpy` runs it), timed between ticks in
//!   batches of 2,000 cycles, with a trace of 64 of its basic values running (a real
//!   [`DynSegment::trace`] from this process, drained every 10 ms by a thread of its own)
//!   against the same with no trace, the two in alternating batches: the trace is started
//!   before each traced batch and ended after it. A traced batch starts only once the trace's
//!   ring has been written round once (its pages are in memory; a new trace's first pass
//!   through them costs page faults, a cost of starting it, not of running it).
//! - `cycle_1k_forced_32_vs_unforced`: the same with 32 values forced ([`DynSegment::force`]
//!   before each forced batch, [`DynSegment::release_all`] after it) against none.
//! - `..._1ms`: both again at a 1 ms period, each cycle's own time (start to end) from the
//!   runtime's cycle probe, in alternating windows of cycles; each side the median of its
//!   windows' medians. A cycle at a real period starts with cold caches: what a program that
//!   sleeps between cycles pays.
//! - `forces_apply_32_ns`, `trace_record_64_ns`: where the time goes, each step alone on a
//!   bare [`plc_io::shm::ShmOwner`] of `Gm1k`: `apply_forces` with 32 held (the cycle calls it
//!   twice), `record_traces` with one 64-value trace.
//! - `trace_4khz_lost`: a `Gm1k` program at 250 µs whose tick counts cycles into `int6`,
//!   traced (six values, that counter first) for 60 s (20 s with `--quick`) by a drainer at
//!   normal priority draining every 10 ms as `plc trace` does; the rows lost
//!   ([`TraceEvent::Lost`]) plus every gap or repeat in the rows' cycle numbers.

mod floor;

use super::gm1k::Gm1k;
use super::owner::leaf_paths;
use super::timing::median_per_iter;
use plc_core::GlobalMemory;
use plc_core::write::{Checked, Write};
use plc_io::shm::trace::{Trace, TraceEvent};
use plc_io::shm::{DynSegment, PathLocation, SharedGlobalMemory};
use std::fmt::Write as _;
use std::hint::black_box;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering::Relaxed};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// Values traced by the cost figure.
const TRACED: usize = 64;
/// Values forced by the cost figure.
const FORCED: usize = 32;
/// How often a drainer drains, as `plc trace` does.
const DRAIN_EVERY: Duration = Duration::from_millis(10);
/// Cycles per batch at period zero (as the cycle group's).
const BATCH: u32 = 2000;
/// The real period of the `_1ms` figures.
const PERIOD: Duration = Duration::from_millis(1);
/// The 4 kHz program's period.
const PERIOD_4KHZ: Duration = Duration::from_micros(250);

/// Runs the group with `batches` batches of each side at period zero; its `name: value` lines.
pub fn run(quick: bool, batches: usize) -> Result<String, String> {
    let mut out = String::new();
    let segment = format!("plc_bench_comm_{}", std::process::id());
    let windows = if quick { 5 } else { 15 };
    for (suffix, timing) in [
        ("", Timing::FlatOut { batches }),
        (
            "_1ms",
            Timing::Probed {
                windows,
                cycles: 1000,
            },
        ),
    ] {
        let _ = writeln!(
            out,
            "cycle_1k_commissioning{suffix}_samples: {}",
            timing.label()
        );
        let traced = compare(&format!("{segment}_t{suffix}"), timing, Load::Trace)?;
        traced.write(&mut out, "traced_64", "untraced", suffix);
        let forced = compare(&format!("{segment}_f{suffix}"), timing, Load::Forces)?;
        forced.write(&mut out, "forced_32", "unforced", suffix);
    }
    steps(&format!("{segment}_steps"), batches, &mut out)?;
    let seconds = if quick { 20 } else { 60 };
    lost_at_4khz(&format!("{segment}_4k"), seconds, quick, &mut out)?;
    Ok(out)
}

/// How a comparison times the cycle.
#[derive(Clone, Copy)]
enum Timing {
    /// Period zero; `batches` batches of [`BATCH`] cycles each side, timed between ticks.
    FlatOut { batches: usize },
    /// At [`PERIOD`]; `windows` windows of `cycles` cycles each side, each cycle's time from
    /// the probe.
    Probed { windows: usize, cycles: usize },
}

impl Timing {
    /// What the figures' samples are.
    fn label(self) -> String {
        match self {
            Timing::FlatOut { batches } => format!(
                "period zero, time between ticks, {batches} batches of {BATCH} cycles each side, \
                 alternating"
            ),
            Timing::Probed { windows, cycles } => format!(
                "1 ms period, each cycle's time from the probe, {windows} windows of {cycles} \
                 cycles each side, alternating"
            ),
        }
    }
}

/// What the loaded side holds.
#[derive(Clone, Copy)]
enum Load {
    Trace,
    Forces,
}

/// The side the cycles run on, with the window's number: `window << 2 | side`. Written by
/// the controlling thread only.
const SWITCHING: u64 = 0;
const PLAIN: u64 = 1;
const LOADED: u64 = 2;

/// What the cycle thread and the controlling thread share.
#[derive(Default)]
struct Phase {
    /// The current window and side (`window << 2 | side`).
    state: AtomicU64,
    /// The state of the last sample recorded and how many were recorded in it
    /// (`state << 32 | count`); written by the cycle thread only.
    progress: AtomicU64,
    /// The state the last tick saw (the probe's cycle is valid if it is still the state).
    at_tick: AtomicU64,
}

impl Phase {
    fn enter(&self, window: u64, side: u64) -> u64 {
        let s = window << 2 | side;
        self.state.store(s, Relaxed);
        s
    }

    /// Counts one sample of state `s` (the cycle thread).
    fn counted(&self, s: u64) {
        let p = self.progress.load(Relaxed);
        let next = if p >> 32 == s { p + 1 } else { s << 32 | 1 };
        self.progress.store(next, Relaxed);
    }

    /// Waits until `n` samples of state `s` are recorded.
    fn wait(&self, s: u64, n: u64, timeout: Duration) -> Result<(), String> {
        let end = Instant::now() + timeout;
        loop {
            let p = self.progress.load(Relaxed);
            if p >> 32 == s && p & 0xffff_ffff >= n {
                return Ok(());
            }
            if Instant::now() > end {
                return Err(format!(
                    "the program did not run {n} batches or cycles in {timeout:?}"
                ));
            }
            std::thread::sleep(Duration::from_micros(200));
        }
    }
}

/// The two sides of a comparison: the median per cycle of each.
struct Compared {
    plain: Duration,
    loaded: Duration,
}

impl Compared {
    fn write(&self, out: &mut String, loaded: &str, plain: &str, suffix: &str) {
        let (l, p) = (self.loaded.as_nanos(), self.plain.as_nanos());
        let _ = writeln!(out, "cycle_1k_{loaded}{suffix}_ns: {l}");
        let _ = writeln!(out, "cycle_1k_{plain}{suffix}_ns: {p}");
        let _ = writeln!(
            out,
            "cycle_1k_{loaded}_vs_{plain}{suffix}: {:.2}",
            super::timing::ratio(self.loaded, self.plain)
        );
    }
}

/// Runs `Gm1k` in a `Runtime` on segment `name` on a thread of its own and compares its cycle
/// with and without `load`, in alternation.
fn compare(name: &str, timing: Timing, load: Load) -> Result<Compared, String> {
    let phase = Arc::new(Phase::default());
    let samples = Arc::new(Mutex::new(Vec::<(u64, Duration)>::with_capacity(1 << 16)));
    let mut builder = plc_io::Runtime::<Gm1k>::builder()
        .segment(name)
        .handle_signals(false);
    let (rounds, needed) = match timing {
        Timing::FlatOut { batches } => {
            builder = builder.period(Duration::ZERO);
            (batches, 1)
        }
        Timing::Probed { windows, cycles } => {
            let (phase, sink) = (phase.clone(), samples.clone());
            builder = builder.period(PERIOD).cycle_probe(move |t| {
                let s = phase.state.load(Relaxed);
                if s & 3 != SWITCHING && phase.at_tick.load(Relaxed) == s {
                    if let Ok(mut v) = sink.lock() {
                        v.push((s, t.end - t.start));
                    }
                    phase.counted(s);
                }
            });
            (windows, cycles as u64)
        }
    };
    let stop = builder.stop_handle();
    let runtime = builder
        .build()
        .map_err(|e| format!("the runtime's settings: {e}"))?;
    let flat = matches!(timing, Timing::FlatOut { .. });
    let (tick_phase, sink) = (phase.clone(), samples.clone());
    let program = std::thread::Builder::new()
        .name("commissioning-cycle".into())
        .spawn(move || {
            // Period zero: batches of BATCH cycles timed from tick to tick, each valid if the
            // state did not change during it. A countdown, not a division, as the cycle
            // group's tick.
            let (mut left, mut began, mut batch_state) = (0u32, None::<Instant>, SWITCHING);
            runtime.run(|_| {
                let s = tick_phase.state.load(Relaxed);
                if !flat {
                    tick_phase.at_tick.store(s, Relaxed);
                    return;
                }
                if left == 0 {
                    if let Some(start) = began
                        && s == batch_state
                        && s & 3 != SWITCHING
                    {
                        if let Ok(mut v) = sink.lock() {
                            v.push((s, start.elapsed() / BATCH));
                        }
                        tick_phase.counted(s);
                    }
                    batch_state = s;
                    left = BATCH;
                    began = Some(Instant::now());
                }
                left -= 1;
            })
        })
        .map_err(|e| format!("the cycle's thread: {e}"))?;
    let controlled = control(name, &phase, rounds, needed, load);
    stop.stop();
    let ran = program.join();
    controlled?;
    match ran {
        Ok(Ok(_)) => {}
        Ok(Err(e)) => return Err(format!("the runtime: {e}")),
        Err(_) => return Err("the cycle's thread panicked".into()),
    }
    let samples = samples.lock().map_err(|_| "the probe panicked")?;
    let side = |side: u64| window_medians(&samples, side);
    let (plain, loaded) = (side(PLAIN), side(LOADED));
    Ok(Compared {
        plain: median(plain),
        loaded: median(loaded),
    })
}

/// The median of each window's samples of `side`.
fn window_medians(samples: &[(u64, Duration)], side: u64) -> Vec<Duration> {
    let mut windows: Vec<(u64, Vec<Duration>)> = Vec::new();
    for &(s, d) in samples.iter().filter(|(s, _)| s & 3 == side) {
        match windows.last_mut() {
            Some((w, v)) if *w == s => v.push(d),
            _ => windows.push((s, vec![d])),
        }
    }
    windows.into_iter().map(|(_, v)| median(v)).collect()
}

fn median(mut v: Vec<Duration>) -> Duration {
    v.sort();
    v.get(v.len() / 2).copied().unwrap_or_default()
}

/// Alternates `rounds` times: a window without the load, then one with it, each ended once
/// `needed` samples of it are in.
fn control(
    name: &str,
    phase: &Phase,
    rounds: usize,
    needed: u64,
    load: Load,
) -> Result<(), String> {
    let shm = |e: plc_io::shm::ShmError| e.to_string();
    let seg = wait_attach(name)?;
    let paths = leaf_paths(&seg);
    let forces = match load {
        Load::Forces => forces_of(&seg, &paths)?,
        Load::Trace => Vec::new(),
    };
    let traced = traced_paths(&seg, &paths)?;
    let timeout = Duration::from_secs(60);
    let mut window = 0;
    for _ in 0..rounds {
        window += 1;
        let s = phase.enter(window, PLAIN);
        phase.wait(s, needed, timeout)?;
        phase.enter(window, SWITCHING);
        let drainer = match load {
            Load::Forces => {
                seg.force(&forces).map_err(shm)?;
                None
            }
            Load::Trace => Some(Drainer::start(name, &traced)?),
        };
        window += 1;
        let s = phase.enter(window, LOADED);
        phase.wait(s, needed, timeout)?;
        phase.enter(window, SWITCHING);
        match drainer {
            None => seg.release_all(false).map_err(shm)?,
            Some(d) => d.stop()?,
        }
    }
    Ok(())
}

/// Attaches to `name` once its owner has published a cycle.
fn wait_attach(name: &str) -> Result<DynSegment, String> {
    let end = Instant::now() + Duration::from_secs(30);
    loop {
        if let Ok(seg) = DynSegment::attach(name)
            && seg.status().cycle_count > 0
        {
            return Ok(seg);
        }
        if Instant::now() > end {
            return Err(format!("the program of `{name}` did not come up in 30 s"));
        }
        std::thread::sleep(Duration::from_millis(5));
    }
}

/// [`TRACED`] basic values spread over the declaration (a STRING cannot be traced).
fn traced_paths(seg: &DynSegment, paths: &[String]) -> Result<Vec<PathLocation>, String> {
    let numbers: Vec<&String> = paths.iter().filter(|p| !p.starts_with("text")).collect();
    spread(&numbers, TRACED)
        .map(|p| seg.locate(p).map_err(|e| e.to_string()))
        .collect()
}

/// [`FORCED`] basic values spread over the declaration, each forced to the value it has.
fn forces_of(seg: &DynSegment, paths: &[String]) -> Result<Vec<Checked>, String> {
    let all: Vec<&String> = paths.iter().collect();
    let image = seg.snapshot_bytes().map_err(|e| e.to_string())?;
    spread(&all, FORCED)
        .map(|p| {
            let at = seg.locate(p).map_err(|e| e.to_string())?;
            let value = at
                .var
                .value_in(&image, 0)
                .ok_or_else(|| format!("`{p}` has no value"))?;
            seg.check_force(Write {
                index: at.index,
                leaf: at.leaf,
                value,
            })
            .map_err(|e| e.to_string())
        })
        .collect()
}

/// Where the forced and traced values are in the image, for [`floor`].
#[derive(Clone)]
struct Places {
    forced: Vec<floor::Place>,
    traced: Vec<floor::Place>,
}

/// `n` of `items`, evenly spaced.
fn spread<'a>(items: &[&'a String], n: usize) -> impl Iterator<Item = &'a String> {
    let step = (items.len() / n).max(1);
    items.iter().step_by(step).take(n).copied()
}

/// A tool tracing on a thread of its own: attached, its trace started, draining every
/// [`DRAIN_EVERY`] until stopped.
struct Drainer {
    stop: Arc<AtomicBool>,
    thread: std::thread::JoinHandle<Result<(), String>>,
}

impl Drainer {
    /// Starts the trace; returns once its ring has been written round once.
    fn start(name: &str, values: &[PathLocation]) -> Result<Drainer, String> {
        let stop = Arc::new(AtomicBool::new(false));
        let (ready_tx, ready_rx) = std::sync::mpsc::channel();
        let (name, values, flag) = (name.to_string(), values.to_vec(), stop.clone());
        let thread = std::thread::Builder::new()
            .name("commissioning-drainer".into())
            .spawn(move || {
                let traced = DynSegment::attach(&name).and_then(|seg| {
                    let trace = seg.trace(&values, 1)?;
                    Ok((seg, trace))
                });
                let (_seg, mut trace) = match traced {
                    Ok(t) => t,
                    Err(e) => {
                        let _ = ready_tx.send(());
                        return Err(e.to_string());
                    }
                };
                let (mut events, mut written, mut ready) = (Vec::new(), 0u64, false);
                while !flag.load(Relaxed) {
                    trace.drain(&mut events, usize::MAX);
                    written += events.iter().map(rows_of).sum::<u64>();
                    events.clear();
                    if !ready && written > trace.capacity() {
                        ready = true;
                        let _ = ready_tx.send(());
                    }
                    std::thread::sleep(DRAIN_EVERY);
                }
                Ok(())
            })
            .map_err(|e| format!("the drainer's thread: {e}"))?;
        let drainer = Drainer { stop, thread };
        if ready_rx.recv_timeout(Duration::from_secs(60)).is_err() || drainer.thread.is_finished() {
            return drainer.stop().and(Err("the trace did not start".into()));
        }
        Ok(drainer)
    }

    /// Ends the trace (the tool leaves), and gives the owner time to drop it.
    fn stop(self) -> Result<(), String> {
        self.stop.store(true, Relaxed);
        let done = self
            .thread
            .join()
            .map_err(|_| "the drainer panicked".to_string())?;
        // The connection's thread marks the trace left when it sees the hang-up; the cycle
        // drops it at its next row.
        std::thread::sleep(Duration::from_millis(20));
        done
    }
}

/// The rows an event stands for, read or lost.
fn rows_of(e: &TraceEvent) -> u64 {
    match e {
        TraceEvent::Row(_) => 1,
        TraceEvent::Lost(n) => *n,
    }
}

/// `apply_forces` with [`FORCED`] held and `record_traces` with one [`TRACED`]-value trace,
/// each alone on a bare owner of `Gm1k`, a tool on another thread forcing and tracing.
fn steps(name: &str, batches: usize, out: &mut String) -> Result<(), String> {
    let shm = |e: plc_io::shm::ShmError| e.to_string();
    let mut owner = SharedGlobalMemory::<Gm1k>::create(name).map_err(shm)?;
    let mut gm = Gm1k::default();
    let mut image = Box::new(gm.to_image());
    owner.publish_image(&image).map_err(shm)?;
    let (tool_tx, tool_rx) = std::sync::mpsc::channel::<Result<Places, String>>();
    let (done_tx, done_rx) = std::sync::mpsc::channel::<()>();
    let tool_name = name.to_string();
    let tool = std::thread::spawn(move || {
        let held = (|| {
            let seg = DynSegment::attach(&tool_name).map_err(|e| e.to_string())?;
            let paths = leaf_paths(&seg);
            let forces = forces_of(&seg, &paths)?;
            seg.force(&forces).map_err(|e| e.to_string())?;
            let traced = traced_paths(&seg, &paths)?;
            let trace = seg.trace(&traced, 1).map_err(|e| e.to_string())?;
            let place = |at: &PathLocation| (at.var.offset, at.var.size);
            let places = Places {
                // The paths `forces_of` chose.
                forced: spread(&paths.iter().collect::<Vec<_>>(), FORCED)
                    .map(|p| seg.locate(p).map(|at| place(&at)))
                    .collect::<Result<_, _>>()
                    .map_err(|e| e.to_string())?,
                traced: traced.iter().map(place).collect(),
            };
            Ok::<(DynSegment, Trace, Places), String>((seg, trace, places))
        })();
        let _ = tool_tx.send(held.as_ref().map(|h| h.2.clone()).map_err(Clone::clone));
        // Attached until the steps are timed: the trace records while it is.
        let _ = done_rx.recv();
        drop(held);
    });
    // The owner's side of the tool's requests: applied, published, answered.
    let end = Instant::now() + Duration::from_secs(30);
    let told = loop {
        owner.apply_requests(&mut gm);
        gm.store_image(&mut image);
        owner.publish_image(&image).map_err(shm)?;
        if let Ok(told) = tool_rx.try_recv() {
            break told;
        }
        if Instant::now() > end {
            break Err("the tool did not force and trace in 30 s".into());
        }
        std::thread::sleep(Duration::from_micros(100));
    };
    // The trace's recording was queued before its answer: this takes it in.
    owner.apply_requests(&mut gm);
    let timed = told.and_then(|places| {
        if owner.forces_held() != FORCED {
            return Err(format!("{} forces held, not {FORCED}", owner.forces_held()));
        }
        let apply = median_per_iter(batches, BATCH, || owner.apply_forces(black_box(&mut gm)));
        let mut cycle = 0u64;
        // Once round the ring first (16,384 rows: a bare owner's period is zero).
        for _ in 0..16_384 {
            cycle += 1;
            owner.record_traces(&image, cycle, cycle);
        }
        let record = median_per_iter(batches, BATCH, || {
            cycle += 1;
            owner.record_traces(black_box(&image), cycle, cycle);
        });
        let bytes = zerocopy::IntoBytes::as_mut_bytes(&mut *image);
        let forces_floor = floor::forces(bytes, &places.forced, batches, BATCH);
        let trace_floor = floor::trace(bytes, &places.traced, batches, BATCH);
        Ok((apply, record, forces_floor, trace_floor))
    });
    let _ = done_tx.send(());
    let _ = tool.join();
    let (apply, record, forces_floor, trace_floor) = timed?;
    let _ = writeln!(out, "forces_apply_32_ns: {}", apply.as_nanos());
    let _ = writeln!(out, "trace_record_64_ns: {}", record.as_nanos());
    let _ = writeln!(out, "forces_floor_32_twice_ns: {}", forces_floor.as_nanos());
    let _ = writeln!(out, "trace_floor_64_ns: {}", trace_floor.as_nanos());
    Ok(())
}

/// A `Gm1k` program at 4 kHz traced for `seconds` by a drainer at normal priority.
fn lost_at_4khz(name: &str, seconds: u64, quick: bool, out: &mut String) -> Result<(), String> {
    let runtime = plc_io::Runtime::<Gm1k>::builder()
        .segment(name)
        .period(PERIOD_4KHZ)
        .handle_signals(false)
        .build()
        .map_err(|e| format!("the runtime's settings: {e}"))?;
    let stop = runtime.stop_handle();
    let program = std::thread::Builder::new()
        .name("commissioning-4khz".into())
        .spawn(move || {
            runtime.run(|ctx| {
                let gm = &mut ctx.gm;
                gm.int6 = ctx.cycle;
                gm.word0 = gm.word0.wrapping_add(1);
                gm.real0 += 0.5;
                gm.flag0 = !gm.flag0;
                gm.samples[7] = (ctx.cycle % 1000) as f32;
            })
        })
        .map_err(|e| format!("the 4 kHz program's thread: {e}"))?;
    let traced = (|| {
        let seg = wait_attach(name)?;
        let at = |p: &str| seg.locate(p).map_err(|e| e.to_string());
        let values = [
            at("int6")?,
            at("word0")?,
            at("mapped3")?,
            at("real0")?,
            at("flag0")?,
            at("samples[7]")?,
        ];
        let trace = seg.trace(&values, 1).map_err(|e| e.to_string())?;
        Ok::<_, String>(drain_for(trace, Duration::from_secs(seconds)))
    })();
    stop.stop();
    let ran = program.join();
    let tally = traced?;
    match ran {
        Ok(Ok(_)) => {}
        Ok(Err(e)) => return Err(format!("the 4 kHz runtime: {e}")),
        Err(_) => return Err("the 4 kHz program's thread panicked".into()),
    }
    let note = if quick { " (--quick; 60 without)" } else { "" };
    let _ = writeln!(
        out,
        "trace_4khz_lost: {} ({} lost, {} gaps, {} repeats)",
        tally.lost + tally.gaps + tally.repeats,
        tally.lost,
        tally.gaps,
        tally.repeats
    );
    let _ = writeln!(out, "trace_4khz_seconds: {seconds}{note}");
    let _ = writeln!(out, "trace_4khz_rows: {}", tally.rows);
    let _ = writeln!(out, "trace_4khz_wrong_counter: {}", tally.wrong_value);
    let _ = writeln!(out, "trace_4khz_ring_rows: {}", tally.capacity);
    let _ = writeln!(
        out,
        "trace_4khz_most_rows_per_drain: {}",
        tally.most_per_drain
    );
    let _ = writeln!(
        out,
        "trace_4khz_longest_drain_gap_ms: {:.1}",
        tally.longest_gap.as_secs_f64() * 1e3
    );
    Ok(())
}

/// What a drainer saw.
#[derive(Default)]
struct Tally {
    rows: u64,
    lost: u64,
    gaps: u64,
    repeats: u64,
    wrong_value: u64,
    capacity: u64,
    most_per_drain: usize,
    longest_gap: Duration,
}

/// Drains `trace` every [`DRAIN_EVERY`] for `length`, checking each row's cycle number
/// against the last one's and the traced counter (the first value) against the row's cycle.
fn drain_for(mut trace: Trace, length: Duration) -> Tally {
    let mut tally = Tally {
        capacity: trace.capacity(),
        ..Tally::default()
    };
    let (mut events, mut last_cycle) = (Vec::new(), None::<u64>);
    let start = Instant::now();
    let mut last_drain = start;
    loop {
        let now = Instant::now();
        tally.longest_gap = tally.longest_gap.max(now - last_drain);
        last_drain = now;
        let n = trace.drain(&mut events, usize::MAX);
        tally.most_per_drain = tally.most_per_drain.max(n);
        for e in events.drain(..) {
            match e {
                TraceEvent::Lost(n) => tally.lost += n,
                TraceEvent::Row(r) => {
                    tally.rows += 1;
                    match last_cycle {
                        Some(c) if r.cycle == c + 1 => {}
                        Some(c) if r.cycle <= c => tally.repeats += 1,
                        Some(_) => tally.gaps += 1,
                        None => {}
                    }
                    last_cycle = Some(r.cycle);
                    if r.values.first() != Some(&plc_core::Value::UInt(r.cycle)) {
                        tally.wrong_value += 1;
                    }
                }
            }
        }
        if now - start >= length {
            return tally;
        }
        std::thread::sleep(DRAIN_EVERY);
    }
}
