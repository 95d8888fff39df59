//! Group `commissioning`: what forces and traces cost a running program's cycle, and whether a
//! trace at 4 kHz loses a row.
//!
//! - `cycle_1k_traced_64_vs_untraced`: `plc_io::Runtime` on `Gm1k` (a segment, no I/O, an
//!   empty tick, period zero, as `cycle_1k_runtime_vs_memcpy` runs it), timed between ticks in
//!   batches of 2,000 cycles, with a trace of 64 of its basic values running (a real
//!   [`DynSegment::trace`](plc_io::shm::DynSegment::trace) from this process, drained every 10 ms by a thread of its own)
//!   against the same with no trace, the two in alternating batches: the trace is started
//!   before each traced batch and ended after it. A traced batch starts only once the trace's
//!   ring has been written round once (its pages are in memory; a new trace's first pass
//!   through them costs page faults, a cost of starting it, not of running it).
//! - `cycle_1k_forced_32_vs_unforced`: the same with 32 values forced
//!   ([`DynSegment::force`](plc_io::shm::DynSegment::force) before each forced batch,
//!   [`DynSegment::release_all`](plc_io::shm::DynSegment::release_all) after it) against none.
//! - `..._1ms`: both again at a 1 ms period, each cycle's own time (start to end) from the
//!   runtime's cycle probe, in alternating windows of cycles; each side the median of its
//!   windows' medians. A cycle at a real period starts with cold caches: what a program that
//!   sleeps between cycles pays.
//! - `forces_apply_32_ns`, `trace_record_64_ns`: where the time goes, each step alone on a
//!   bare [`plc_io::shm::ShmOwner`] of `Gm1k`: `apply_forces` with 32 held (the cycle calls it
//!   twice), `record_traces` with one 64-value trace; `forces_floor_32_twice_ns`,
//!   `trace_floor_64_ns`: the least any implementation pays for the same values (the `floor` module).
//! - `forced_32_vs_floor`, `traced_64_vs_floor`: what the forces and the trace add to a cycle
//!   at period zero (loaded minus plain, from the same run) in those floors; target 2 at most.
//! - group `flood` (its own, beside this one): `flood_force_1024_*`, `flood_write_1024_*`,
//!   `flood_force_vs_write_ns_per_value`: a 5 s flood of requests of 1,024 values from four tools against `Gm1k` at 1 ms, forces against
//!   writes: overruns, cycle times, and what a forced value costs the cycle against a written
//!   one (the `flood` module; target 1 at most, and no more overruns than the writes).
//! - `trace_4khz_lost`: a `Gm1k` program at 250 µs whose tick counts cycles into `int6`,
//!   traced (six values, that counter first) for 60 s (20 s with `--quick`) by a drainer at
//!   normal priority draining every 10 ms as `plc trace` does; the rows lost
//!   ([`TraceEvent::Lost`](plc_io::shm::trace::TraceEvent::Lost)) plus every gap or repeat in the rows' cycle numbers.

mod compare;
mod flood;
mod floor;
mod lost;
mod steps;
mod tool;

use compare::{Compared, Load, Timing, compare};
use std::fmt::Write as _;
use std::time::Duration;

/// Runs the group with `batches` batches of each side at period zero; its `name: value` lines.
pub fn run(quick: bool, batches: usize) -> Result<String, String> {
    let mut out = String::new();
    let segment = format!("plc_bench_comm_{}", std::process::id());
    let windows = if quick { 5 } else { 15 };
    // The period-zero comparisons, read against the floors once the steps are measured.
    let mut flat_out = None;
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
        if suffix.is_empty() {
            flat_out = Some((forced, traced));
        }
    }
    let steps = steps::steps(&format!("{segment}_steps"), batches)?;
    steps.write(&mut out);
    if let Some((forced, traced)) = flat_out {
        let _ = writeln!(
            out,
            "forced_32_vs_floor: {:.2}",
            over_floor(&forced, steps.forces_floor)
        );
        let _ = writeln!(
            out,
            "traced_64_vs_floor: {:.2}",
            over_floor(&traced, steps.trace_floor)
        );
    }
    let seconds = if quick { 20 } else { 60 };
    lost::lost_at_4khz(&format!("{segment}_4k"), seconds, quick, &mut out)?;
    Ok(out)
}

/// Group `flood`: a 5 s flood of force requests against one of write requests (the `flood`
/// module); its `name: value` lines.
pub fn flood() -> Result<String, String> {
    let mut out = String::new();
    let segment = format!("plc_bench_flood_{}", std::process::id());
    flood::flood(&segment, 5, &mut out)?;
    Ok(out)
}

/// What the load adds to a cycle at period zero, in floors: the target is 2 at most.
fn over_floor(compared: &Compared, floor: Duration) -> f64 {
    let added = compared.loaded.as_secs_f64() - compared.plain.as_secs_f64();
    added / floor.as_secs_f64()
}
