//! `cycle_10k_over_1k`: how the cycle grows from 1,000 to 10,000 variables. A 10,000-field
//! struct takes minutes to compile, so it does not live in the examples crate (every build
//! would pay for it): `plc-bench` writes a crate with `Gm10k` (from [`super::workload`]) that
//! uses this crate's cycle code and `Gm1k`, builds it in release into the workspace's target
//! directory (the first run compiles it; later runs reuse it) and runs it, so the 1k and 10k
//! cycles are timed side by side in one process.

use std::path::Path;
use std::process::Command;

/// The generated crate's `main`: times both cycles and prints the figures.
const MAIN: &str = r#"
mod gm10k;

use examples::bench::cycle::{FrameworkCycle, HandCycle};
use examples::bench::gm1k::Gm1k;
use examples::bench::timing::{ratio, side_by_side};

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
}
"#;

/// Writes, builds and runs the crate; returns its `name: value` lines.
pub fn run(batches: usize) -> Result<String, String> {
    let workspace = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let workspace = workspace
        .canonicalize()
        .map_err(|e| format!("{}: {e}", workspace.display()))?;
    let dir = workspace.join("target/plc-bench/cycle-10k");
    let io = |e: std::io::Error| format!("{}: {e}", dir.display());
    std::fs::create_dir_all(dir.join("src")).map_err(io)?;
    let manifest = format!(
        "[package]\nname = \"cycle-10k\"\nversion = \"0.0.0\"\nedition = \"2024\"\npublish = false\n\n\
         [workspace]\n\n[dependencies]\nexamples = {{ path = {:?} }}\n\
         plc-core = {{ path = {:?}, features = [\"serde\"] }}\n\n\
         # As the workspace's, so its release artifacts are reused.\n[profile.release]\ndebug = 1\n",
        workspace.join("examples").display().to_string(),
        workspace.join("plc-core").display().to_string(),
    );
    write_if_changed(&dir.join("Cargo.toml"), &manifest).map_err(io)?;
    std::fs::copy(workspace.join("Cargo.lock"), dir.join("Cargo.lock")).map_err(io)?;
    write_if_changed(&dir.join("src/main.rs"), MAIN).map_err(io)?;
    let gm10k = super::workload::source(10, "examples::bench::cycle::HandWritten");
    let gm10k = format!("#![allow(missing_docs, clippy::identity_op)]\n{gm10k}");
    write_if_changed(&dir.join("src/gm10k.rs"), &gm10k).map_err(io)?;
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let target = workspace.join("target");
    let built = Command::new(&cargo)
        .args(["build", "--release", "--quiet"])
        .current_dir(&dir)
        .env("CARGO_TARGET_DIR", &target)
        .status()
        .map_err(|e| format!("{cargo}: {e}"))?;
    if !built.success() {
        return Err(format!("building {} failed", dir.display()));
    }
    let out = Command::new(target.join("release/cycle-10k"))
        .arg(batches.to_string())
        .output()
        .map_err(|e| format!("cycle-10k: {e}"))?;
    if !out.status.success() {
        return Err(format!(
            "cycle-10k failed: {}",
            String::from_utf8_lossy(&out.stderr)
        ));
    }
    Ok(String::from_utf8_lossy(&out.stdout).into_owned())
}

/// Writes `text` unless the file already holds it, so cargo sees no change and reuses the build.
fn write_if_changed(path: &Path, text: &str) -> std::io::Result<()> {
    if std::fs::read_to_string(path).is_ok_and(|old| old == text) {
        return Ok(());
    }
    std::fs::write(path, text)
}
