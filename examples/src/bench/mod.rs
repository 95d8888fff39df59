//! Workloads of the benchmarks (`plc-bench`).
// The workload is generated; its fields document themselves by name.
#![allow(missing_docs)]

// Generated shifts include `>> 0` and `<< 0`, kept for regularity.
#[allow(clippy::identity_op)]
pub mod gm1k;
