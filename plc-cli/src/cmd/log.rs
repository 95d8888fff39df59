//! `plc log <segment> <names...> --csv FILE [--rate HZ] [--seconds S]`.
//!
//! It runs until `--seconds` have passed, the program stops, or Ctrl-C / SIGTERM: the signals
//! only ask the loop to end, so the rows still buffered are written before it exits. The file is
//! also flushed every second, so `tail -f` follows it and a `kill -9` loses at most a second.
//! Values keep full precision; a STRING cell a spreadsheet would run as a formula (`=1+1`) is
//! written as text, and control characters in text are escaped (see [`csv_cell`]).

use super::{Error, is_path, leaves_of, period_of, resolve, show};
use crate::display::{Format, csv_cell, value};
use plc_core::IecType;
use plc_shm::DynSegment;
use plc_shm::PathLocation;
use std::io::Write;
use std::path::Path;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

/// How often the CSV file is flushed while logging.
const FLUSH_EVERY: Duration = Duration::from_secs(1);

/// A flag that SIGINT (Ctrl-C) and SIGTERM set instead of ending the process, so the rows
/// still buffered are written; a second signal while the first is pending ends it at once.
pub(super) fn stop_on_signals() -> Result<Arc<AtomicBool>, String> {
    let stop = Arc::new(AtomicBool::new(false));
    plc_shm::stop_on_signals(&stop)
        .map_err(|e| format!("cannot handle Ctrl-C and SIGTERM: {e}"))?;
    Ok(stop)
}

/// What one column of the log holds.
enum LogColumn {
    /// A variable (an array whole) or one element, by index.
    Flat(usize, Option<usize>),
    /// A value inside a structure, by path.
    Path(Box<PathLocation>),
}

pub fn run(
    segment: &str,
    names: &[String],
    csv: &Path,
    rate: f64,
    seconds: Option<f64>,
) -> Result<(), Error> {
    let period = period_of(rate, 10_000.0, "samples")?;
    let stop = stop_on_signals()?;
    let seg = DynSegment::attach(segment)?;
    // One column per name: a variable or element as before, or each value a path reaches
    // inside structures (a whole structure gives a column per member).
    let mut columns: Vec<(String, LogColumn)> = Vec::new();
    for n in names {
        if is_path(&seg, n) {
            for at in leaves_of(&seg, n)? {
                columns.push((at.path.clone(), LogColumn::Path(Box::new(at))));
            }
        } else {
            let (i, _, e) = resolve(&seg, n)?;
            columns.push((n.clone(), LogColumn::Flat(i, e)));
        }
    }
    let mut out = std::io::BufWriter::new(
        std::fs::File::create(csv).map_err(|e| format!("{}: {e}", csv.display()))?,
    );
    let header: Vec<String> = ["time_s", "cycle"]
        .iter()
        .map(|s| s.to_string())
        .chain(columns.iter().map(|(n, _)| csv_cell(n, false)))
        .collect();
    writeln!(out, "{}", header.join(","))?;
    out.flush()?;
    let start = Instant::now();
    let mut next = start;
    let mut flushed = start;
    let mut rows = 0u64;
    // Full precision: a log is data for other programs, not for the eye.
    let full = Format::default();
    while !stop.load(Ordering::Acquire) && seconds.is_none_or(|s| start.elapsed().as_secs_f64() < s)
    {
        let image = match seg.snapshot_bytes() {
            Ok(i) => i,
            Err(e) if rows > 0 => {
                eprintln!("plc log: stopped: {e}");
                break;
            }
            Err(e) => return Err(e.into()),
        };
        let mut row = vec![
            format!("{:.6}", start.elapsed().as_secs_f64()),
            seg.status().cycle_count.to_string(),
        ];
        row.extend(columns.iter().map(|(_, c)| {
            match c {
                LogColumn::Flat(i, e) => csv_cell(
                    &show(&seg, &image, *i, *e, &full),
                    seg.descriptor().variables[*i].iec_type == IecType::String,
                ),
                LogColumn::Path(at) => csv_cell(
                    &at.var
                        .value_in(&image, 0)
                        .map_or("?".to_string(), |v| value(&v, at.var.iec_type, &full)),
                    at.var.iec_type == IecType::String,
                ),
            }
        }));
        writeln!(out, "{}", row.join(","))?;
        rows += 1;
        if flushed.elapsed() >= FLUSH_EVERY {
            out.flush()?;
            flushed = Instant::now();
        }
        next += period;
        // Sleep in short steps: a slow rate must not delay the answer to Ctrl-C.
        while !stop.load(Ordering::Acquire) {
            let now = Instant::now();
            if next <= now {
                break;
            }
            std::thread::sleep((next - now).min(Duration::from_millis(50)));
        }
    }
    out.flush()?;
    eprintln!("plc log: {rows} rows written to {}", csv.display());
    Ok(())
}
