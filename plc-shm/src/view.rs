//! An attached segment, typed or not: header checks, seqlock snapshots, owner liveness and
//! writes over the socket. `SharedGlobalMemory::attach` and `DynSegment::attach` both use it.

use super::client::answer_result;
use super::codec;
use super::descriptor::LayoutDescriptor;
use super::error::refusal;
use super::layout::*;
use super::mailbox::{Outcome, Ticket};
use super::segment::{self, MAX_DESCRIPTOR, MAX_IMAGE, Segment};
use super::status::{OwnerState, RunState, Status};
use super::{ShmError, bytes};
use crate::sys::base::Base;
use plc_core::Value;
use plc_core::write::{self, Checked, Write};
use std::cell::{Cell, OnceCell};
use std::collections::HashMap;
use std::sync::atomic::{Ordering, fence};
use std::time::{Duration, Instant};

/// How long a reader waits for a consistent image before it reports the owner stuck.
pub const SNAPSHOT_PATIENCE: Duration = Duration::from_millis(500);
/// How often a reader re-checks that the owner is alive.
const LIVENESS_EVERY: Duration = Duration::from_millis(20);
/// How long a write waits for the owner's answer at least and at most: fifty of its cycles
/// in between.
const WRITE_PATIENCE: (Duration, Duration) = (Duration::from_secs(1), Duration::from_secs(10));

pub(crate) struct View {
    pub seg: Segment,
    pub base: Base,
    pub off: Offsets,
    pub desc: LayoutDescriptor,
    pub generation: u64,
    pub checked_alive: Cell<Option<Instant>>,
    /// Top-level variables by lower-case name, built at the first lookup: a tool that names
    /// thousands of variables (`plc get` of 4,000 names) finds each in constant time, where a
    /// scan of the descriptor per name is quadratic.
    pub names: OnceCell<HashMap<String, usize>>,
}

impl View {
    pub fn attach(name: &str) -> Result<View, ShmError> {
        let name = segment::normalise(name)?;
        let seg = Segment::open(&name)?;
        let base = seg.base();
        if base.len() < IMAGE {
            return Err(ShmError::TooSmall {
                name,
                len: base.len(),
                needed: IMAGE,
            });
        }
        // The owner serves its segment only once its header is complete.
        let magic = base.load(H_MAGIC);
        if magic == MAGIC_CLOSED {
            return Err(closed(&base, name));
        }
        if magic != MAGIC {
            return Err(ShmError::Format {
                name,
                found: format!("magic {magic:016x}"),
            });
        }
        let version = base.load(H_VERSION);
        if version != plc_rules::layout::FORMAT_VERSION as u64 {
            return Err(ShmError::Format {
                name,
                found: format!("format version {version}"),
            });
        }
        // Every number below comes from another process: checked arithmetic only.
        let header_image_size = base.load(H_IMAGE_SIZE);
        let off = usize::try_from(header_image_size)
            .ok()
            .and_then(Offsets::checked)
            .ok_or_else(|| ShmError::Corrupt {
                name: name.clone(),
                why: format!("its header gives an image size of {header_image_size} bytes"),
            })?;
        let image_size = off.image_size;
        if image_size > MAX_IMAGE {
            return Err(ShmError::Corrupt {
                name,
                why: format!(
                    "its header gives an image of {image_size} bytes, more than the {MAX_IMAGE} \
                     a tool reads"
                ),
            });
        }
        let (d_off, d_len) = (base.load(H_DESC_OFFSET), base.load(H_DESC_LEN));
        if d_len > MAX_DESCRIPTOR as u64 {
            return Err(ShmError::Corrupt {
                name,
                why: format!(
                    "its header gives a descriptor of {d_len} bytes, more than the \
                     {MAX_DESCRIPTOR} a tool reads"
                ),
            });
        }
        let d_end = d_off.saturating_add(d_len);
        let needed = usize::try_from(d_end)
            .unwrap_or(usize::MAX)
            .max(off.descriptor);
        if base.len() < needed {
            return Err(ShmError::TooSmall {
                name,
                len: base.len(),
                needed,
            });
        }
        if d_off != off.descriptor as u64 {
            return Err(ShmError::Corrupt {
                name,
                why: format!(
                    "its header puts the descriptor at byte {d_off}, not {}",
                    off.descriptor
                ),
            });
        }
        let mut json = vec![0u8; d_len as usize];
        bytes::load(&base, off.descriptor, &mut json);
        let desc: LayoutDescriptor =
            serde_json::from_slice(&json).map_err(|e| ShmError::Corrupt {
                name: name.clone(),
                why: format!("its descriptor is not valid JSON: {e}"),
            })?;
        let hash = base.load(H_LAYOUT_HASH);
        if desc.computed_hash() != hash || desc.layout_hash != hash {
            return Err(ShmError::Corrupt {
                name,
                why: "the descriptor does not match the layout hash".into(),
            });
        }
        if desc.image_size != image_size {
            return Err(ShmError::Corrupt {
                name,
                why: format!(
                    "the descriptor gives an image of {} bytes, the header {image_size}",
                    desc.image_size
                ),
            });
        }
        desc.check_variables().map_err(|why| ShmError::Corrupt {
            name: name.clone(),
            why,
        })?;
        Ok(View {
            generation: base.load(H_GENERATION),
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
    /// 20 ms).
    pub fn check_owner(&self) -> Result<(), ShmError> {
        match self.base.load(H_MAGIC) {
            MAGIC if self.base.load(H_GENERATION) == self.generation => {}
            MAGIC_CLOSED => return Err(closed(&self.base, self.name().to_string())),
            _ => {
                return Err(ShmError::Corrupt {
                    name: self.name().to_string(),
                    why: "its header changed under this tool".into(),
                });
            }
        }
        if self.seg.is_owner() {
            return Ok(());
        }
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
    pub fn consistent<R>(&self, mut read: impl FnMut() -> R) -> Result<R, ShmError> {
        self.check_owner()?;
        let seq = self.base.word(H_SEQ);
        // The clock is read only once the owner made us wait: most snapshots succeed at once.
        let mut start = None;
        let mut spins = 0u32;
        loop {
            let s1 = seq.load(Ordering::Acquire);
            if s1.is_multiple_of(2) {
                let r = read();
                fence(Ordering::Acquire);
                if seq.load(Ordering::Relaxed) == s1 {
                    return Ok(r);
                }
            }
            spins += 1;
            if spins.is_multiple_of(64) {
                if start.get_or_insert_with(Instant::now).elapsed() > SNAPSHOT_PATIENCE {
                    self.check_owner()?;
                    return Err(ShmError::Stuck(self.name().to_string()));
                }
                std::thread::yield_now();
            } else {
                std::hint::spin_loop();
            }
        }
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
                segment: self.name().to_string(),
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
        Ok(codec::decode(&image, var, element).unwrap_or(Value::Bool(false)))
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
        let too_large = |why: String| ShmError::Os {
            name: self.name().to_string(),
            what: format!("cannot send {} writes as one request", requests.len()),
            error: why.into(),
        };
        let most = super::protocol::MAX_WRITES;
        if requests.is_empty() || requests.len() > most {
            return Err(too_large(format!("a request holds 1 to {most} writes")));
        }
        let writes: Vec<Write> = requests.iter().map(|c| *c.write()).collect();
        let (len, most) = (
            super::protocol::request_len(&writes),
            super::protocol::MAX_MESSAGE,
        );
        if len > most {
            return Err(too_large(format!(
                "they take {len} bytes and a request at most {most}: send the texts in parts"
            )));
        }
        self.client()?.post(requests)
    }

    fn client(&self) -> Result<&super::client::Client, ShmError> {
        self.seg
            .client()
            .ok_or_else(|| ShmError::NotOwner(self.name().to_string()))
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
            Some(_) => super::forces::path_of(&self.desc.variables, w.index, w.leaf),
            None => format!("#{}", w.index),
        }
    }

    /// Sends the message `encode` makes (for the request id it is given).
    pub fn post_with(&self, encode: impl FnOnce(u64) -> Vec<u8>) -> Result<Ticket, ShmError> {
        self.check_owner()?;
        self.client()?.post_with(encode)
    }

    /// Waits for the owner's answer to `ticket` (fifty of its cycles, within bounds);
    /// `names` are the request's values, as a refusal names them.
    pub fn wait_answer(&self, ticket: Ticket, names: &[String]) -> Result<(), ShmError> {
        let period = self.status().stats.period;
        let patience = (period * 50).clamp(WRITE_PATIENCE.0, WRITE_PATIENCE.1);
        let reply = self.client()?.wait(ticket, patience)?;
        answer_result(self.name(), names, reply)
    }

    /// The memory file that came with the answer to `ticket`.
    pub fn take_file(&self, ticket: Ticket) -> Option<std::os::fd::OwnedFd> {
        self.seg.client().and_then(|c| c.take_file(ticket))
    }

    /// Sends raw bytes on the socket (test hook for hostile messages).
    #[cfg(feature = "fault-injection")]
    pub fn send_raw(&self, bytes: &[u8]) -> Result<(), ShmError> {
        self.client()?.send_raw(bytes)
    }

    pub fn may_write(&self) -> bool {
        self.seg.client().is_some_and(|c| c.may_write())
    }

    pub fn outcome(&self, ticket: Ticket) -> Outcome {
        self.seg
            .client()
            .map_or(Outcome::Unknown, |c| c.outcome(ticket))
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

/// The error of a segment whose owner stopped, saying whether it stopped because it faulted.
fn closed(base: &Base, name: String) -> ShmError {
    let faulted = Status::read_run_state(base) == RunState::Faulted;
    ShmError::Closed { name, faulted }
}
