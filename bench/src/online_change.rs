//! The online change's figures: the counter test module run by the runtime as `plc run` runs
//! it (shared memory, no I/O), changed to a build with the same variables and to one with
//! another layout, at 1 kHz and 4 kHz. Each cycle's start is recorded in its tick; the
//! longest interval between two starts around the swap, over the median interval, is
//! `online_change_cycle_ratio`, and an interval longer than one and a half periods is a late
//! cycle. The swap's work on the cycle thread is `online_change_swap_us`, and the preparation
//! off it (checks, the trial child, loading, planning) `online_change_prepare_ms`.
//!
//! The modules are found beside this program: `cargo build --release -p
//! plc-test-module-counter -p plc-test-module-counter-v2` first.

use plc_io::module::trial::Trial;
use plc_io::module::{Module, ModuleMemory, prepare};
use plc_io::{Runtime, SwapEvent};
use std::fmt::Write;
use std::path::PathBuf;
use std::sync::Arc;
use std::time::{Duration, Instant};

fn module(name: &str) -> Result<PathBuf, String> {
    let exe = std::env::current_exe().map_err(|e| e.to_string())?;
    let lib = exe.with_file_name(name);
    if lib.is_file() {
        Ok(lib)
    } else {
        Err(format!(
            "{} is missing: `cargo build --release -p plc-test-module-counter -p \
             plc-test-module-counter-v2` first",
            lib.display()
        ))
    }
}

/// What one change measured.
struct Measured {
    prepare: Duration,
    swap: Duration,
    ratio: f64,
    /// Late cycles among the seven around the swap.
    late_around: usize,
    /// Late cycles in the whole run, the swap's included: the machine's own noise.
    late: usize,
    cycles: usize,
}

/// Runs the counter at `period`, changes it to `to` after a second, runs a second more.
fn one(period: Duration, to: &str, segment: &str) -> Result<Measured, String> {
    let trial = Trial::this_program().map_err(|e| e.to_string())?;
    let first =
        Arc::new(Module::load(module("libcounter.so")?, &trial).map_err(|e| e.to_string())?);
    let gm = ModuleMemory::initial(first.clone()).map_err(|e| e.to_string())?;
    let cycles = (2 * Duration::from_secs(1).as_nanos() / period.as_nanos()) as u64;
    let (swaps, rx) = std::sync::mpsc::channel();
    let runtime = Runtime::for_memory(gm)
        .period(period)
        .segment(segment)
        .handle_signals(false)
        .max_cycles(cycles)
        .swaps(rx)
        .build()
        .map_err(|e| e.to_string())?;
    let to = module(to)?;
    let running = first.descriptor().clone();
    let changer = std::thread::spawn(move || -> Result<(Duration, SwapEvent), String> {
        std::thread::sleep(Duration::from_secs(1));
        let began = Instant::now();
        let next = Arc::new(Module::load(&to, &trial).map_err(|e| e.to_string())?);
        let prepared =
            prepare(&running, next, &["last_now_us".into()], 100).map_err(|r| format!("{r:?}"))?;
        let prepare = began.elapsed();
        swaps.send(prepared.swap).map_err(|e| e.to_string())?;
        let swapped = prepared
            .events
            .recv_timeout(Duration::from_secs(10))
            .map_err(|e| e.to_string())?;
        Ok((prepare, swapped))
    });
    let mut starts: Vec<i64> = Vec::with_capacity(cycles as usize + 1);
    runtime
        .run(|ctx| {
            starts.push(ctx.now().as_nanos());
            plc_io::module::tick(ctx);
        })
        .map_err(|e| e.to_string())?;
    let (prepare, event) = changer.join().map_err(|_| "the changer panicked")??;
    let SwapEvent::Swapped { cycle, took, .. } = event else {
        return Err(format!("the change was not made: {event:?}"));
    };
    let intervals: Vec<i64> = starts.windows(2).map(|w| w[1] - w[0]).collect();
    let mut sorted = intervals.clone();
    sorted.sort_unstable();
    let median = sorted[sorted.len() / 2].max(1) as f64;
    let at = (cycle as usize).saturating_sub(2);
    let around = &intervals[at.saturating_sub(3)..(at + 4).min(intervals.len())];
    let longest = around.iter().copied().max().unwrap_or(0) as f64;
    let is_late = |i: &&i64| **i as f64 > 1.5 * period.as_nanos() as f64;
    Ok(Measured {
        prepare,
        swap: took,
        ratio: longest / median,
        late_around: around.iter().filter(is_late).count(),
        late: intervals.iter().filter(is_late).count(),
        cycles: intervals.len(),
    })
}

/// The figures, one line each.
pub fn run() -> Result<String, String> {
    let mut out = String::new();
    let pid = std::process::id();
    for (period_us, hz) in [(1000u64, "1k"), (250, "4k")] {
        for (to, what) in [("libcounter.so", "same"), ("libcounter_v2.so", "relaid")] {
            let segment = format!("bench_change_{hz}_{what}_{pid}");
            let m = one(Duration::from_micros(period_us), to, &segment)?;
            let _ = writeln!(
                out,
                "online_change_swap_us_{what}_{hz} {}\nonline_change_prepare_ms_{what}_{hz} {:.1}\n\
                 online_change_cycle_ratio_{what}_{hz} {:.2}\n\
                 online_change_late_cycles_{what}_{hz} {} of 7 around the swap, {} of {} in the run",
                m.swap.as_micros(),
                m.prepare.as_secs_f64() * 1e3,
                m.ratio,
                m.late_around,
                m.late,
                m.cycles
            );
        }
    }
    Ok(out)
}
