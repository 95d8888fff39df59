//! Group `tools`: what a tool costs against a running program of 4,000 variables
//! ([`super::owner`]'s `Flat4k`, a real owner process at 1 ms).
//!
//! - `tools_read_4000_us`: the 4,000 names found in the segment's descriptor, one snapshot,
//!   the 4,000 values decoded, through `DynSegment` in this process (median of batches).
//!   `tools_read_4000_scan_us` is the same with each name found by a scan of the descriptor
//!   (`LayoutDescriptor::index_of`), side by side: what a tool paid before
//!   `DynSegment::index_of`.
//! - `plc_get_4000_ms`: the real `plc get SEGMENT name...` with the 4,000 names on its command
//!   line, as a whole process (start, attach, descriptor, lookups, snapshot, printing, exit),
//!   wall time, median of runs, its output read through a pipe.
//! - `watch_4000_frame_p99_ms`: the real `plc watch SEGMENT --rate 10` in a terminal (a tmux
//!   session of its own, 200 x 50) for some seconds, each periodic frame's time as `plc watch`
//!   logs it with `PLC_WATCH_FRAME_LOG` (snapshot, the 4,000 values formatted, the window drawn
//!   and written to the terminal).

use super::owner::{self, Owner};
use super::timing::side_by_side;
use plc_io::shm::DynSegment;
use std::fmt::Write;
use std::hint::black_box;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Runs the group; its `name: value` lines.
pub fn run(quick: bool) -> Result<String, String> {
    let binary = owner::build()?;
    let plc = owner::plc_binary()?;
    let segment = format!("plc_bench_tools_{}", std::process::id());
    let program = Owner::start(&binary, "4k", &segment)?;
    let seg = DynSegment::attach(&segment).map_err(|e| e.to_string())?;
    let names = owner::leaf_paths(&seg);
    if names.len() != 4000 {
        return Err(format!(
            "the 4k program has {} variables, not 4,000",
            names.len()
        ));
    }
    let mut out = String::new();
    let (hashed, scan) = read_by_name(&seg, &names, if quick { 15 } else { 61 })?;
    let _ = writeln!(out, "tools_read_4000_us: {:.0}", hashed.as_secs_f64() * 1e6);
    let _ = writeln!(
        out,
        "tools_read_4000_scan_us: {:.0}",
        scan.as_secs_f64() * 1e6
    );
    let get = plc_get(&plc, &segment, &names, if quick { 5 } else { 15 })?;
    let _ = writeln!(out, "plc_get_4000_ms: {:.1}", get.as_secs_f64() * 1e3);
    let seconds = if quick { 10 } else { 30 };
    match watch_frames(&plc, &segment, seconds) {
        Ok((p99, frames)) => {
            let _ = writeln!(
                out,
                "watch_4000_frame_p99_ms: {:.1}",
                p99.as_secs_f64() * 1e3
            );
            let _ = writeln!(out, "watch_4000_frames: {frames}");
        }
        Err(why) => {
            let _ = writeln!(out, "watch_4000_frame_p99_ms: unavailable ({why})");
        }
    }
    drop(seg);
    drop(program);
    Ok(out)
}

/// Every name found, one snapshot, every value decoded: the median time of the hashed lookup
/// (`DynSegment::index_of`) and of a scan of the descriptor per name, in alternating batches.
fn read_by_name(
    seg: &DynSegment,
    names: &[String],
    batches: usize,
) -> Result<(Duration, Duration), String> {
    let read = |find: &dyn Fn(&str) -> Option<usize>| -> Result<usize, String> {
        let indexes: Vec<usize> = names
            .iter()
            .map(|n| find(n).ok_or_else(|| format!("no variable `{n}`")))
            .collect::<Result<_, _>>()?;
        let image = seg.snapshot_bytes().map_err(|e| e.to_string())?;
        let values = indexes
            .iter()
            .filter_map(|&i| seg.descriptor().variables.get(i)?.value_in(&image, 0))
            .count();
        Ok(black_box(values))
    };
    // Once outside the timing, to report a failure instead of timing it.
    let found = read(&|n| seg.index_of(n))?;
    if found != names.len() {
        return Err(format!("{found} of {} values decoded", names.len()));
    }
    let (hashed, scan) = side_by_side(
        batches,
        1,
        || {
            let _ = read(&|n| seg.index_of(n));
        },
        || {
            let _ = read(&|n| seg.descriptor().index_of(n));
        },
    );
    Ok((hashed, scan))
}

/// The median wall time of `plc get SEGMENT names...` as a whole process.
fn plc_get(plc: &Path, segment: &str, names: &[String], runs: usize) -> Result<Duration, String> {
    let mut times = Vec::new();
    for _ in 0..runs.max(1) {
        let start = Instant::now();
        let out = Command::new(plc)
            .arg("get")
            .arg(segment)
            .args(names)
            .stdin(Stdio::null())
            .output()
            .map_err(|e| format!("{}: {e}", plc.display()))?;
        let took = start.elapsed();
        if !out.status.success() {
            return Err(format!(
                "plc get failed: {}",
                String::from_utf8_lossy(&out.stderr)
            ));
        }
        let lines = out.stdout.iter().filter(|&&b| b == b'\n').count();
        if lines != names.len() {
            return Err(format!(
                "plc get printed {lines} lines for {} names",
                names.len()
            ));
        }
        times.push(took);
    }
    times.sort();
    Ok(times[times.len() / 2])
}

/// Runs `plc watch SEGMENT --rate 10` in a tmux session of its own for `seconds`; the 99th
/// percentile of its frames' times and the number of frames.
fn watch_frames(plc: &Path, segment: &str, seconds: u64) -> Result<(Duration, usize), String> {
    let tmux_here = Command::new("tmux")
        .arg("-V")
        .output()
        .is_ok_and(|o| o.status.success());
    if !tmux_here {
        return Err("no tmux".into());
    }
    let log: PathBuf = std::env::temp_dir().join(format!(
        "plc-bench-watch-{}-{}.log",
        std::process::id(),
        segment
    ));
    let _ = std::fs::remove_file(&log);
    // A tmux server of our own (`-L`): nothing of anyone else's tmux is touched, and
    // kill-server ends only it.
    let socket = format!("plc-bench-{}", std::process::id());
    let command = format!(
        "PLC_WATCH_FRAME_LOG={} exec {} watch {} --rate 10",
        shell_quote(&log.to_string_lossy()),
        shell_quote(&plc.to_string_lossy()),
        shell_quote(segment)
    );
    let started = Command::new("tmux")
        .args(["-L", &socket, "-f", "/dev/null", "new-session", "-d"])
        .args(["-x", "200", "-y", "50", &command])
        .status()
        .map_err(|e| format!("tmux: {e}"))?;
    if !started.success() {
        return Err("tmux new-session failed".into());
    }
    std::thread::sleep(Duration::from_secs(seconds));
    let _ = Command::new("tmux")
        .args(["-L", &socket, "kill-server"])
        .status();
    let text = std::fs::read_to_string(&log).map_err(|e| format!("{}: {e}", log.display()))?;
    let _ = std::fs::remove_file(&log);
    let mut frames: Vec<u64> = text.lines().filter_map(|l| l.trim().parse().ok()).collect();
    // The first frame fills the terminal from nothing; the figure is the steady refresh.
    if frames.len() < 10 {
        return Err(format!("only {} frames in {seconds} s", frames.len()));
    }
    frames.remove(0);
    frames.sort_unstable();
    let p99 = frames[(frames.len() * 99 / 100).min(frames.len() - 1)];
    Ok((Duration::from_micros(p99), frames.len()))
}

/// `text` in single quotes for sh.
fn shell_quote(text: &str) -> String {
    format!("'{}'", text.replace('\'', r"'\''"))
}
