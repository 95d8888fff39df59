//! `DynSegment`: a running program's variables for tools that do not have its Rust type.

use super::view::View;
use crate::error::ShmError;
use crate::format::descriptor::LayoutDescriptor;
use crate::format::status::{OwnerState, Status};
use crate::protocol::{Ticket, WriteOutcome};
use plc_core::Value;
use plc_core::write::{Checked, Write};

/// A segment attached through its stored descriptor (what `plc` uses).
///
/// ```no_run
/// let seg = plc_shm::DynSegment::attach("tensile_tester")?;
/// for v in &seg.descriptor().variables {
///     println!("{} = {}", v.name, seg.read(&v.name)?);
/// }
/// seg.write("speed_setpoint", plc_core::Value::Real(1.5))?;
/// # Ok::<(), plc_shm::ShmError>(())
/// ```
pub struct DynSegment {
    pub(crate) view: View,
}

impl DynSegment {
    /// Attaches to segment `name` (`press`, `plc.press` and the path of its socket all work):
    /// connects to the program's socket, receives its segment and maps it read-only.
    pub fn attach(name: &str) -> Result<Self, ShmError> {
        Ok(DynSegment {
            view: View::attach(name)?,
        })
    }

    /// The segment's name.
    pub fn name(&self) -> &str {
        self.view.name()
    }

    /// Every variable's metadata.
    pub fn descriptor(&self) -> &LayoutDescriptor {
        &self.view.desc
    }

    /// The status block.
    pub fn status(&self) -> Status {
        self.view.status()
    }

    /// The owner's state: running, stalled, faulted, stopped or gone.
    pub fn owner_state(&self) -> OwnerState {
        self.view.owner_state()
    }

    /// Index of a top-level variable by name, case-insensitively: what
    /// [`LayoutDescriptor::index_of`] finds, from an index built at the first lookup, so
    /// finding each of thousands of names costs the same as finding one.
    ///
    /// ```no_run
    /// let seg = plc_shm::DynSegment::attach("tensile_tester")?;
    /// let i = seg.index_of("SPEED_SETPOINT").expect("declared");
    /// assert_eq!(seg.descriptor().variables[i].name, "speed_setpoint");
    /// # Ok::<(), plc_shm::ShmError>(())
    /// ```
    pub fn index_of(&self, name: &str) -> Option<usize> {
        self.view.index_of(name)
    }

    /// A consistent copy of the whole image; a value in it is
    /// [`VarDescriptor::value_in`](crate::VarDescriptor::value_in).
    pub fn snapshot_bytes(&self) -> Result<Vec<u8>, ShmError> {
        self.view.snapshot_bytes()
    }

    /// One variable's value (element 0 of an array).
    pub fn read(&self, name: &str) -> Result<Value, ShmError> {
        self.view.read_element(name, 0)
    }

    /// One element of a variable.
    pub fn read_element(&self, name: &str, element: usize) -> Result<Value, ShmError> {
        self.view.read_element(name, element)
    }

    /// Writes a variable (element 0 of an array): checked here as the owner checks it, sent,
    /// and applied by the owner at the start of its next cycle. Returns once the owner applied
    /// it, or with its refusal (not writable, a value `set` refuses, a writer the program's
    /// policy does not let write).
    pub fn write(&self, name: &str, value: Value) -> Result<(), ShmError> {
        self.write_element(name, 0, value)
    }

    /// Checks a write of one element as [`write_element`](Self::write_element) would (unknown
    /// variable, read-only, input, status, element, kind, range, string capacity), without
    /// sending it: tools check a whole batch first and send none of it if one is refused.
    /// Returns the value as it would be sent (fitted to the variable's type).
    ///
    /// ```no_run
    /// let seg = plc_shm::DynSegment::attach("tensile_tester")?;
    /// let value = seg.check("speed_setpoint", 0, plc_core::Value::Int(2))?;
    /// assert_eq!(value, plc_core::Value::Real(2.0));
    /// # Ok::<(), plc_shm::ShmError>(())
    /// ```
    pub fn check(&self, name: &str, element: usize, value: Value) -> Result<Value, ShmError> {
        self.view
            .check_element(name, element, value)
            .map(|c| c.write().value)
    }

    /// Checks one write as the owner will ([`plc_core::write::check`], against this segment's
    /// descriptor): the write as it would be sent, to send with
    /// [`write_checked`](Self::write_checked) without checking it again.
    pub fn check_write(&self, write: Write) -> Result<Checked, ShmError> {
        self.view.check_write(write)
    }

    /// Sends writes checked by [`check_write`](Self::check_write) as one request (at most
    /// [`MAX_WRITES`](crate::limits::MAX_WRITES), and [`MAX_MESSAGE`](crate::limits::MAX_MESSAGE)
    /// bytes: [`protocol::request_len`](crate::protocol::request_len)), applied by the owner in
    /// one cycle, all or none; returns once it answered.
    pub fn write_checked(&self, writes: &[Checked]) -> Result<(), ShmError> {
        self.view.send_and_wait(writes)
    }

    /// Writes one array element, as [`write`](Self::write) does.
    pub fn write_element(&self, name: &str, element: usize, value: Value) -> Result<(), ShmError> {
        self.view.write_element(name, element, value)
    }

    /// Writes several basic values as one request: checked whole before anything is sent,
    /// applied by the owner in one cycle, all or none. At most
    /// [`MAX_WRITES`](crate::limits::MAX_WRITES) writes (an array of as many elements written
    /// whole), and [`MAX_MESSAGE`](crate::limits::MAX_MESSAGE) bytes of them.
    ///
    /// ```no_run
    /// use plc_core::{Value, write::Write};
    /// let seg = plc_shm::DynSegment::attach("tensile_tester")?;
    /// let index = |name| seg.index_of(name).expect("declared");
    /// seg.write_all(&[
    ///     Write { index: index("speed_setpoint"), leaf: 0, value: Value::Real(1.5) },
    ///     Write { index: index("start"), leaf: 0, value: Value::Bool(true) },
    /// ])?;
    /// # Ok::<(), plc_shm::ShmError>(())
    /// ```
    pub fn write_all(&self, writes: &[Write]) -> Result<(), ShmError> {
        self.view.write_all(writes)
    }

    /// Sends a write of one element, checked as [`write_element`](Self::write_element) checks
    /// it, without waiting: its ticket, to ask for its [`outcome`](Self::outcome) later.
    pub fn post_element(
        &self,
        name: &str,
        element: usize,
        value: Value,
    ) -> Result<Ticket, ShmError> {
        let checked = self.view.check_element(name, element, value)?;
        self.view.post(&[checked])
    }

    /// Sends writes checked by [`check_write`](Self::check_write) as one request, as
    /// [`write_checked`](Self::write_checked) does, without waiting: its ticket, to ask for its
    /// [`outcome`](Self::outcome) later.
    pub fn post_checked(&self, writes: &[Checked]) -> Result<Ticket, ShmError> {
        self.view.post(writes)
    }

    /// What became of a posted write: pending, applied, rejected or refused by the owner, not
    /// taken, or unknown (no answer can come any more).
    pub fn outcome(&self, ticket: Ticket) -> WriteOutcome {
        self.view.outcome(ticket)
    }

    /// Whether the program's policy lets this process write (from the owner's greeting; the
    /// owner checks every request again).
    pub fn may_write(&self) -> bool {
        self.view.may_write()
    }

    /// Test hook: sends a request without any of the writer's checks, as a misbehaving process
    /// could, to test that the owner does not trust its socket.
    #[cfg(feature = "fault-injection")]
    #[doc(hidden)]
    pub fn post_unchecked(
        &self,
        index: usize,
        element: usize,
        value: Value,
    ) -> Result<Ticket, ShmError> {
        self.view.post(&[Checked::__unchecked(Write {
            index,
            leaf: element,
            value,
        })])
    }

    /// Test hook: sends a request without any of the writer's checks and waits for the
    /// owner's answer.
    #[cfg(feature = "fault-injection")]
    #[doc(hidden)]
    pub fn write_unchecked(
        &self,
        index: usize,
        element: usize,
        value: Value,
    ) -> Result<(), ShmError> {
        self.view.send_and_wait(&[Checked::__unchecked(Write {
            index,
            leaf: element,
            value,
        })])
    }

    /// Test hook: the segment's descriptor as this tool received it, to try what a hostile
    /// tool would do with it.
    #[cfg(feature = "fault-injection")]
    #[doc(hidden)]
    pub fn segment_fd(&self) -> std::os::fd::BorrowedFd<'_> {
        self.view.seg.fd()
    }

    /// Test hook: sends any bytes as one message on the segment's socket.
    #[cfg(feature = "fault-injection")]
    #[doc(hidden)]
    pub fn send_raw(&self, bytes: &[u8]) -> Result<(), ShmError> {
        self.view.send_raw(bytes)
    }
}
