//! The runtime of plc-vars: makes a `#[derive(GlobalMemory)]` struct live.
//!
//! - [`shm`]: the variables in a named shared-memory segment for HMIs and tools.
//! - [`retain`]: nonvolatile variables that survive restarts and edits of the declaration.
//! - [`Runtime`]: the cycle: I/O exchange, bit unpacking, mailbox writes, the program's tick,
//!   bit packing, publishing, retaining.
//! - [`ethercat`] (feature `ethercat`, default): EtherCAT I/O through ethercrab, on real
//!   hardware or the simulated bus of `ethercat-sim`.
//! - `import` (feature `import`): JSON variable lists to Rust, and back.
#![deny(missing_docs)]

#[cfg(feature = "ethercat")]
pub mod ethercat;
#[cfg(feature = "import")]
pub mod import;
pub mod retain;
pub(crate) mod runtime;
pub mod shm;

pub use runtime::{
    Context, CycleStats, IoBackend, IoError, IoStatus, NoIo, Runtime, RuntimeBuilder, RuntimeError,
    StopHandle, zero_outputs,
};
