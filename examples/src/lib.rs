//! The example programs of plc-vars (binaries in `src/bin`: `tensile_tester`, the main
//! example, and `hmi_reader`) and the code they share. The benchmarks are the `plc-bench`
//! crate (`bench/`).
#![deny(missing_docs)]

pub mod project;
pub mod tensile;
