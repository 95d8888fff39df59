//! `plc alarms --history`: the transitions a program's alarm journal keeps, read from the file
//! its segment names (with the journal's own checks: no link followed, the reader's own
//! private file), damaged lines reported and skipped.

use super::Error;
use plc_runtime::alarm_journal::{DEFAULT_CAPACITY, read_journal};
use plc_shm::DynSegment;

/// Prints the history of `seg`'s alarms, from `since` (a UTC time or how long ago) on.
pub fn print(seg: &DynSegment, since: Option<&str>) -> Result<(), Error> {
    let since_ns = since.map(since_ns).transpose()?;
    let Some(path) = &seg.descriptor().alarm_journal else {
        return Err(format!(
            "segment `{}` keeps no alarm history: its program has no retained-values file and \
             no alarm journal (`RuntimeBuilder::retain` or `alarm_journal`), or declares no \
             alarms",
            seg.name()
        )
        .into());
    };
    // The capacity the program keeps: a larger journal's file would be refused as too large.
    let capacity = seg
        .descriptor()
        .alarm_journal_capacity
        .unwrap_or(DEFAULT_CAPACITY)
        .clamp(1, 10_000_000);
    let contents = read_journal(path, capacity)
        .map_err(|e| format!("segment `{}`: {e}", seg.name()))?
        .ok_or_else(|| {
            format!(
                "segment `{}`: its alarm journal {path} does not exist (yet): nothing has \
                 happened to an alarm",
                seg.name()
            )
        })?;
    for d in contents.damage() {
        eprintln!("plc: alarm journal {path}: {d}; skipped, the other records are shown");
    }
    if let Some(t) = contents.torn() {
        eprintln!(
            "plc: alarm journal {path}: its last {} bytes are a record a crash cut short; not \
             shown",
            t.len
        );
    }
    if contents.dropped() > 0 {
        println!(
            "({} older records were dropped: the journal keeps the last {capacity})",
            contents.dropped()
        );
    }
    let mut n = 0;
    for record in contents.history(since_ns) {
        println!("{record}");
        n += 1;
    }
    if n == 0 {
        println!(
            "no alarm transition{}",
            since.map_or(String::new(), |s| format!(" since {s}"))
        );
    }
    Ok(())
}

/// A UTC time (`2026-12-05 14:00`), or how long ago (`2h`, `T#30m`), as UTC nanoseconds.
fn since_ns(text: &str) -> Result<i64, Error> {
    if let Some(ns) = plc_shm::parse_utc(text) {
        return Ok(ns);
    }
    let ago = super::duration(text).map_err(|e| {
        format!(
            "--since {text:?}: neither a UTC time (`2026-12-05 14:00`) nor how long ago (`2h`, \
             `30m`): {e}"
        )
    })?;
    let now = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| i64::try_from(d.as_nanos()).unwrap_or(i64::MAX));
    Ok(now.saturating_sub(ago.as_nanos()))
}
