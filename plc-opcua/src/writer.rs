//! A segment's writer thread: Writes go through the program's own write path (the checks of
//! `plc set`, then the mailbox the program applies at the start of a cycle), one Write of a
//! node as one batch, so an array written whole lands in one cycle. Every write is logged with
//! the OPC UA user and the old and new value; every refusal with its reason.
//!
//! It has its own attachment, so a write waiting for the program to take it never delays the
//! sampler's snapshots or anyone's Reads.

use crate::mapping;
use crate::shared::{Shared, WriteJob};
use opcua::types::StatusCode;
use plc_core::Value;
use plc_core::write::Write;
use plc_shm::{DynSegment, ShmError};
use std::sync::Arc;
use std::sync::mpsc::Receiver;

/// The writer of one segment.
pub struct Writer {
    shared: Arc<Shared>,
    seg: Option<DynSegment>,
}

impl Writer {
    /// The writer of `shared`'s segment (it attaches at its first write).
    pub fn new(shared: Arc<Shared>) -> Writer {
        Writer { shared, seg: None }
    }

    /// Runs until the node manager is gone.
    pub fn run(mut self, jobs: Receiver<WriteJob>) {
        while let Ok(job) = jobs.recv() {
            let status = self.write(&job);
            let _ = job.reply.send(status);
        }
    }

    fn write(&mut self, job: &WriteJob) -> StatusCode {
        let segment = self.shared.segment.clone();
        let layout = self.shared.layout();
        let Some(node) = layout.var(&job.node) else {
            return StatusCode::BadNodeIdUnknown;
        };
        let var = &node.var;
        // A write of part of an array (an index range) names the elements it set.
        let target = match job.elements.as_slice() {
            [(e, _)] if !var.dims.is_empty() => format!("{segment}.{}[{e}]", node.path),
            part if part.len() < var.elements() => {
                let elements: Vec<String> = part.iter().map(|(e, _)| e.to_string()).collect();
                format!("{segment}.{} (elements {})", node.path, elements.join(", "))
            }
            _ => format!("{segment}.{}", node.path),
        };
        // Writes go to the top-level variable, a member's elements by their leaf numbers.
        let batch: Vec<Write> = job
            .elements
            .iter()
            .map(|&(e, value)| Write {
                index: node.index,
                leaf: node.first_leaf + e,
                value,
            })
            .collect();
        // A program restarted since the last write: attach again once and retry.
        for attempt in 0..2 {
            let seg = match self.attached() {
                Ok(seg) => seg,
                Err(e) => return refused(&job.user, &target, &e),
            };
            let old = seg.snapshot_bytes().ok().map(|image| {
                let values = job.elements.iter().map(|&(e, _)| var.value_in(&image, e));
                show(values)
            });
            match seg.write_all(&batch) {
                Ok(()) => {
                    log::info!(
                        "OPC UA write by `{}`: {target}: {} -> {}",
                        job.user,
                        old.as_deref().unwrap_or("?"),
                        show(job.elements.iter().map(|&(_, v)| Some(v)))
                    );
                    return StatusCode::Good;
                }
                Err(ShmError::Replaced(_) | ShmError::Closed { .. } | ShmError::OwnerGone(_))
                    if attempt == 0 =>
                {
                    self.seg = None;
                }
                Err(e) => return refused(&job.user, &target, &e),
            }
        }
        StatusCode::BadNoCommunication
    }

    fn attached(&mut self) -> Result<&DynSegment, ShmError> {
        let seg = match self.seg.take() {
            Some(seg) => seg,
            None => DynSegment::attach(&self.shared.segment)?,
        };
        Ok(self.seg.insert(seg))
    }
}

/// Logs a write the program's write path refused and gives its status code.
fn refused(user: &str, target: &str, e: &ShmError) -> StatusCode {
    log_refusal(user, target, e, mapping::write_refusal(e))
}

/// Refused writes, logged at a bounded rate.
static REFUSED: plc_shm::LogLimit = plc_shm::LogLimit::new("plc_opcua::writer");

/// Logs a refused write with its reason and status code (at a bounded rate), and gives the
/// code.
pub fn log_refusal(
    user: &str,
    target: &str,
    why: &dyn std::fmt::Display,
    status: StatusCode,
) -> StatusCode {
    REFUSED.warn(|| format!("OPC UA write by `{user}` refused: {target}: {why} ({status})"));
    status
}

/// Values as the log shows them: one, or a bracketed list.
fn show(values: impl Iterator<Item = Option<Value>>) -> String {
    let texts: Vec<String> = values
        .map(|v| v.map_or_else(|| "?".to_string(), |v| plc_shm::shown_in_log(&v)))
        .collect();
    match texts.as_slice() {
        [one] => one.clone(),
        many => format!("[{}]", many.join(", ")),
    }
}
