//! The runtime of plc-vars: makes a `#[derive(GlobalMemory)]` struct live.
//!
//! - `shm`: the variables in a named shared-memory segment for HMIs and tools.
//! - `retain`: nonvolatile variables that survive restarts and edits of the declaration.
//! - `Runtime`: the cycle: I/O exchange, bit unpacking, mailbox writes, the program's tick,
//!   bit packing, publishing, retaining.
//! - `ethercat` (feature `ethercat`, default): EtherCAT I/O through ethercrab, on real
//!   hardware or the simulated bus of `ethercat-sim`.
//! - `import`: JSON and CSV variable lists to Rust (feature `import`), and back (feature
//!   `export`).
//!
//! The first three are feature `runtime` (default); a build script that only imports uses
//! `default-features = false, features = ["import"]` and compiles none of them.
#![deny(missing_docs)]

#[cfg(feature = "ethercat")]
pub mod ethercat;
#[cfg(any(feature = "import", feature = "export"))]
pub mod import;
#[cfg(feature = "runtime")]
pub mod retain;
#[cfg(feature = "runtime")]
pub(crate) mod runtime;
#[cfg(feature = "runtime")]
pub mod shm;

/// Per-cycle timestamps for the benchmarks (feature `cycle-probe`).
#[cfg(feature = "cycle-probe")]
#[doc(hidden)]
pub use runtime::probe;
#[cfg(feature = "runtime")]
pub use runtime::{
    BusState, Context, CycleStats, IoBackend, IoError, IoStatus, NoIo, Runtime, RuntimeBuilder,
    RuntimeError, StopHandle, zero_outputs,
};
