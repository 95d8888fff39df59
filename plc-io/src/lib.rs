//! Placeholder: the runtime lands with its issue.
#[cfg(feature = "ethercat")]
pub mod ethercat;
