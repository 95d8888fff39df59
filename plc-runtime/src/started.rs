//! The one line every program logs once its first cycle ran, whatever the program: its
//! segment, its bus's state, its retain file and how many values it loaded. An operator
//! reading a journal sees that it started and how, without the program printing it.

use plc_shm::IoStatus;
use std::path::PathBuf;

/// What the line says besides the bus, known at start.
pub(super) struct Started {
    pub segment: Option<String>,
    /// The retain file and how many values it gave back.
    pub retain: Option<(PathBuf, usize)>,
}

impl Started {
    /// Logs the line, with the first cycle's I/O.
    pub fn log(self, io: &IoStatus) {
        let segment = match &self.segment {
            Some(name) => format!("segment `{name}`"),
            None => "no segment".into(),
        };
        let retain = match &self.retain {
            Some((path, n)) => format!(
                "retain file {} ({n} value{} loaded)",
                path.display(),
                if *n == 1 { "" } else { "s" }
            ),
            None => "no retain file".into(),
        };
        log::info!(target: "plc_io::runtime",
            "running: {segment}, bus {}, {retain}", io.bus_state.name());
    }
}
