//! The runtime of plc-vars: makes a `#[derive(GlobalMemory)]` struct live.
//!
//! - `shm`: the variables in a named shared-memory segment for HMIs and tools.
//! - `retain`: nonvolatile variables that survive restarts and edits of the declaration.
//! - `alarm_journal`: every alarm transition on disk, each alarm's state across restarts.
//! - `Runtime`: the cycle: I/O exchange, bit unpacking, tools' writes, the program's tick,
//!   alarms evaluated, bit packing, publishing, retaining.
//! - `ethercat` (feature `ethercat`, default): EtherCAT I/O through ethercrab, on real
//!   hardware or the simulated bus of `ethercat-sim`.
//! - `module` (feature `module`, default): [`program!`] builds a program as a loadable module,
//!   which a host runs and swaps for a new build between two cycles.
//! - `import`: JSON and CSV variable lists to Rust (feature `import`), and back (feature
//!   `export`).
//!
//! This crate is the one a control program links; each job is a crate of its own
//! (`plc-shm`, `plc-runtime`, `plc-ethercat`, `plc-import`), re-exported here at these paths.
//! The first three are feature `runtime` (default); a build script that only imports uses
//! `default-features = false, features = ["import"]` and compiles none of them, and a tool
//! that only reads and writes running programs needs `shm` alone.
#![deny(missing_docs)]

#[cfg(feature = "ethercat")]
pub use plc_ethercat as ethercat;
#[cfg(any(feature = "import", feature = "export"))]
pub use plc_import as import;
#[cfg(feature = "module")]
pub use plc_module as module;
/// Makes a `cdylib` crate a program module that `plc run` runs and `plc change` swaps in: see
/// [`module`].
#[cfg(feature = "module")]
pub use plc_module::program;
#[cfg(feature = "runtime")]
pub use plc_runtime::{alarm_journal, retain};
#[cfg(feature = "shm")]
pub use plc_shm as shm;

/// Per-cycle timestamps for the benchmarks (feature `cycle-probe`).
#[cfg(feature = "cycle-probe")]
#[doc(hidden)]
pub use plc_runtime::probe;
#[cfg(feature = "runtime")]
pub use plc_runtime::{
    AlarmActionError, BusState, Context, CyclePhase, CycleStats, IoBackend, IoError, IoStatus,
    NoIo, Runtime, RuntimeAlarms, RuntimeBuilder, RuntimeError, StopHandle, Swap, SwapEvent,
    zero_outputs,
};
