//! Workloads and measurements of the benchmarks (`plc-bench`, `cargo bench -p examples`).
//! Method and results: BENCHMARKS.md.

pub mod cycle;
pub mod derive_check;
pub mod hand_seqlock;
pub mod timing;

// The workload is generated (scripts/gen-bench-workload.py); its fields document themselves by
// name, and its shifts include `>> 0` and `<< 0`, kept for regularity.
#[allow(missing_docs, clippy::identity_op)]
pub mod gm1k;
