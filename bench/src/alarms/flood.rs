//! `alarm_flood_*`: 1,000 alarms changing in every cycle of a real runtime with a real alarm
//! journal: whether the cycle keeps its period (target: no overrun) and the process its
//! memory (bounded), and what the journal does with a million transitions a second.
//!
//! `Doors1k` (1,000 door alarms on a `[bool; 1000]`) runs in a `plc_io::Runtime` at 1 ms on
//! a thread of its own, under SCHED_FIFO where permitted (the samples line says), its
//! journal in a private directory made for the run (mode 0700, as the journal requires,
//! removed at the end); the tick flips every door in every cycle, so each cycle raises or
//! clears all 1,000 alarms and hands 1,000 transitions to the journal's queue. The journal
//! writes at most 1,000 records a second and summarises the rest; the queue holds 8,192, so
//! the rest are counted on the cycle's side of a full queue.
//!
//! After a warm-up second the process's resident memory (`VmRSS`, read by this thread, not
//! the cycle's) is taken, then every second to the end of the flood:
//! `alarm_flood_rss_growth_kib` from the first reading to the last,
//! `_second_half_kib` from half-time to the end (memory that levels off grows by nothing
//! there; a leak grows as much as in the first half). The overruns, the longest and mean
//! cycle are the runtime's own statistics as the last tick saw them (every cycle but the
//! last); the percentiles come from the cycle probe (each cycle's time, start to end, in a
//! histogram made before the run so that it takes no memory during it). The summarised count
//! is the runtime's (`RuntimeAlarms::summarised`, read in the last tick); the records written
//! and the file's size are read back once the runtime has stopped and the journal is synced.

use crate::place;
use plc_core::GlobalMemory;
use plc_io::Runtime;
use plc_io::alarm_journal::{self, Entry};
use plc_io::probe::CycleTimes;
use std::fmt::Write as _;
use std::os::unix::fs::DirBuilderExt;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::sync::{Arc, Mutex};
use std::time::{Duration, SystemTime, UNIX_EPOCH};

/// 1,000 door alarms, all flipped every cycle.
#[derive(GlobalMemory, Clone, Debug)]
pub struct Doors1k {
    #[plc(alarm = "Guard door open")]
    doors: [bool; 1000],
}

/// The program's period.
const PERIOD: Duration = Duration::from_millis(1);
/// Before the first memory reading: the queue filled, the vectors grown, the file opened.
const WARM_UP: Duration = Duration::from_secs(1);
/// The histogram's buckets, one a microsecond; longer cycles count in the last.
const BUCKETS: usize = 20_000;

/// What the tick saw last.
#[derive(Default)]
struct Seen {
    cycles: AtomicU64,
    summarised: AtomicU64,
    overruns: AtomicU64,
    max_ns: AtomicU64,
    mean_ns: AtomicU64,
}

/// Floods for `length` after the warm-up; the figures' `name: value` lines.
pub fn run(length: Duration) -> Result<String, String> {
    if Doors1k::ALARMS.len() != 1000 {
        return Err(format!(
            "{} alarms declared, not 1,000",
            Doors1k::ALARMS.len()
        ));
    }
    let dir = PrivateDir::new("alarm-flood")?;
    let file = dir.0.join("flood.alarms");
    // The cycle under SCHED_FIFO where it is permitted, as a program at 1 ms is run: on a
    // shared machine a cycle at normal priority overruns whenever another process's work
    // takes its core, flood or not, and the figure would be the other process's.
    let fifo = place::fifo_permitted(place::CYCLE_PRIORITY);
    let sched = match &fifo {
        Ok(()) => format!("SCHED_FIFO {}", place::CYCLE_PRIORITY),
        Err(why) => format!("SCHED_OTHER: {why}"),
    };
    let seen = Arc::new(Seen::default());
    // Every bucket written once now, so the histogram's pages are resident before the first
    // memory reading.
    let mut buckets = vec![1u32; BUCKETS];
    buckets.fill(std::hint::black_box(0));
    let histogram = Arc::new(Mutex::new(buckets));
    let (sink, in_tick) = (histogram.clone(), seen.clone());
    let mut builder = Runtime::<Doors1k>::builder()
        .period(PERIOD)
        .handle_signals(false)
        .alarm_journal(&file)
        .cycle_probe(move |t: &CycleTimes| {
            let us = (t.end - t.start).as_micros() as usize;
            if let Ok(mut h) = sink.lock()
                && let Some(b) = h.get_mut(us.min(BUCKETS - 1))
            {
                *b += 1;
            }
        });
    if fifo.is_ok() {
        builder = builder.realtime_priority(place::CYCLE_PRIORITY);
    }
    let stop = builder.stop_handle();
    let runtime = builder
        .build()
        .map_err(|e| format!("the flood's runtime: {e}"))?;
    let program = std::thread::Builder::new()
        .name("alarm-flood".into())
        .spawn(move || {
            runtime.run(move |ctx| {
                ctx.gm.doors = [ctx.cycle % 2 == 1; 1000];
                let s = &in_tick;
                s.cycles.store(ctx.cycle, Relaxed);
                s.summarised.store(ctx.alarms().summarised(), Relaxed);
                s.overruns.store(ctx.stats.overruns, Relaxed);
                s.max_ns.store(ctx.stats.max.as_nanos() as u64, Relaxed);
                s.mean_ns.store(ctx.stats.mean.as_nanos() as u64, Relaxed);
            })
        })
        .map_err(|e| format!("the flood's thread: {e}"))?;
    let memory = watch_memory(length, || program.is_finished());
    stop.stop();
    match program.join() {
        Ok(Ok(_)) => {}
        Ok(Err(e)) => return Err(format!("the flood's runtime: {e}")),
        Err(_) => return Err("the flood's thread panicked".into()),
    }
    let memory = memory?;
    let journal = read_back(&file)?;
    let histogram = histogram.lock().map_err(|_| "the probe panicked")?;
    let cycles = seen.cycles.load(Relaxed);

    let mut out = String::new();
    let _ = writeln!(
        out,
        "alarm_flood_samples: 1,000 alarms changing every cycle at {} ms for {} s after a {} s \
         warm-up, a real journal; the cycle under {sched}",
        PERIOD.as_millis(),
        length.as_secs(),
        WARM_UP.as_secs()
    );
    let overruns = seen.overruns.load(Relaxed);
    let _ = writeln!(out, "alarm_flood_overruns: {overruns} (of {cycles} cycles)");
    let us = |ns: &AtomicU64| ns.load(Relaxed) as f64 / 1e3;
    let _ = writeln!(out, "alarm_flood_max_cycle_us: {:.0}", us(&seen.max_ns));
    let _ = writeln!(out, "alarm_flood_mean_cycle_us: {:.1}", us(&seen.mean_ns));
    let _ = writeln!(
        out,
        "alarm_flood_cycle_p50_us: {}",
        percentile(&histogram, 50)
    );
    let _ = writeln!(
        out,
        "alarm_flood_cycle_p99_us: {}",
        percentile(&histogram, 99)
    );
    memory.write(&mut out);
    let _ = writeln!(out, "alarm_flood_journal_bytes: {}", journal.bytes);
    let transitions = cycles * Doors1k::ALARMS.len() as u64;
    let _ = writeln!(out, "alarm_flood_transitions: {transitions}");
    let _ = writeln!(
        out,
        "alarm_flood_summarised: {}",
        seen.summarised.load(Relaxed)
    );
    let _ = writeln!(
        out,
        "alarm_flood_journal_records: {} written, {} kept ({} of them summaries, of {} \
         transitions)",
        journal.written, journal.kept, journal.summaries_kept, journal.summarised_kept
    );
    Ok(out)
}

/// The process's resident memory during the flood, KiB.
struct Memory {
    /// After the warm-up, at half-time, at the end.
    start: u64,
    half: u64,
    end: u64,
    /// The most of every second's reading.
    peak: u64,
}

impl Memory {
    fn write(&self, out: &mut String) {
        let grew = |from: u64, to: u64| to as i64 - from as i64;
        let _ = writeln!(
            out,
            "alarm_flood_rss_growth_kib: {} ({} KiB after the warm-up, {} at half-time, {} at \
             the end, {} at most)",
            grew(self.start, self.end),
            self.start,
            self.half,
            self.end,
            self.peak
        );
        let _ = writeln!(
            out,
            "alarm_flood_rss_growth_second_half_kib: {}",
            grew(self.half, self.end)
        );
    }
}

/// Reads the resident memory after the warm-up, then every second for `length` (bounded
/// memory levels off: the second half's growth tells it from a leak), stopping early if
/// `ended` (a runtime that failed to start, whose error is then reported without the wait).
fn watch_memory(length: Duration, ended: impl Fn() -> bool) -> Result<Memory, String> {
    std::thread::sleep(WARM_UP);
    let start = resident_kib()?;
    let mut m = Memory {
        start,
        half: start,
        end: start,
        peak: start,
    };
    let seconds = length.as_secs();
    for s in 1..=seconds {
        if ended() {
            break;
        }
        std::thread::sleep(Duration::from_secs(1));
        m.end = resident_kib()?;
        m.peak = m.peak.max(m.end);
        if s == seconds / 2 {
            m.half = m.end;
        }
    }
    Ok(m)
}

/// The cycle time at percentile `p` of the histogram, µs (the last bucket: that or longer).
fn percentile(histogram: &[u32], p: u64) -> usize {
    let total: u64 = histogram.iter().map(|&n| u64::from(n)).sum();
    let rank = total * p / 100;
    let mut seen = 0;
    for (us, &n) in histogram.iter().enumerate() {
        seen += u64::from(n);
        if seen > rank {
            return us;
        }
    }
    histogram.len().saturating_sub(1)
}

/// The journal as the stopped runtime left it.
struct Journal {
    bytes: u64,
    /// Records written since the file was made, summaries included (the next record's
    /// number less one), most of them dropped by compactions since.
    written: u64,
    kept: usize,
    /// The summary records among the kept, and the transitions they count.
    summaries_kept: usize,
    summarised_kept: u64,
}

fn read_back(file: &Path) -> Result<Journal, String> {
    let bytes = std::fs::metadata(file)
        .map_err(|e| format!("the journal {}: {e}", file.display()))?
        .len();
    let contents = alarm_journal::read_journal(file, alarm_journal::DEFAULT_CAPACITY)
        .map_err(|e| e.to_string())?
        .ok_or_else(|| format!("no journal at {} after the flood", file.display()))?;
    if !contents.damage().is_empty() || contents.torn().is_some() {
        return Err(format!(
            "the journal {} reads back damaged: {} lines, torn end {:?}",
            file.display(),
            contents.damage().len(),
            contents.torn()
        ));
    }
    let summaries: Vec<u64> = (contents.records().iter())
        .filter_map(|r| match r.entry {
            Entry::Summarised { transitions, .. } => Some(transitions),
            _ => None,
        })
        .collect();
    Ok(Journal {
        bytes,
        written: contents.next_seq().saturating_sub(1),
        kept: contents.records().len(),
        summaries_kept: summaries.len(),
        summarised_kept: summaries.iter().sum(),
    })
}

/// This process's resident memory, KiB, from `/proc/self/status`.
fn resident_kib() -> Result<u64, String> {
    let status = std::fs::read_to_string("/proc/self/status")
        .map_err(|e| format!("/proc/self/status: {e}"))?;
    status
        .lines()
        .find_map(|l| l.strip_prefix("VmRSS:"))
        .and_then(|v| v.split_whitespace().next())
        .and_then(|kb| kb.parse().ok())
        .ok_or_else(|| "/proc/self/status has no VmRSS line".to_string())
}

/// A directory of this run's own, mode 0700 from its creation, removed with what it holds
/// when dropped (after the runtime, and with it the journal, has stopped).
struct PrivateDir(PathBuf);

impl PrivateDir {
    fn new(what: &str) -> Result<PrivateDir, String> {
        let nanos = SystemTime::now()
            .duration_since(UNIX_EPOCH)
            .map_or(0, |d| d.subsec_nanos());
        let dir =
            std::env::temp_dir().join(format!("plc-bench-{what}-{}-{nanos}", std::process::id()));
        // Made new, never an existing one: the journal must be this user's own and private.
        std::fs::DirBuilder::new()
            .mode(0o700)
            .create(&dir)
            .map_err(|e| format!("the journal's directory {}: {e}", dir.display()))?;
        Ok(PrivateDir(dir))
    }
}

impl Drop for PrivateDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}
