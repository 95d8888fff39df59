//! The cost figures' comparison: `Gm1k` run by a `Runtime` on a thread of its own, its cycle
//! timed with and without a load (forces or a trace) in alternating windows, at period zero
//! or at a real period through the cycle probe.

use super::super::gm1k::Gm1k;
use super::super::owner::leaf_paths;
use super::tool::{Drainer, forces_of, traced_paths, wait_attach};
use std::fmt::Write as _;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// Cycles per batch at period zero (as the cycle group's).
pub const BATCH: u32 = 2000;
/// The real period of the `_1ms` figures.
const PERIOD: Duration = Duration::from_millis(1);

/// How a comparison times the cycle.
#[derive(Clone, Copy)]
pub enum Timing {
    /// Period zero; `batches` batches of [`BATCH`] cycles each side, timed between ticks.
    FlatOut { batches: usize },
    /// At [`PERIOD`]; `windows` windows of `cycles` cycles each side, each cycle's time from
    /// the probe.
    Probed { windows: usize, cycles: usize },
}

impl Timing {
    /// What the figures' samples are.
    pub fn label(self) -> String {
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
pub enum Load {
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
pub struct Compared {
    pub plain: Duration,
    pub loaded: Duration,
}

impl Compared {
    pub fn write(&self, out: &mut String, loaded: &str, plain: &str, suffix: &str) {
        let (l, p) = (self.loaded.as_nanos(), self.plain.as_nanos());
        let _ = writeln!(out, "cycle_1k_{loaded}{suffix}_ns: {l}");
        let _ = writeln!(out, "cycle_1k_{plain}{suffix}_ns: {p}");
        let _ = writeln!(
            out,
            "cycle_1k_{loaded}_vs_{plain}{suffix}: {:.2}",
            super::super::timing::ratio(self.loaded, self.plain)
        );
    }
}

/// Runs `Gm1k` in a `Runtime` on segment `name` on a thread of its own and compares its cycle
/// with and without `load`, in alternation.
pub fn compare(name: &str, timing: Timing, load: Load) -> Result<Compared, String> {
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
