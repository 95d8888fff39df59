//! `plc log <segment> <names...> --csv FILE [--rate HZ] [--seconds S]`.

use super::{Error, resolve, show};
use plc_io::shm::DynSegment;
use std::io::Write;
use std::path::Path;
use std::time::{Duration, Instant};

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
    if !(rate > 0.0 && rate <= 10_000.0) {
        return Err("--rate must be between 0 and 10000 samples per second".into());
    }
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
    let start = Instant::now();
    let period = Duration::from_secs_f64(1.0 / rate);
    let mut next = start;
    let mut rows = 0u64;
    while seconds.is_none_or(|s| start.elapsed().as_secs_f64() < s) {
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
        next += period;
        let now = Instant::now();
        if next > now {
            std::thread::sleep(next - now);
        }
    }
    out.flush()?;
    eprintln!("plc log: {rows} rows written to {}", csv.display());
    Ok(())
}
