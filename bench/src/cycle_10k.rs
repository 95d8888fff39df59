//! `cycle_10k_over_1k`: how the cycle grows from 1,000 to 10,000 variables. A 10,000-field
//! struct takes minutes to compile, so it does not live in the bench crate (every build
//! would pay for it): `plc-bench` writes a crate with `Gm10k` (from [`super::workload`]) that
//! uses this crate's cycle code and `Gm1k`, builds it in release into the workspace's target
//! directory (the first run compiles it; later runs reuse it) and runs it, so the 1k and 10k
//! cycles are timed side by side in one process.
//!
//! `cycle_100k_over_10k` (the opt-in group `cycle_100k`, `--full`): the same for `Gm100k`
//! against `Gm10k`, in a crate of its own that holds both; `cycle_100k_check_s` is the
//! `cargo check` of that crate (dependencies checked before, incremental compilation off, so
//! the two declarations are checked whole).

use std::os::unix::process::ExitStatusExt;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The generated crate's `main`: times both cycles and prints the figures.
const MAIN: &str = r#"
mod gm10k;

use plc_bench::cycle::{FrameworkCycle, HandCycle, growth_by_part};
use plc_bench::gm1k::Gm1k;
use plc_bench::timing::{ratio, side_by_side};

fn main() {
    let batches: usize = std::env::args().nth(1).and_then(|b| b.parse().ok()).unwrap_or(61);
    let pid = std::process::id();
    let mut small = FrameworkCycle::<Gm1k>::new(&format!("plc_bench_1k_{pid}")).expect("segment");
    let mut large =
        FrameworkCycle::<gm10k::Gm10k>::new(&format!("plc_bench_10k_{pid}")).expect("segment");
    let mut hand = HandCycle::<gm10k::Hand10k>::default();
    // Ten 1k cycles against one 10k cycle, so both sides do the same number of variables.
    let (one_k, ten_k) = side_by_side(
        batches,
        200,
        || {
            for _ in 0..10 {
                small.step();
            }
        },
        || large.step(),
    );
    let (ours, theirs) = side_by_side(batches, 200, || large.step(), || hand.step());
    println!("cycle_10k_ns: {}", ten_k.as_nanos());
    println!("cycle_10k_vs_handwritten: {:.2}", ratio(ours, theirs));
    println!("cycle_10k_over_1k: {:.2}", 10.0 * ratio(ten_k, one_k));
    growth_by_part(batches / 4, 200, &mut small, &mut large, ("1k", "10k"));
}
"#;

/// The 100k crate's `main`: one 100k cycle against ten 10k cycles.
const MAIN_100K: &str = r#"
mod gm10k;
mod gm100k;

use plc_bench::cycle::{FrameworkCycle, growth_by_part};
use plc_bench::timing::{ratio, side_by_side};

fn main() {
    let batches: usize = std::env::args().nth(1).and_then(|b| b.parse().ok()).unwrap_or(61);
    let pid = std::process::id();
    let mut small =
        FrameworkCycle::<gm10k::Gm10k>::new(&format!("plc_bench_10k_{pid}")).expect("segment");
    let mut large =
        FrameworkCycle::<gm100k::Gm100k>::new(&format!("plc_bench_100k_{pid}")).expect("segment");
    let (ten_k, hundred_k) = side_by_side(
        batches,
        20,
        || {
            for _ in 0..10 {
                small.step();
            }
        },
        || large.step(),
    );
    println!("cycle_100k_ns: {}", hundred_k.as_nanos());
    println!("cycle_100k_over_10k: {:.2}", 10.0 * ratio(hundred_k, ten_k));
    growth_by_part(batches / 4, 20, &mut small, &mut large, ("10k", "100k"));
}
"#;

/// Writes, builds and runs the 10k crate; returns its `name: value` lines.
pub fn run(batches: usize) -> Result<String, String> {
    let dir = write_crate("cycle-10k", MAIN, &[(10, true)])?;
    build_and_run(&dir, "cycle-10k", batches)
}

/// Writes, checks, builds and runs the 100k crate; returns its `name: value` lines, the check
/// time first.
pub fn run_100k(batches: usize) -> Result<String, String> {
    let dir = write_crate("cycle-100k", MAIN_100K, &[(10, false), (100, false)])?;
    let check_s = check(&dir)?;
    let lines = build_and_run(&dir, "cycle-100k", batches)?;
    Ok(format!("cycle_100k_check_s: {check_s:.1}\n{lines}"))
}

/// Writes crate `name` under `target/plc-bench/` with `main` and a module `gm{k}k` per
/// workload (`Gm{k}k`, with its hand-written twin when asked); returns its directory.
fn write_crate(name: &str, main: &str, workloads: &[(usize, bool)]) -> Result<PathBuf, String> {
    let workspace = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let workspace = workspace
        .canonicalize()
        .map_err(|e| format!("{}: {e}", workspace.display()))?;
    let dir = workspace.join("target/plc-bench").join(name);
    let io = |e: std::io::Error| format!("{}: {e}", dir.display());
    std::fs::create_dir_all(dir.join("src")).map_err(io)?;
    let manifest = format!(
        "[package]\nname = \"{name}\"\nversion = \"0.0.0\"\nedition = \"2024\"\npublish = false\n\n\
         [workspace]\n\n[dependencies]\nplc-bench = {{ path = {:?} }}\n\
         plc-core = {{ path = {:?}, features = [\"serde\"] }}\n\n\
         # As the workspace's, so its release artifacts are reused.\n[profile.release]\ndebug = 1\n",
        workspace.join("bench").display().to_string(),
        workspace.join("plc-core").display().to_string(),
    );
    write_if_changed(&dir.join("Cargo.toml"), &manifest).map_err(io)?;
    std::fs::copy(workspace.join("Cargo.lock"), dir.join("Cargo.lock")).map_err(io)?;
    write_if_changed(&dir.join("src/main.rs"), main).map_err(io)?;
    for &(k, hand) in workloads {
        let source = if hand {
            super::workload::source(k, "plc_bench::cycle::HandWritten")
        } else {
            super::workload::derive_source(k)
        };
        let source = format!("#![allow(missing_docs, clippy::identity_op)]\n{source}");
        write_if_changed(&dir.join(format!("src/gm{k}k.rs")), &source).map_err(io)?;
    }
    Ok(dir)
}

/// The workspace and its target directory, which the generated crates share.
pub(crate) fn target() -> Result<PathBuf, String> {
    let workspace = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    workspace
        .canonicalize()
        .map(|w| w.join("target"))
        .map_err(|e| format!("{}: {e}", workspace.display()))
}

/// The cargo that runs plc-bench, to build the generated crates.
pub(crate) fn cargo() -> String {
    std::env::var("CARGO").unwrap_or_else(|_| "cargo".into())
}

/// Seconds of a `cargo check` of the crate at `dir` whole: its dependencies are checked
/// first and not counted, and the timed check runs without incremental compilation after
/// its sources are touched (it checks the crate itself only).
fn check(dir: &Path) -> Result<f64, String> {
    let target = target()?;
    let run = |packages: &[&str]| {
        Command::new(cargo())
            .args(["check", "--quiet"])
            .args(packages.iter().flat_map(|p| ["-p", p]))
            .current_dir(dir)
            .env("CARGO_TARGET_DIR", &target)
            .env("CARGO_INCREMENTAL", "0")
            .status()
            .map_err(|e| format!("{}: {e}", cargo()))
    };
    let failed = |status: std::process::ExitStatus| {
        // The OOM killer ends a check that needs more memory than the machine has (a
        // 100,000-variable declaration needed more than 24 GiB: docs/benchmarks-history.md).
        let hint = if status.signal() == Some(libc::SIGKILL) {
            ": killed, most likely for want of memory (see the kernel log)"
        } else {
            ""
        };
        Err(format!(
            "checking {} failed ({status}){hint}",
            dir.display()
        ))
    };
    // The dependencies alone first (a 100,000-variable crate takes minutes to check: once is
    // enough), then the crate with its sources touched.
    let status = run(&["plc-bench", "plc-core"])?;
    if !status.success() {
        return failed(status);
    }
    let main = dir.join("src/main.rs");
    let text = std::fs::read_to_string(&main).map_err(|e| format!("{}: {e}", main.display()))?;
    std::fs::write(&main, text).map_err(|e| format!("{}: {e}", main.display()))?;
    let start = std::time::Instant::now();
    let status = run(&[])?;
    if !status.success() {
        return failed(status);
    }
    Ok(start.elapsed().as_secs_f64())
}

/// Builds the crate at `dir` (binary `bin`) in release and runs it.
fn build_and_run(dir: &Path, bin: &str, batches: usize) -> Result<String, String> {
    let (cargo, target) = (cargo(), target()?);
    let built = Command::new(&cargo)
        .args(["build", "--release", "--quiet"])
        .current_dir(dir)
        .env("CARGO_TARGET_DIR", &target)
        .status()
        .map_err(|e| format!("{cargo}: {e}"))?;
    if !built.success() {
        return Err(format!("building {} failed", dir.display()));
    }
    let out = Command::new(target.join("release").join(bin))
        .arg(batches.to_string())
        .output()
        .map_err(|e| format!("{bin}: {e}"))?;
    if !out.status.success() {
        return Err(format!(
            "{bin} failed: {}",
            String::from_utf8_lossy(&out.stderr)
        ));
    }
    Ok(String::from_utf8_lossy(&out.stdout).into_owned())
}

/// Writes `text` unless the file already holds it, so cargo sees no change and reuses the build.
pub(crate) fn write_if_changed(path: &Path, text: &str) -> std::io::Result<()> {
    if std::fs::read_to_string(path).is_ok_and(|old| old == text) {
        return Ok(());
    }
    std::fs::write(path, text)
}
