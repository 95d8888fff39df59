//! Group `alarms`: what the runtime's alarms cost its cycle, with none changing
//! (`alarm_eval_ns_per_alarm`, target 5 ns a cycle per alarm at most: [`eval`]) and when every
//! one of 1,000 changes in every cycle (`alarm_flood_*`, target no overrun, bounded memory:
//! [`flood`]).

pub mod eval;
pub mod flood;

use plc_core::GlobalMemory;
use std::time::Duration;

/// A program with 1,000 alarms: 900 on the elements of a `[bool; 900]` (a door switch each)
/// and 100 limit alarms (high, high-high, low, deadband, on-delay) on a `[f32; 100]`.
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

/// [`Alarmed1k`] without its alarm attributes: the same variables, the same image, the same
/// tick, so a cycle of one against a cycle of the other differs by the alarm step alone.
#[derive(GlobalMemory, Clone, Debug)]
pub struct Plain1k {
    doors: [bool; 900],
    temperatures: [f32; 100],
}

/// An oil temperature inside every limit (low 5, high 80): none of the limit alarms is due.
const TEMPERATURE: f32 = 40.0;

/// How long the group runs.
#[derive(Clone, Copy, Debug)]
pub struct Scale {
    /// Batches each side of the evaluator alone (the runner's cycle batches).
    pub batches: usize,
    /// Blocks each side of the runtime's comparison.
    pub blocks: usize,
    /// The flood's length, after its warm-up.
    pub flood: Duration,
}

impl Scale {
    /// `--quick`: 12 blocks each side and a 10 s flood; the default 30 blocks and 10 s;
    /// `--full` 30 blocks and the flood of the issue, 60 s. Not less than 10 s: the journal
    /// first compacts some 6 s into a flood (its 12,500th record), and the memory that takes
    /// is what a shorter flood would leave out of its memory figure.
    pub fn of(quick: bool, full: bool, batches: usize) -> Scale {
        Scale {
            batches,
            blocks: if quick { 12 } else { 30 },
            flood: Duration::from_secs(if full { 60 } else { 10 }),
        }
    }
}

/// Runs the group; its `name: value` lines.
pub fn run(scale: Scale) -> Result<String, String> {
    let mut out = eval::run(scale.blocks, scale.batches)?;
    out.push_str(&flood::run(scale.flood)?);
    Ok(out)
}

/// The median of `v` (sorted here), 0 for none.
fn median(v: &mut [u64]) -> u64 {
    v.sort_unstable();
    v.get(v.len() / 2).copied().unwrap_or(0)
}
