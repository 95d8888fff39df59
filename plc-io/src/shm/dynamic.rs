//! `DynSegment`: a running program's variables for tools that do not have its Rust type.

use super::ShmError;
use super::codec;
use super::descriptor::{LayoutDescriptor, VarDescriptor};
use super::mailbox::{Outcome, Ticket};
use super::status::{OwnerState, Status};
use super::view::View;
use plc_core::Value;
use std::time::{Duration, Instant};

/// A segment attached through its stored descriptor (what `plc` uses).
///
/// ```no_run
/// let seg = plc_io::shm::DynSegment::attach("tensile_tester")?;
/// for v in &seg.descriptor().variables {
///     println!("{} = {}", v.name, seg.read(&v.name)?);
/// }
/// seg.write("speed_setpoint", plc_core::Value::Real(1.5))?;
/// # Ok::<(), plc_io::shm::ShmError>(())
/// ```
pub struct DynSegment {
    view: View,
}

impl DynSegment {
    /// Attaches to segment `name` (`press`, `plc.press` and `/dev/shm/plc.press` all work).
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

    /// A consistent copy of the whole image.
    pub fn snapshot_bytes(&self) -> Result<Vec<u8>, ShmError> {
        self.view.snapshot_bytes()
    }

    /// Element `element` of variable `index` in an image from [`snapshot_bytes`](Self::snapshot_bytes).
    pub fn value_at(&self, image: &[u8], index: usize, element: usize) -> Option<Value> {
        let var: &VarDescriptor = self.view.desc.variables.get(index)?;
        codec::decode(image, var, element)
    }

    /// One variable's value (element 0 of an array).
    pub fn read(&self, name: &str) -> Result<Value, ShmError> {
        self.view.read_element(name, 0)
    }

    /// One element of a variable.
    pub fn read_element(&self, name: &str, element: usize) -> Result<Value, ShmError> {
        self.view.read_element(name, element)
    }

    /// Posts a write, checked as the owner's `set` would check it (and refused for read-only,
    /// input and status variables).
    pub fn write(&self, name: &str, value: Value) -> Result<(), ShmError> {
        self.view.write_element(name, 0, value).map(drop)
    }

    /// Checks a write of one element as [`write_element`](Self::write_element) would (unknown
    /// variable, read-only, input, status, element, kind, range, string capacity), without
    /// sending it: tools check a whole batch first and send none of it if one is refused.
    /// Returns the value as it would be sent (fitted to the variable's type).
    ///
    /// ```no_run
    /// let seg = plc_io::shm::DynSegment::attach("tensile_tester")?;
    /// let value = seg.check("speed_setpoint", 0, plc_core::Value::Int(2))?;
    /// assert_eq!(value, plc_core::Value::Real(2.0));
    /// # Ok::<(), plc_io::shm::ShmError>(())
    /// ```
    pub fn check(&self, name: &str, element: usize, value: Value) -> Result<Value, ShmError> {
        self.view
            .check_element(name, element, value)
            .map(|(_, v)| v)
    }

    /// Posts a write of one array element.
    pub fn write_element(&self, name: &str, element: usize, value: Value) -> Result<(), ShmError> {
        self.view.write_element(name, element, value).map(drop)
    }

    /// Writes a batch of elements as one request: every write is checked first (as
    /// [`check`](Self::check) checks it) and nothing is posted if one is refused; the mailbox
    /// must have room for the whole batch; then all are posted together and their outcomes
    /// awaited (fifty of the owner's periods, at least one second, at most ten).
    ///
    /// The owner applies every request it finds in its mailbox at the start of a cycle, in
    /// order, so a batch posted together is applied at one cycle start when it fits the mailbox
    /// ([`mailbox_free`](Self::mailbox_free)) and no cycle starts while it is being posted
    /// (posting takes microseconds; on this mailbox a cycle starting in between splits it over
    /// two cycles). An array written whole (`name`, elements `0..n`) goes as one batch.
    ///
    /// ```no_run
    /// use plc_core::Value;
    /// let seg = plc_io::shm::DynSegment::attach("tensile_tester")?;
    /// seg.write_all(&[("speed_setpoint", 0, Value::Real(1.5)), ("auto_start", 0, Value::Bool(true))])?;
    /// # Ok::<(), plc_io::shm::ShmError>(())
    /// ```
    pub fn write_all(&self, writes: &[(&str, usize, Value)]) -> Result<(), ShmError> {
        let checked = writes
            .iter()
            .map(|&(name, element, value)| {
                self.view
                    .check_element(name, element, value)
                    .map(|(index, value)| (index, element, value))
            })
            .collect::<Result<Vec<_>, _>>()?;
        if checked.len() > self.mailbox_free() {
            return Err(ShmError::MailboxFull(self.name().to_string()));
        }
        let tickets = checked
            .iter()
            .map(|&(index, element, value)| self.view.post(index, element, value))
            .collect::<Result<Vec<_>, _>>()?;
        let patience = (self.status().stats.period * 50)
            .clamp(Duration::from_secs(1), Duration::from_secs(10));
        let start = Instant::now();
        loop {
            let outcomes: Vec<Outcome> = tickets.iter().map(|&t| self.outcome(t)).collect();
            for (&(index, _, _), outcome) in checked.iter().zip(&outcomes) {
                let name = &self.view.desc.variables[index].name;
                match outcome {
                    Outcome::Rejected => {
                        return Err(ShmError::NotWritable {
                            variable: name.clone(),
                            reason: "the program refused the value",
                        });
                    }
                    Outcome::Discarded => {
                        return Err(ShmError::WriteReclaimed(self.name().to_string()));
                    }
                    _ => {}
                }
            }
            if !outcomes.contains(&Outcome::Pending) {
                return Ok(());
            }
            self.view.check_owner()?;
            if start.elapsed() > patience {
                return Err(ShmError::Os {
                    name: self.name().to_string(),
                    what: "waiting for the program to take a batch of writes".into(),
                    error: format!(
                        "not taken within {:.1} s (is it running? `plc list` shows its state); \
                         it is applied when the program takes it",
                        patience.as_secs_f64()
                    ),
                });
            }
            std::thread::sleep(Duration::from_millis(1));
        }
    }

    /// Posts a write of one element, checked as [`write_element`](Self::write_element) checks
    /// it, and returns its ticket, to ask for its [`outcome`](Self::outcome) later.
    pub fn post_element(
        &self,
        name: &str,
        element: usize,
        value: Value,
    ) -> Result<Ticket, ShmError> {
        self.view.write_element(name, element, value)
    }

    /// What became of a posted write: pending, applied, rejected by the owner, discarded, or
    /// unknown (taken long ago; its slot has been reused since).
    pub fn outcome(&self, ticket: Ticket) -> Outcome {
        self.view.outcome(ticket)
    }

    /// Free mailbox slots just now: a batch of writes fits whole if it is no larger (unless
    /// another process posts at the same moment).
    pub fn mailbox_free(&self) -> usize {
        self.view.mailbox_free()
    }

    /// Test hook: posts a request without any of the writer's checks, as a misbehaving process
    /// could, to test that the owner does not trust its mailbox.
    #[cfg(feature = "fault-injection")]
    #[doc(hidden)]
    pub fn post_unchecked(
        &self,
        index: usize,
        element: usize,
        value: Value,
    ) -> Result<Ticket, ShmError> {
        self.view.post(index, element, value)
    }
}
