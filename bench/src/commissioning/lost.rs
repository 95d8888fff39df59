//! Whether a trace at 4 kHz loses a row: a `Gm1k` program at 250 µs traced by a drainer at
//! normal priority.

use super::super::gm1k::Gm1k;
use super::tool::{DRAIN_EVERY, wait_attach};
use plc_io::shm::trace::{Trace, TraceEvent};
use std::fmt::Write as _;
use std::time::{Duration, Instant};

/// The 4 kHz program's period.
const PERIOD_4KHZ: Duration = Duration::from_micros(250);

/// A `Gm1k` program at 4 kHz traced for `seconds` by a drainer at normal priority.
pub fn lost_at_4khz(name: &str, seconds: u64, quick: bool, out: &mut String) -> Result<(), String> {
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
