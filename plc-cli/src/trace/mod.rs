//! The tool side of `plc trace`: what becomes of the rows the program recorded.
//!
//! The program (the owner of the segment) records the traced variables every cycle, or every
//! Nth, into a ring the tool drains; the transport turns what it drains into [`Row`]s. From
//! there everything is pure, so it is tested without a running program:
//!
//! - [`trigger`]: `--trigger EXPR`, parsed before the segment is known, then bound to a column;
//! - [`capture`]: `--pre`/`--post` around the trigger, and the gaps the transport reports;
//! - [`csv`]: the rows as a CSV file;
//! - [`plot`]: the rows as an SVG picture.

pub mod capture;
pub mod csv;
pub mod plot;
pub mod trigger;

use plc_core::{IecType, Value};

/// One traced variable.
#[derive(Clone, Debug, PartialEq)]
pub struct Column {
    /// The variable's path as the user gave it, canonical (`axes[1].actual`).
    pub path: String,
    /// Its type, which decides how values are written and drawn.
    pub iec_type: IecType,
    /// The variable's `quantity`, e.g. `"kN"`, shown beside its path in the picture.
    pub unit: Option<String>,
}

/// One recorded cycle.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// The program's cycle counter when the values were taken.
    pub cycle: u64,
    /// The cycle's time, in nanoseconds since the program started.
    pub time_ns: u64,
    /// One value per [`Column`], in the same order.
    pub values: Vec<Value>,
}
