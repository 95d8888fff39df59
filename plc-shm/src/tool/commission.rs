//! Commissioning from a tool: forcing values, releasing them, reading the forces held, and
//! tracing values every cycle. Each goes over the segment's socket like a write, checked here
//! as the owner checks it again.

use super::client::answer_result;
use super::dynamic::DynSegment;
use super::paths::PathLocation;
use super::trace::Trace;
use super::view::refusal;
use crate::error::ShmError;
use crate::format::force_table::{self, ForceInfo};
use crate::limits::{MAX_TRACED, MAX_WRITES};
use crate::naming::path_of;
use crate::protocol::{self, Code, Release, TraceRequest, WriteRequest};
use plc_core::write::{self, Checked, Write};

impl DynSegment {
    /// Checks a force as the owner will ([`plc_core::write::check_force`]: any basic value,
    /// inputs and status included; the value must fit).
    pub fn check_force(&self, force: Write) -> Result<Checked, ShmError> {
        write::check_force(&self.descriptor().variables, force).map_err(|r| refusal(self.name(), r))
    }

    /// Forces values (checked by [`check_force`](Self::check_force); at most
    /// [`MAX_WRITES`] per call and [`MAX_FORCES`](crate::limits::MAX_FORCES) held at once): the owner holds each at both of its cycle's boundaries
    /// until it is released or the program stops, and refuses writes to it. Who may force is
    /// who may write. Returns once the owner holds them, or with its refusal.
    ///
    /// ```no_run
    /// use plc_core::{Value, write::Write};
    /// let seg = plc_shm::DynSegment::attach("tensile_tester")?;
    /// let lamp = seg.index_of("lamp_ready").expect("declared");
    /// let on = seg.check_force(Write { index: lamp, leaf: 0, value: Value::Bool(true) })?;
    /// seg.force(&[on])?;
    /// seg.release(&[(lamp, 0)], false)?;
    /// # Ok::<(), plc_shm::ShmError>(())
    /// ```
    pub fn force(&self, forces: &[Checked]) -> Result<(), ShmError> {
        self.view.count_ok(forces.len(), MAX_WRITES, "forces")?;
        let request = |id| WriteRequest {
            id,
            writes: forces.iter().map(|f| *f.write()).collect(),
        };
        let ticket = self
            .view
            .post_with(|id| protocol::encode_force(&request(id)))?;
        let names: Vec<String> = forces.iter().map(|f| self.view.label(f.write())).collect();
        self.view.wait_answer(ticket, &names)
    }

    /// Ends the forces of these values ((variable index, leaf); each must be forced, at most
    /// [`MAX_WRITES`] per call): with `restore` each value is set back to what it was before its force, else the
    /// program's next value stands.
    pub fn release(&self, values: &[(usize, usize)], restore: bool) -> Result<(), ShmError> {
        self.view.count_ok(values.len(), MAX_WRITES, "releases")?;
        self.send_release(values, restore, false)
    }

    /// Ends every force.
    pub fn release_all(&self, restore: bool) -> Result<(), ShmError> {
        self.send_release(&[], restore, true)
    }

    fn send_release(
        &self,
        values: &[(usize, usize)],
        restore: bool,
        all: bool,
    ) -> Result<(), ShmError> {
        let ticket = self.view.post_with(|id| {
            protocol::encode_release(&Release {
                id,
                restore,
                all,
                values: values.to_vec(),
            })
        })?;
        let names: Vec<String> = values
            .iter()
            .map(|&(index, leaf)| path_of(&self.descriptor().variables, index, leaf))
            .collect();
        self.view.wait_answer(ticket, &names)
    }

    /// The forces held now, as the owner published them (their values are in the image).
    pub fn forces(&self) -> Result<Vec<ForceInfo>, ShmError> {
        self.view.check_owner()?;
        force_table::read(&self.view.base, &self.view.off)
            .ok_or_else(|| ShmError::Stuck(self.name().into()))
    }

    /// Starts a trace of `values` (basic values found by [`locate`](Self::locate), no STRING,
    /// at most [`MAX_TRACED`]), recorded by the owner every `every`th cycle from its next cycle on, for
    /// as long as this segment handle stays attached. Drain it with [`Trace::drain`].
    ///
    /// ```no_run
    /// let seg = plc_shm::DynSegment::attach("tensile_tester")?;
    /// let force = seg.locate("force_kn")?;
    /// let mut trace = seg.trace(&[force], 1)?;
    /// let mut rows = Vec::new();
    /// std::thread::sleep(std::time::Duration::from_millis(50));
    /// trace.drain(&mut rows, 100_000);
    /// # Ok::<(), plc_shm::ShmError>(())
    /// ```
    pub fn trace(&self, values: &[PathLocation], every: u32) -> Result<Trace, ShmError> {
        self.view
            .count_ok(values.len(), MAX_TRACED, "traced values")?;
        if let Some(s) = values
            .iter()
            .find(|v| v.var.iec_type == plc_core::IecType::String)
        {
            return Err(ShmError::NotTraceable {
                name: self.name().to_string(),
                path: s.path.clone(),
            });
        }
        let ticket = self.view.post_with(|id| {
            protocol::encode_trace(&TraceRequest {
                id,
                every: every.max(1),
                values: values.iter().map(|v| (v.index, v.leaf)).collect(),
            })
        })?;
        let names: Vec<String> = values.iter().map(|v| v.path.clone()).collect();
        let reply = self.view.wait_reply(ticket)?;
        // A trace refused for now says why (traces already running, one per connection),
        // not that writes wait.
        if reply.code == Code::Busy {
            return Err(ShmError::Busy {
                name: self.name().to_string(),
                reason: reply.reason,
            });
        }
        answer_result(self.name(), &names, reply)?;
        let fd = self
            .view
            .take_file(ticket)
            .ok_or_else(|| ShmError::Protocol {
                name: self.name().to_string(),
                why: "its answer to the trace came without the trace's memory".into(),
            })?;
        Trace::receive(self.name(), fd, values)
    }
}
