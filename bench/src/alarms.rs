//! Group `alarms`: what evaluating declared alarms costs a cycle when none changes, the figure
//! `alarm_eval_ns_per_alarm` (target 5 ns at most).
//!
//! `Alarmed1k` declares 1,000 alarms: 900 on the elements of a `[bool; 900]` (a door switch
//! each) and 100 limit alarms (high, high-high, low, deadband, on-delay) on a `[f32; 100]`;
//! none of them changes. The evaluator ([`plc_core::alarm::Alarms::evaluate`]) runs over all
//! of them, each alarm's sample read from the struct, in alternating batches against the same
//! loop without alarms (the reads alone), and the difference is divided by 1,000.
//!
//! The runtime does not call the evaluator yet: this is the step alone, what the cycle will pay
//! per alarm once it does.

use super::timing::side_by_side;
use plc_core::GlobalMemory;
use plc_core::alarm::{AlarmEvent, Alarms, Sample};
use std::fmt::Write as _;
use std::hint::black_box;

/// A program with 1,000 alarms.
#[derive(GlobalMemory, Clone, Debug)]
pub struct Alarmed1k {
    #[plc(alarm = "Guard door open")]
    doors: [bool; 900],
    #[plc(alarm(
        text = "Oil temperature",
        high = 80.0,
        high_high = 95.0,
        low = 5.0,
        deadband = 1.0,
        delay = "2s"
    ))]
    temperatures: [f32; 100],
}

/// Iterations of the evaluator per batch.
const ITERS: u32 = 2000;

/// Runs the group with `batches` batches each side; its `name: value` lines.
pub fn run(batches: usize) -> Result<String, String> {
    let gm = Alarmed1k {
        temperatures: [40.0; 100],
        ..Alarmed1k::default()
    };
    let decls = Alarmed1k::ALARMS;
    if decls.len() != 1000 {
        return Err(format!("{} alarms declared, not 1,000", decls.len()));
    }
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
    let per_alarm = (with.as_secs_f64() - without.as_secs_f64()) * 1e9 / decls.len() as f64;
    let mut out = String::new();
    let _ = writeln!(
        out,
        "alarm_eval_samples: {batches} batches of {ITERS} evaluations of 1,000 alarms each side, \
         alternating"
    );
    let _ = writeln!(out, "alarm_eval_1000_ns: {}", with.as_nanos());
    let _ = writeln!(out, "alarm_samples_1000_ns: {}", without.as_nanos());
    let _ = writeln!(out, "alarm_eval_ns_per_alarm: {per_alarm:.2}");
    Ok(out)
}
