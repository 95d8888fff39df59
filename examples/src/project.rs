//! The struct generated from `examples/project.json` by `build.rs` (`plc_io::import`): every
//! field has a doc comment, so it passes the crate's `#![deny(missing_docs)]` as it is.

include!(concat!(env!("OUT_DIR"), "/project.rs"));

/// The struct generated from `examples/project.csv`, a variable list kept as a spreadsheet (the
/// HMI column and door switches of the tester), by the same `build.rs`.
pub mod from_csv {
    include!(concat!(env!("OUT_DIR"), "/project_csv.rs"));
}
