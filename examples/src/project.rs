//! The struct generated from `examples/project.json` by `build.rs` (`plc_io::import`): every
//! field has a doc comment, so it passes the crate's `#![deny(missing_docs)]` as it is.

include!(concat!(env!("OUT_DIR"), "/project.rs"));
