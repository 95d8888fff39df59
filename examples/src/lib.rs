//! The example programs of plc-vars (binaries in `src/bin`) and the code they share.
#![deny(missing_docs)]

pub mod bench;
pub mod project;
pub mod tensile;
