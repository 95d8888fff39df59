//! `flood_*`: what a tool that floods a running program with requests costs its cycle, forces
//! against writes of as many values.
//!
//! `Gm1k` runs in a `Runtime` at a 1 ms period on a thread of its own. After a quiet second,
//! [`TOOLS`] tools, each attached on a thread of its own, send requests of
//! [`MAX_WRITES`] values back to back for the flood's seconds, each waiting for its answer
//! before the next (as `plc force` and `plc set` do): first requests that force the values,
//! then, with every force released, requests that write them. The values are
//! [`DISTINCT`] basic values spread over the declaration, each named
//! `MAX_WRITES / DISTINCT` times (at most [`MAX_FORCES`] forces are held at once, so a request
//! of 1,024 forces re-forces what is held: the flood an attacker with the owner's uid sends).
//!
//! Each side's figures come from the status block (cycles, overruns, values applied) and the
//! runtime's cycle probe (each cycle's time, start to end). `flood_force_vs_write_ns_per_value`
//! is what a forced value costs the cycle against a written one: each side's cycle time above
//! the quiet second's, summed over the flood, per value applied. Target: 1 at most, and no
//! more overruns with forces than with writes.

use super::super::gm1k::Gm1k;
use super::super::owner::leaf_paths;
use super::tool::{checked_values, wait_attach};
use plc_core::write::Checked;
use plc_io::shm::limits::{MAX_FORCES, MAX_WRITES};
use plc_io::shm::{DynSegment, ShmError};
use std::fmt::Write as _;
use std::sync::atomic::{AtomicU8, Ordering::Relaxed};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// Tools flooding at once.
pub const TOOLS: usize = 4;
/// Distinct values a request names.
pub const DISTINCT: usize = 256;
/// The program's period.
const PERIOD: Duration = Duration::from_millis(1);

/// What the cycle probe records a cycle under.
const IDLE: u8 = 0;
const QUIET: u8 = 1;
const FLOODED: u8 = 2;

/// What the tools send.
#[derive(Clone, Copy, PartialEq)]
enum Kind {
    Forces,
    Writes,
}

impl Kind {
    fn label(self) -> &'static str {
        match self {
            Kind::Forces => "force",
            Kind::Writes => "write",
        }
    }
}

/// One side's figures.
struct Side {
    cycles: u64,
    overruns: u64,
    /// Values applied (forced or written).
    values: u64,
    /// Requests refused (a full queue, say); a refused request costs the cycle nothing.
    refused: u64,
    /// Each flooded cycle's time, sorted.
    cycle_times: Vec<Duration>,
    /// The quiet second's mean cycle.
    quiet_mean: Duration,
}

impl Side {
    /// The cycle time above the quiet mean, summed over the flood, per value applied.
    fn ns_per_value(&self) -> f64 {
        let quiet = self.quiet_mean.as_secs_f64();
        let above: f64 = (self.cycle_times.iter())
            .map(|t| (t.as_secs_f64() - quiet).max(0.0))
            .sum();
        above * 1e9 / self.values.max(1) as f64
    }

    fn percentile_us(&self, p: usize) -> f64 {
        let n = self.cycle_times.len();
        let at = (n * p / 100).min(n.saturating_sub(1));
        self.cycle_times
            .get(at)
            .map_or(0.0, |t| t.as_secs_f64() * 1e6)
    }

    fn write(&self, out: &mut String, kind: Kind) {
        let k = kind.label();
        let _ = writeln!(
            out,
            "flood_{k}_1024_overruns: {} (of {} cycles)",
            self.overruns, self.cycles
        );
        let _ = writeln!(out, "flood_{k}_1024_values_applied: {}", self.values);
        let _ = writeln!(out, "flood_{k}_1024_refused: {}", self.refused);
        let _ = writeln!(
            out,
            "flood_{k}_1024_cycle_p50_us: {:.0}",
            self.percentile_us(50)
        );
        let _ = writeln!(
            out,
            "flood_{k}_1024_cycle_p99_us: {:.0}",
            self.percentile_us(99)
        );
        let _ = writeln!(
            out,
            "flood_{k}_1024_ns_per_value: {:.0}",
            self.ns_per_value()
        );
    }
}

/// Floods `Gm1k` on segments named from `name` for `seconds`, forces then writes; the
/// figures' `name: value` lines.
pub fn flood(name: &str, seconds: u64, out: &mut String) -> Result<(), String> {
    let _ = writeln!(
        out,
        "flood_samples: 1 ms period, {TOOLS} tools each sending requests of {MAX_WRITES} values \
         ({DISTINCT} values, each {} times) back to back for {seconds} s",
        MAX_WRITES / DISTINCT
    );
    let forced = side(&format!("{name}_f"), seconds, Kind::Forces)?;
    let written = side(&format!("{name}_w"), seconds, Kind::Writes)?;
    forced.write(out, Kind::Forces);
    written.write(out, Kind::Writes);
    let _ = writeln!(
        out,
        "flood_force_vs_write_ns_per_value: {:.2}",
        forced.ns_per_value() / written.ns_per_value().max(1e-9)
    );
    Ok(())
}

/// One side: a program of its own, a quiet second, then the flood.
fn side(name: &str, seconds: u64, kind: Kind) -> Result<Side, String> {
    let phase = Arc::new(AtomicU8::new(IDLE));
    let samples = Arc::new(Mutex::new(Vec::<(u8, Duration)>::with_capacity(
        (seconds as usize + 2) * 1100,
    )));
    let (probe_phase, sink) = (phase.clone(), samples.clone());
    let builder = plc_io::Runtime::<Gm1k>::builder()
        .segment(name)
        .handle_signals(false)
        .period(PERIOD)
        .cycle_probe(move |t| {
            let p = probe_phase.load(Relaxed);
            if p != IDLE
                && let Ok(mut v) = sink.lock()
            {
                v.push((p, t.end - t.start));
            }
        });
    let stop = builder.stop_handle();
    let runtime = builder
        .build()
        .map_err(|e| format!("the runtime's settings: {e}"))?;
    let program = std::thread::Builder::new()
        .name("flood-cycle".into())
        .spawn(move || runtime.run(|_| {}))
        .map_err(|e| format!("the cycle's thread: {e}"))?;
    let flooded = run_flood(name, seconds, kind, &phase);
    stop.stop();
    let ran = program.join();
    let (cycles, overruns, values, refused) = flooded?;
    match ran {
        Ok(Ok(_)) => {}
        Ok(Err(e)) => return Err(format!("the runtime: {e}")),
        Err(_) => return Err("the cycle's thread panicked".into()),
    }
    let samples = samples.lock().map_err(|_| "the probe panicked")?;
    let of = |p: u8| -> Vec<Duration> {
        let mut v: Vec<Duration> = (samples.iter())
            .filter(|(q, _)| *q == p)
            .map(|(_, d)| *d)
            .collect();
        v.sort();
        v
    };
    let quiet = of(QUIET);
    let quiet_mean = quiet.iter().sum::<Duration>() / (quiet.len().max(1) as u32);
    Ok(Side {
        cycles,
        overruns,
        values,
        refused,
        cycle_times: of(FLOODED),
        quiet_mean,
    })
}

/// The quiet second and the flood against the running program on `name`: cycles, overruns
/// and values applied during the flood, and the requests refused.
fn run_flood(
    name: &str,
    seconds: u64,
    kind: Kind,
    phase: &AtomicU8,
) -> Result<(u64, u64, u64, u64), String> {
    let shm = |e: ShmError| e.to_string();
    let seg = wait_attach(name)?;
    let paths = leaf_paths(&seg);
    let values: Vec<Checked> = match kind {
        Kind::Forces => checked_values(&seg, &paths, DISTINCT, DynSegment::check_force)?,
        Kind::Writes => checked_values(&seg, &paths, DISTINCT, DynSegment::check_write)?,
    };
    if DISTINCT > MAX_FORCES || values.len() != DISTINCT {
        return Err(format!("{} values to flood, not {DISTINCT}", values.len()));
    }
    let request: Vec<Checked> = values.iter().cycle().take(MAX_WRITES).copied().collect();
    phase.store(QUIET, Relaxed);
    std::thread::sleep(Duration::from_secs(1));
    let before = seg.status();
    phase.store(FLOODED, Relaxed);
    let end = Instant::now() + Duration::from_secs(seconds);
    let refused: Result<u64, String> = std::thread::scope(|s| {
        let tools: Vec<_> = (0..TOOLS)
            .map(|_| {
                let request = &request;
                s.spawn(move || -> Result<u64, String> {
                    let tool = DynSegment::attach(name).map_err(shm)?;
                    let mut refused = 0;
                    while Instant::now() < end {
                        let sent = match kind {
                            Kind::Forces => tool.force(request),
                            Kind::Writes => tool.write_checked(request),
                        };
                        refused += u64::from(sent.is_err());
                    }
                    Ok(refused)
                })
            })
            .collect();
        tools
            .into_iter()
            .map(|t| t.join().map_err(|_| "a tool panicked".to_string())?)
            .sum()
    });
    phase.store(IDLE, Relaxed);
    let after = seg.status();
    if kind == Kind::Forces {
        seg.release_all(false).map_err(shm)?;
    }
    Ok((
        after.cycle_count - before.cycle_count,
        after.stats.overruns - before.stats.overruns,
        after.writes_applied - before.writes_applied,
        refused?,
    ))
}
