//! The struct generated from `examples/project.json` by `build.rs` (`plc_io::import`).
// Variables without a description in the JSON have no doc comment.
#![allow(missing_docs)]

include!(concat!(env!("OUT_DIR"), "/project.rs"));
