//! Ways for a MainDevice's frames to reach the simulated bus.

pub mod inproc;
#[cfg(target_os = "linux")]
pub mod raw;
