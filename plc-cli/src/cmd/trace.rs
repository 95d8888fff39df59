//! `plc trace SEGMENT path... --out FILE.csv [--plot FILE.svg] [--for 10s] [--trigger EXPR]
//! [--pre N] [--post N] [--every N]`: the running program records the values every cycle (or
//! every Nth) into a ring this tool drains every few milliseconds, so no cycle is lost or
//! repeated at the program's period; rows it could not drain in time are said, in the cycle
//! column (it jumps) and at the end, never skipped in silence.
//!
//! The CSV is written to a temporary file beside `--out` and renamed over it at the end (a
//! trace cut short by Ctrl-C keeps the rows drained so far); the plot likewise. A replaced file
//! keeps its permissions, and a trace whose trigger never fired replaces nothing.

use super::log::stop_on_signals;
use super::{Error, leaves_of};
use crate::trace::capture::Capture;
use crate::trace::csv::CsvWriter;
use crate::trace::plot::{self, Samples};
use crate::trace::trigger::Trigger;
use crate::trace::{Column, Row};
use plc_shm::trace::TraceEvent;
use plc_shm::{DynSegment, PathLocation};
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::Ordering;
use std::time::{Duration, Instant};

/// How often the ring is drained: a ring holds at least two seconds of rows.
const DRAIN_EVERY: Duration = Duration::from_millis(10);
/// Rows after the trigger when `--post` is not given.
pub const DEFAULT_POST: usize = 1000;

/// What the command line asks for.
#[derive(clap::Args)]
pub struct Options {
    /// Segment name.
    pub segment: String,
    /// Basic values to record, at most 64 (a structure gives each of its members).
    #[arg(required = true)]
    pub paths: Vec<String>,
    /// The CSV file to write (`cycle,time_s,<path>...`).
    #[arg(long)]
    pub out: PathBuf,
    /// Also draw the trace as an SVG picture.
    #[arg(long)]
    pub plot: Option<PathBuf>,
    /// Stop after this long (`10s`, `500ms`, `2m`; default: until Ctrl-C, the trigger's
    /// rows, or the program's stop).
    #[arg(long = "for", value_parser = parse_duration)]
    pub duration: Option<std::time::Duration>,
    /// Start at `path > v`, `path < v`, `path == v`, `path rising` or `path falling`.
    #[arg(long)]
    pub trigger: Option<String>,
    /// Rows kept before the trigger row.
    #[arg(long, default_value_t = 0, requires = "trigger")]
    pub pre: usize,
    /// Rows kept after the trigger row (default 1000).
    #[arg(long, requires = "trigger")]
    pub post: Option<usize>,
    /// Record every Nth cycle.
    #[arg(long, default_value_t = 1)]
    pub every: u32,
}

/// `10s`, `500ms`, `250us`, `2m`, or plain seconds (`1.5`).
fn parse_duration(text: &str) -> Result<std::time::Duration, String> {
    let t = text.trim();
    let (number, scale) = [
        ("ms", 1e-3),
        ("us", 1e-6),
        ("s", 1.0),
        ("m", 60.0),
        ("h", 3600.0),
    ]
    .iter()
    .find_map(|(unit, scale)| t.strip_suffix(unit).map(|n| (n, *scale)))
    .unwrap_or((t, 1.0));
    let seconds: f64 = number
        .trim()
        .parse()
        .map_err(|_| format!("`{text}`: write a duration such as 10s, 500ms or 2m"))?;
    std::time::Duration::try_from_secs_f64(seconds * scale)
        .map_err(|_| format!("`{text}`: a duration of zero or more, such as 10s"))
}

/// How a trace ended.
struct Outcome {
    rows: u64,
    lost: u64,
    stopped: Option<String>,
    /// The trigger row's time, if it fired.
    trigger_ns: Option<u64>,
    summary: crate::trace::capture::Summary,
}

pub fn run(o: &Options) -> Result<(), Error> {
    if o.every == 0 {
        return Err("--every must be 1 or more (cycles between rows)".into());
    }
    let trigger = o
        .trigger
        .as_deref()
        .map(Trigger::parse)
        .transpose()
        .map_err(|e| format!("--trigger: {e}"))?;
    let seg = DynSegment::attach(&o.segment)?;
    let mut found: Vec<PathLocation> = Vec::new();
    for p in &o.paths {
        found.extend(leaves_of(&seg, p)?);
    }
    // The trigger's value is recorded too, as a column of its own if it is not one already.
    let trigger = match trigger {
        None => None,
        Some(spec) => {
            let at = seg.locate(spec.path())?;
            let column = match found
                .iter()
                .position(|f| (f.index, f.leaf) == (at.index, at.leaf))
            {
                Some(k) => k,
                None => {
                    found.push(at);
                    found.len() - 1
                }
            };
            Some(
                spec.bind(column, found[column].var.iec_type)
                    .map_err(|e| format!("--trigger: {e}"))?,
            )
        }
    };
    if found.len() > plc_shm::protocol::MAX_TRACED {
        return Err(format!(
            "{} values named: a trace records at most {}",
            found.len(),
            plc_shm::protocol::MAX_TRACED
        )
        .into());
    }
    let columns: Vec<Column> = found
        .iter()
        .map(|at| Column {
            path: at.path.clone(),
            iec_type: at.var.iec_type,
            unit: at.var.quantity.clone(),
        })
        .collect();
    let post = o.post.unwrap_or(DEFAULT_POST);
    let stop = stop_on_signals()?;
    let mut trace = seg.trace(&found, o.every)?;
    let capture = Capture::new(o.pre, post, trigger);
    let keep = o.plot.is_some();
    let mut kept = Samples::new(columns.len());
    let mut outcome = None;
    let untriggered = o.trigger.is_some();
    plc_files::write_atomically_with(
        &o.out,
        mode_to_keep(&o.out),
        |file| {
            let mut csv = CsvWriter::new(BufWriter::new(file), &columns)?;
            let result = record(
                &seg,
                &mut trace,
                capture,
                &mut csv,
                o.duration,
                &stop,
                |r| {
                    if keep {
                        kept.push(r);
                    }
                },
            )?;
            csv.into_inner().flush()?;
            // A trigger that never fired recorded nothing: the file a trace made before stays
            // (the temporary file is removed).
            let fired = !untriggered || result.summary.triggered_at.is_some();
            outcome = Some(result);
            if fired {
                Ok(())
            } else {
                Err(std::io::Error::other(NOT_FIRED))
            }
        },
        |_| {},
    )
    .or_else(|e| match &outcome {
        // Said by `report`, with the file left as it was.
        Some(_) if e.to_string() == NOT_FIRED => Ok(()),
        _ => Err(format!("{}: {e}", o.out.display())),
    })?;
    let Some(outcome) = outcome else {
        return Err("the trace did not run".into());
    };
    if outcome.summary.triggered_at.is_none() && untriggered {
        return report(o, &outcome);
    }
    eprintln!(
        "plc trace: {} rows written to {}",
        outcome.rows,
        o.out.display()
    );
    if let Some(svg) = &o.plot {
        let title = format!("{} — plc trace", seg.name());
        let picture = plot::svg(&title, &columns, &kept, outcome.trigger_ns)?;
        write_plot(svg, &picture)?;
        eprintln!("plc trace: plot written to {}", svg.display());
    }
    report(o, &outcome)
}

fn write_plot(path: &Path, svg: &str) -> Result<(), Error> {
    plc_files::write_atomically(path, svg.as_bytes(), mode_to_keep(path))
        .map_err(|e| format!("{}: {e}", path.display()).into())
}

/// What the write closure answers when the trigger never fired, so nothing replaces the file.
const NOT_FIRED: &str = "the trigger did not fire";

/// The permissions a new trace file gets: those of the file it replaces (a 0600 CSV stays
/// 0600), else 0644. A link or anything but a plain file is refused by the write itself.
fn mode_to_keep(path: &Path) -> u32 {
    use std::os::unix::fs::PermissionsExt;
    match std::fs::symlink_metadata(path) {
        Ok(m) if m.is_file() => m.permissions().mode() & 0o777,
        _ => 0o644,
    }
}

/// What the user is told at the end; an error (exit status 1) when rows were lost or the
/// trigger never fired, so a script cannot take a trace with holes for a whole one.
fn report(o: &Options, outcome: &Outcome) -> Result<(), Error> {
    if let Some(why) = &outcome.stopped {
        eprintln!("plc trace: stopped: {why}");
    }
    let s = &outcome.summary;
    if o.trigger.is_some() {
        match s.triggered_at {
            Some(cycle) if s.post_missing > 0 => eprintln!(
                "plc trace: triggered at cycle {cycle}; the trace ended {} rows short of --post",
                s.post_missing
            ),
            Some(cycle) => eprintln!("plc trace: triggered at cycle {cycle}"),
            None => {
                return Err(format!(
                    "the trigger `{}` did not fire: nothing was recorded, and no file was \
                     written or replaced",
                    o.trigger.as_deref().unwrap_or_default()
                )
                .into());
            }
        }
    }
    if outcome.lost > 0 {
        let gaps: Vec<String> = s.gaps.iter().map(|g| g.to_string()).collect();
        return Err(format!(
            "{} rows were lost because this tool fell behind the program ({}); the cycle \
             column shows each gap. Trace fewer values, use --every, or run the tool with \
             less else on the machine",
            outcome.lost,
            if gaps.is_empty() {
                "before the rows kept".into()
            } else {
                gaps.join(", ")
            }
        )
        .into());
    }
    Ok(())
}

/// Drains the ring until the capture is done, `duration` has passed, a signal came or the
/// program stopped, writing the rows the capture keeps.
fn record<W: Write>(
    seg: &DynSegment,
    trace: &mut plc_shm::trace::Trace,
    mut capture: Capture,
    csv: &mut CsvWriter<W>,
    duration: Option<Duration>,
    stop: &std::sync::atomic::AtomicBool,
    mut keep: impl FnMut(&Row),
) -> std::io::Result<Outcome> {
    let start = Instant::now();
    let (mut rows, mut lost) = (0u64, 0u64);
    let mut last_cycle: Option<u64> = None;
    let mut pending_gap = false;
    let mut origin_set = false;
    let mut events = Vec::new();
    let mut stopped = None;
    loop {
        let ended = trace.ended();
        events.clear();
        trace.drain(&mut events, usize::MAX);
        for event in events.drain(..) {
            let row = match event {
                TraceEvent::Lost(n) => {
                    lost += n;
                    pending_gap = true;
                    continue;
                }
                TraceEvent::Row(r) => Row {
                    cycle: r.cycle,
                    time_ns: r.time_ns,
                    values: r.values,
                },
            };
            if pending_gap {
                let first = last_cycle.map_or(0, |c| c + 1);
                capture.push_gap(first, row.cycle.saturating_sub(1));
                pending_gap = false;
            }
            last_cycle = Some(row.cycle);
            let out = capture.push(row);
            if !origin_set && let Some(t) = capture.trigger_time_ns() {
                csv.set_origin(t);
                origin_set = true;
            }
            for r in &out {
                csv.write_row(r)?;
                keep(r);
                rows += 1;
            }
            if capture.is_done() {
                break;
            }
        }
        if capture.is_done() {
            break;
        }
        if ended {
            stopped = Some("the program stopped".to_string());
            break;
        }
        if stop.load(Ordering::Acquire) {
            break;
        }
        if duration.is_some_and(|d| start.elapsed() >= d) {
            break;
        }
        // A program killed cannot say it ended: its state can.
        match seg.owner_state() {
            plc_shm::OwnerState::Running | plc_shm::OwnerState::Stalled => {}
            state => {
                stopped = Some(format!("the program is {state}"));
                break;
            }
        }
        std::thread::sleep(DRAIN_EVERY);
    }
    Ok(Outcome {
        rows,
        lost,
        stopped,
        trigger_ns: capture.trigger_time_ns(),
        summary: capture.finish(),
    })
}

#[cfg(test)]
mod tests {
    use super::parse_duration;
    use std::time::Duration;

    #[test]
    fn durations_read_with_their_units() {
        assert_eq!(parse_duration("10s"), Ok(Duration::from_secs(10)));
        assert_eq!(parse_duration("500ms"), Ok(Duration::from_millis(500)));
        assert_eq!(parse_duration("250us"), Ok(Duration::from_micros(250)));
        assert_eq!(parse_duration("2m"), Ok(Duration::from_secs(120)));
        assert_eq!(parse_duration(" 1.5 "), Ok(Duration::from_millis(1500)));
        assert!(parse_duration("ten").unwrap_err().contains("such as 10s"));
        assert!(parse_duration("-1s").is_err());
    }
}
