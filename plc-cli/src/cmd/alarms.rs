//! `plc alarms`: a running program's alarms as its segment holds them (the ones that want an
//! operator's eye first, most severe first), or their history from the program's alarm
//! journal.

use super::Error;
use crate::display::escape_text;
use plc_core::alarm::AlarmState;
use plc_shm::{AlarmDescriptor, AlarmEntry, DynSegment, utc_text};

/// `plc alarms`.
#[derive(clap::Args)]
pub struct AlarmsArgs {
    /// Segment name.
    pub segment: String,
    /// Every declared alarm, normal ones too (without it: those active, waiting for an
    /// acknowledgement, latched, shelved or suppressed).
    #[arg(long, conflicts_with = "history")]
    pub all: bool,
    /// The history: every transition the program's alarm journal keeps (raised, acknowledged
    /// by whom, cleared, shelved, reset), oldest first.
    #[arg(long)]
    pub history: bool,
    /// With --history: from this time on, a UTC time (`2026-12-05 14:00`) or how long ago
    /// (`2h`, `30m`, `1d`).
    #[arg(long, requires = "history")]
    pub since: Option<String>,
}

/// Runs `plc alarms`.
pub fn run(args: &AlarmsArgs) -> Result<(), Error> {
    let seg = DynSegment::attach(&args.segment)?;
    if args.history {
        return super::alarm_history::print(&seg, args.since.as_deref());
    }
    let states = seg.alarm_states()?;
    let mut shown: Vec<(&AlarmDescriptor, &AlarmEntry)> = seg
        .alarms()
        .iter()
        .zip(&states)
        .filter(|(_, s)| args.all || s.state != AlarmState::Normal)
        .collect();
    if shown.is_empty() {
        println!(
            "segment `{}`: no alarm active or waiting for an acknowledgement ({} declared; \
             --all lists them)",
            seg.name(),
            seg.alarms().len()
        );
        return Ok(());
    }
    // Most severe first; of the same severity, the oldest first.
    shown.sort_by_key(|(a, s)| (std::cmp::Reverse(a.severity), s.since_ns));
    let rows: Vec<[String; 5]> = shown.iter().map(|(a, s)| row(a, s)).collect();
    let header = ["SEVERITY", "ALARM", "STATE", "SINCE", "TEXT"].map(String::from);
    let widths: Vec<usize> = (0..5)
        .map(|c| {
            rows.iter()
                .chain([&header])
                .map(|r| r[c].chars().count())
                .max()
                .unwrap_or(0)
        })
        .collect();
    for r in [&header].into_iter().chain(&rows) {
        let line: Vec<String> = r
            .iter()
            .zip(&widths)
            .map(|(cell, w)| format!("{cell:<w$}"))
            .collect();
        println!("{}", line.join("  ").trim_end());
    }
    Ok(())
}

/// One alarm's cells: severity, path, state (with the level of a limit alarm and a shelf's
/// end), since when, text.
fn row(a: &AlarmDescriptor, s: &AlarmEntry) -> [String; 5] {
    [
        a.severity.to_string(),
        escape_text(&a.path),
        s.state_text(a),
        match s.since_ns {
            ..=0 => "-".to_string(),
            ns => utc_text(ns as u64),
        },
        escape_text(&a.text),
    ]
}
