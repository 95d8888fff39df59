//! The tool's side of the cost figures: which values it forces and traces, and a tool that
//! traces them on a thread of its own, draining as `plc trace` does.

use plc_core::write::{Checked, Write};
use plc_io::shm::trace::TraceEvent;
use plc_io::shm::{DynSegment, PathLocation, ShmError};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering::Relaxed};
use std::time::{Duration, Instant};

/// Values traced by the cost figure.
pub const TRACED: usize = 64;
/// Values forced by the cost figure.
pub const FORCED: usize = 32;
/// How often a drainer drains, as `plc trace` does.
pub const DRAIN_EVERY: Duration = Duration::from_millis(10);

/// Attaches to `name` once its owner has published a cycle.
pub fn wait_attach(name: &str) -> Result<DynSegment, String> {
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
pub fn traced_paths(seg: &DynSegment, paths: &[String]) -> Result<Vec<PathLocation>, String> {
    let numbers: Vec<&String> = paths.iter().filter(|p| !p.starts_with("text")).collect();
    spread(&numbers, TRACED)
        .map(|p| seg.locate(p).map_err(|e| e.to_string()))
        .collect()
}

/// [`FORCED`] basic values spread over the declaration, each forced to the value it has.
pub fn forces_of(seg: &DynSegment, paths: &[String]) -> Result<Vec<Checked>, String> {
    checked_values(seg, paths, FORCED, DynSegment::check_force)
}

/// `n` basic values spread over the declaration, each at the value it has, checked by
/// `check` (as a force or as a write).
pub fn checked_values(
    seg: &DynSegment,
    paths: &[String],
    n: usize,
    check: impl Fn(&DynSegment, Write) -> Result<Checked, ShmError>,
) -> Result<Vec<Checked>, String> {
    let all: Vec<&String> = paths.iter().collect();
    let image = seg.snapshot_bytes().map_err(|e| e.to_string())?;
    spread(&all, n)
        .map(|p| {
            let at = seg.locate(p).map_err(|e| e.to_string())?;
            let value = at
                .var
                .value_in(&image, 0)
                .ok_or_else(|| format!("`{p}` has no value"))?;
            let write = Write {
                index: at.index,
                leaf: at.leaf,
                value,
            };
            check(seg, write).map_err(|e| format!("`{p}`: {e}"))
        })
        .collect()
}

/// `n` of `items`, evenly spaced.
pub fn spread<'a>(items: &[&'a String], n: usize) -> impl Iterator<Item = &'a String> {
    let step = (items.len() / n).max(1);
    items.iter().step_by(step).take(n).copied()
}

/// A tool tracing on a thread of its own: attached, its trace started, draining every
/// [`DRAIN_EVERY`] until stopped.
pub struct Drainer {
    stop: Arc<AtomicBool>,
    thread: std::thread::JoinHandle<Result<(), String>>,
}

impl Drainer {
    /// Starts the trace; returns once its ring has been written round once.
    pub fn start(name: &str, values: &[PathLocation]) -> Result<Drainer, String> {
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
    pub fn stop(self) -> Result<(), String> {
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
pub fn rows_of(e: &TraceEvent) -> u64 {
    match e {
        TraceEvent::Row(_) => 1,
        TraceEvent::Lost(n) => *n,
    }
}
