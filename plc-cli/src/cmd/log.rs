//! `plc log <segment> <names...> --csv FILE [--rate HZ] [--seconds S]`.
//!
//! It runs until `--seconds` have passed, the program stops, or Ctrl-C / SIGTERM: the signals
//! only ask the loop to end, so the rows still buffered are written before it exits. The file is
//! also flushed every second, so `tail -f` follows it and a `kill -9` loses at most a second.

use super::{Error, period_of, resolve, show};
use plc_io::StopHandle;
use plc_io::shm::DynSegment;
use std::io::Write;
use std::path::Path;
use std::time::{Duration, Instant};

/// How often the CSV file is flushed while logging.
const FLUSH_EVERY: Duration = Duration::from_secs(1);

/// A CSV field, quoted per RFC 4180 when it needs to be.
fn field(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

pub fn run(
    segment: &str,
    names: &[String],
    csv: &Path,
    rate: f64,
    seconds: Option<f64>,
) -> Result<(), Error> {
    let period = period_of(rate, 10_000.0, "samples")?;
    let stop = StopHandle::default();
    stop.stop_on_signals()
        .map_err(|e| format!("cannot handle Ctrl-C and SIGTERM: {e}"))?;
    let seg = DynSegment::attach(segment)?;
    let vars: Vec<_> = names
        .iter()
        .map(|n| resolve(&seg, n))
        .collect::<Result<_, _>>()?;
    let mut out = std::io::BufWriter::new(
        std::fs::File::create(csv).map_err(|e| format!("{}: {e}", csv.display()))?,
    );
    let header: Vec<String> = ["time_s", "cycle"]
        .iter()
        .map(|s| s.to_string())
        .chain(names.iter().map(|n| field(n)))
        .collect();
    writeln!(out, "{}", header.join(","))?;
    out.flush()?;
    let start = Instant::now();
    let mut next = start;
    let mut flushed = start;
    let mut rows = 0u64;
    while !stop.is_stopped() && seconds.is_none_or(|s| start.elapsed().as_secs_f64() < s) {
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
        row.extend(
            vars.iter()
                .map(|&(i, _, e)| field(&show(&seg, &image, i, e))),
        );
        writeln!(out, "{}", row.join(","))?;
        rows += 1;
        if flushed.elapsed() >= FLUSH_EVERY {
            out.flush()?;
            flushed = Instant::now();
        }
        next += period;
        // Sleep in short steps: a slow rate must not delay the answer to Ctrl-C.
        while !stop.is_stopped() {
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
