//! An attached segment, typed or not: header checks, seqlock snapshots, owner liveness and
//! writes over the socket. `SharedGlobalMemory::attach` and `DynSegment::attach` both use it.

use super::client::answer_result;
use super::segment::AttachedSegment;
use crate::error::ShmError;
use crate::format::alarm_table::AlarmTable;
use crate::format::descriptor::{LayoutDescriptor, VarDescriptor};
use crate::format::header::{self, Header};
use crate::format::layout::{H_MAGIC, IMAGE, MAGIC, Offsets};
use crate::format::status::{OwnerState, Status};
use crate::format::{bytes, seqlock};
use crate::limits::{MAX_MESSAGE, MAX_WRITES};
use crate::naming::path_of;
use crate::protocol::{self, Reply, Ticket, WriteOutcome};
use crate::sys::base::Base;
use crate::sys::rundir;
use plc_core::Value;
use plc_core::write::{self, Checked, Refusal, Write};
use std::cell::{Cell, OnceCell};
use std::collections::HashMap;
use std::time::{Duration, Instant};

/// How often a reader re-checks that the owner is alive.
const LIVENESS_EVERY: Duration = Duration::from_millis(20);
/// How long a write waits for the owner's answer at least and at most: fifty of its cycles
/// in between. At least two seconds: on a loaded two-core machine a fast program's answer
/// once took longer than one (a test's request queued behind a burst of refused ones), and
/// a person waits two seconds as readily as one.
const WRITE_PATIENCE: (Duration, Duration) = (Duration::from_secs(2), Duration::from_secs(10));

pub(crate) struct View {
    pub seg: AttachedSegment,
    pub base: Base,
    pub off: Offsets,
    pub desc: LayoutDescriptor,
    pub generation: u64,
    /// Where the alarm states lie.
    pub alarms: AlarmTable,
    pub checked_alive: Cell<Option<Instant>>,
    /// Top-level variables by lower-case name, built at the first lookup: a tool that names
    /// thousands of variables (`plc get` of 4,000 names) finds each in constant time, where a
    /// scan of the descriptor per name is quadratic.
    pub names: OnceCell<HashMap<String, usize>>,
}

impl View {
    pub fn attach(name: &str) -> Result<View, ShmError> {
        let name = rundir::normalise(name)?;
        let seg = AttachedSegment::open(&name)?;
        let base = seg.base();
        let Header {
            off,
            desc,
            generation,
            alarms,
        } = header::read(&base, name)?;
        Ok(View {
            generation,
            alarms,
            seg,
            base,
            off,
            desc,
            checked_alive: Cell::new(None),
            names: OnceCell::new(),
        })
    }

    pub fn name(&self) -> &str {
        self.seg.name()
    }

    /// Errors if the owner stopped, was replaced or is gone (liveness checked at most every
    /// [`LIVENESS_EVERY`]).
    pub fn check_owner(&self) -> Result<(), ShmError> {
        header::check_current(&self.base, self.generation, self.name())?;
        let fresh = self
            .checked_alive
            .get()
            .is_some_and(|t| t.elapsed() < LIVENESS_EVERY);
        if !fresh {
            if !self.seg.owner_alive() {
                return Err(ShmError::OwnerGone(self.name().to_string()));
            }
            self.checked_alive.set(Some(Instant::now()));
        }
        Ok(())
    }

    /// Reads a consistent image with `read`, retrying while the owner writes.
    pub fn consistent<R>(&self, read: impl FnMut() -> R) -> Result<R, ShmError> {
        self.check_owner()?;
        seqlock::read(&self.base, self.name(), read, || self.check_owner())
    }

    pub fn snapshot_bytes(&self) -> Result<Vec<u8>, ShmError> {
        let mut buf = vec![0u8; self.off.image_size];
        self.consistent(|| bytes::load(&self.base, IMAGE, &mut buf))?;
        Ok(buf)
    }

    /// Index of a top-level variable by name, case-insensitively (as
    /// [`LayoutDescriptor::index_of`], the first of equal names).
    pub fn index_of(&self, name: &str) -> Option<usize> {
        let names = self.names.get_or_init(|| {
            let mut names = HashMap::with_capacity(self.desc.variables.len());
            for (i, v) in self.desc.variables.iter().enumerate() {
                names.entry(v.name.to_ascii_lowercase()).or_insert(i);
            }
            names
        });
        if name.bytes().any(|b| b.is_ascii_uppercase()) {
            names.get(&name.to_ascii_lowercase()).copied()
        } else {
            names.get(name).copied()
        }
    }

    pub fn var_index(&self, name: &str) -> Result<usize, ShmError> {
        self.index_of(name)
            .ok_or_else(|| ShmError::UnknownVariable {
                name: self.name().to_string(),
                variable: name.to_string(),
            })
    }

    pub fn read_element(&self, name: &str, element: usize) -> Result<Value, ShmError> {
        let i = self.var_index(name)?;
        let var = &self.desc.variables[i];
        if element >= var.elements() {
            return Err(ShmError::ElementOutOfRange {
                variable: var.name.clone(),
                element,
                len: var.elements(),
            });
        }
        let image = self.snapshot_bytes()?;
        Ok(var.value_in(&image, element).unwrap_or(Value::Bool(false)))
    }

    /// Checks one write as the owner will: the one check ([`plc_core::write::check`]) against
    /// this segment's descriptor.
    pub fn check_write(&self, write: Write) -> Result<Checked, ShmError> {
        write::check(&self.desc.variables, write).map_err(|r| refusal(self.name(), r))
    }

    /// Checks a write to variable `name` (element or leaf `element`) as the owner will.
    pub fn check_element(
        &self,
        name: &str,
        element: usize,
        value: Value,
    ) -> Result<Checked, ShmError> {
        let index = self.var_index(name)?;
        self.check_write(Write {
            index,
            leaf: element,
            value,
        })
    }

    /// Checks one write to variable `name` as the owner will, sends it and waits for the
    /// owner's answer.
    pub fn write_element(&self, name: &str, element: usize, value: Value) -> Result<(), ShmError> {
        let checked = self.check_element(name, element, value)?;
        self.send_and_wait(&[checked])
    }

    fn check_each(&self, writes: &[Write]) -> Result<Vec<Checked>, ShmError> {
        writes.iter().map(|&w| self.check_write(w)).collect()
    }

    /// Sends checked writes as one request.
    pub fn post(&self, requests: &[Checked]) -> Result<Ticket, ShmError> {
        self.check_owner()?;
        self.count_ok(requests.len(), MAX_WRITES, "writes")?;
        let writes: Vec<Write> = requests.iter().map(|c| *c.write()).collect();
        let bytes = protocol::request_len(&writes);
        if bytes > MAX_MESSAGE {
            return Err(ShmError::RequestTooLarge {
                name: self.name().to_string(),
                bytes,
                most: MAX_MESSAGE,
            });
        }
        self.seg.client().post(requests)
    }

    /// Errors unless `count` values (`what`: writes, forces, ...) fit one request of at most
    /// `most`.
    pub fn count_ok(&self, count: usize, most: usize, what: &'static str) -> Result<(), ShmError> {
        if (1..=most).contains(&count) {
            return Ok(());
        }
        Err(ShmError::RequestCount {
            name: self.name().to_string(),
            what,
            count,
            most,
        })
    }

    /// Checks writes as the owner will, sends them as one request and waits for the owner to
    /// apply all of them or none.
    pub fn write_all(&self, writes: &[Write]) -> Result<(), ShmError> {
        let checked = self.check_each(writes)?;
        self.send_and_wait(&checked)
    }

    /// Sends checked writes as one request and waits for the owner's answer.
    pub fn send_and_wait(&self, requests: &[Checked]) -> Result<(), ShmError> {
        let ticket = self.post(requests)?;
        let names: Vec<String> = requests.iter().map(|r| self.label(r.write())).collect();
        self.wait_answer(ticket, &names)
    }

    /// The name of a write's value, as answers name it.
    pub fn label(&self, w: &Write) -> String {
        match self.desc.variables.get(w.index) {
            Some(_) => path_of(&self.desc.variables, w.index, w.leaf),
            None => format!("#{}", w.index),
        }
    }

    /// Sends the message `encode` makes (for the request id it is given).
    pub fn post_with(&self, encode: impl FnOnce(u64) -> Vec<u8>) -> Result<Ticket, ShmError> {
        self.check_owner()?;
        self.seg.client().post_with(encode)
    }

    /// Waits for the owner's answer to `ticket` (fifty of its cycles, within bounds);
    /// `names` are the request's values, as a refusal names them.
    pub fn wait_answer(&self, ticket: Ticket, names: &[String]) -> Result<(), ShmError> {
        answer_result(self.name(), names, self.wait_reply(ticket)?)
    }

    /// The owner's answer to `ticket` as it came (fifty of its cycles, within bounds).
    pub fn wait_reply(&self, ticket: Ticket) -> Result<Reply, ShmError> {
        let period = self.status().stats.period;
        let patience = (period * 50).clamp(WRITE_PATIENCE.0, WRITE_PATIENCE.1);
        self.seg.client().wait(ticket, patience)
    }

    /// The memory file that came with the answer to `ticket`.
    pub fn take_file(&self, ticket: Ticket) -> Option<std::os::fd::OwnedFd> {
        self.seg.client().take_file(ticket)
    }

    /// Sends raw bytes on the socket (test hook for hostile messages).
    #[cfg(feature = "fault-injection")]
    pub fn send_raw(&self, bytes: &[u8]) -> Result<(), ShmError> {
        self.seg.client().send_raw(bytes)
    }

    pub fn may_write(&self) -> bool {
        self.seg.client().may_write()
    }

    pub fn outcome(&self, ticket: Ticket) -> WriteOutcome {
        self.seg.client().outcome(ticket)
    }

    pub fn status(&self) -> Status {
        Status::read(&self.base, &self.off)
    }

    pub fn owner_state(&self) -> OwnerState {
        let alive = self.seg.owner_alive();
        if self.base.load(H_MAGIC) != MAGIC {
            return OwnerState::Gone;
        }
        self.status().owner_state(alive)
    }
}

/// A refusal of the one write check, as a tool's error for segment `segment`.
pub(crate) fn refusal(segment: &str, r: Refusal<'_, VarDescriptor>) -> ShmError {
    let variable = r.label().to_string();
    match r {
        Refusal::NoVariable { index, .. } => ShmError::UnknownVariable {
            name: segment.to_string(),
            variable: format!("number {index}"),
        },
        Refusal::NotWritable { reason, .. } => ShmError::NotWritable { variable, reason },
        Refusal::NoElement { leaf, len, .. } => ShmError::ElementOutOfRange {
            variable,
            element: leaf,
            len,
        },
        Refusal::Value { error, .. } => ShmError::Value { variable, error },
    }
}
