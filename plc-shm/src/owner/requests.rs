//! Requests from outside, on the owner's side: the writes, forces, releases, traces and alarm
//! actions its
//! socket server accepted, queued (bounded) for the cycle thread, which applies them at the start of its next cycle in
//! order, each request all or none; and the counters tools see in the status block.
//!
//! The server thread checks each request against the program's own declaration (not the
//! descriptor in the segment) before queueing it: variable, writability from outside, element,
//! value kind and range. The cycle thread only calls the program's `set`, undoing a request's
//! earlier writes if `set` refuses a later one.

use super::alarm_commands::{AlarmCommand, AlarmRefusal};
use super::forces::ForceTable;
use super::recording::Recording;
use super::refused::Refused;
use super::spent::{Spent, SpentTx, retire_departed};
use crate::format::layout::{Offsets, S_WRITES_APPLIED, S_WRITES_REJECTED};
use crate::limits::{PER_CYCLE, PER_CYCLE_WRITES};
use crate::protocol::{self, Code, Reply};
use crate::sys::base::Base;
use crate::sys::clock::utc_ns;
use crate::sys::unix;
use plc_core::memory::Memory;
use plc_core::write::{self, Checked, Write};
use plc_core::{SetError, Value, VarInfo};
use std::cell::RefCell;
use std::fmt;
use std::os::fd::{AsRawFd, OwnedFd};
use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering::Relaxed};
use std::sync::mpsc::{Receiver, TryRecvError};
use std::sync::{Arc, Mutex};

/// Why the owner refused a write that reached it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rejection {
    /// The variable may not be written from outside.
    NotWritable {
        /// The variable.
        variable: &'static str,
        /// Why: read-only, input or status.
        reason: &'static str,
    },
    /// The program's [`set`](plc_core::GlobalMemory::set) refused it (unknown
    /// index, element out of range, value that does not fit).
    Set(SetError),
}

impl fmt::Display for Rejection {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Rejection::NotWritable { variable, reason } => {
                write!(f, "`{variable}` cannot be written: {reason}")
            }
            Rejection::Set(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for Rejection {}

/// The owner's write counters, in its own memory (the status block's words are written from
/// them, never read back).
#[derive(Debug, Default)]
pub(crate) struct Counters {
    /// Writes applied.
    applied: AtomicU64,
    /// Writes refused by the declaration or the program's `set`.
    rejected: AtomicU64,
    /// Requests refused by the policy.
    refused: AtomicU64,
    /// Messages that were not valid requests.
    malformed: AtomicU64,
    /// Requests not taken because too many were waiting.
    busy: AtomicU64,
    /// Requests queued for the cycle thread.
    pending: AtomicU64,
    /// Writes (and forces and releases) in the queued requests: what the queue holds is
    /// bounded by these ([`MAX_WAITING_WRITES`](crate::limits::MAX_WAITING_WRITES)), as a
    /// request holds up to [`MAX_WRITES`](crate::limits::MAX_WRITES).
    pub waiting_writes: AtomicU64,
}

/// Which counter to add to.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Count {
    Applied,
    Rejected,
    Refused,
    Malformed,
    Busy,
}

impl Counters {
    /// Adds `n` to `which` and publishes every counter.
    pub fn add(&self, which: Count, n: u64, base: &Base, off: &Offsets) {
        let c = match which {
            Count::Applied => &self.applied,
            Count::Rejected => &self.rejected,
            Count::Refused => &self.refused,
            Count::Malformed => &self.malformed,
            Count::Busy => &self.busy,
        };
        c.fetch_add(n, Relaxed);
        self.publish(base, off);
    }

    pub fn queued(&self, delta: i64, base: &Base, off: &Offsets) {
        if delta >= 0 {
            self.pending.fetch_add(delta as u64, Relaxed);
        } else {
            self.pending.fetch_sub(delta.unsigned_abs(), Relaxed);
        }
        self.publish(base, off);
    }

    /// Stores every counter into the status block.
    pub fn publish(&self, base: &Base, off: &Offsets) {
        base.store(S_WRITES_APPLIED, self.applied.load(Relaxed));
        base.store(S_WRITES_REJECTED, self.rejected.load(Relaxed));
        base.store(off.w_refused(), self.refused.load(Relaxed));
        base.store(off.w_malformed(), self.malformed.load(Relaxed));
        base.store(off.w_busy(), self.busy.load(Relaxed));
        base.store(off.w_pending(), self.pending.load(Relaxed));
    }
}

/// One connection of the owner's socket server, as the cycle thread answers it.
#[derive(Debug)]
pub(crate) struct Conn {
    pub fd: OwnedFd,
    /// Requests of this connection queued and not answered yet.
    pub outstanding: AtomicUsize,
}

impl Conn {
    /// Answers with a memory file attached (a trace's ring).
    pub fn answer_with(&self, id: u64, code: Code, fd: &OwnedFd) {
        let reply = Reply {
            id,
            code,
            which: 0,
            reason: String::new(),
        };
        let _ = unix::send(
            self.fd.as_raw_fd(),
            &protocol::encode_reply(&reply),
            Some(fd.as_raw_fd()),
            false,
        );
    }

    /// Answers a refused request, saying which of its values and why.
    pub fn refuse(&self, id: u64, refused: Refused) {
        self.answer(id, refused.code, refused.which, refused.why);
    }

    /// Sends `reply` without waiting: a tool that does not read its answers loses them
    /// instead of stalling the owner.
    pub fn answer(&self, id: u64, code: Code, which: usize, reason: String) {
        let reply = Reply {
            id,
            code,
            which: u16::try_from(which).unwrap_or(u16::MAX),
            reason,
        };
        let _ = unix::send(
            self.fd.as_raw_fd(),
            &protocol::encode_reply(&reply),
            None,
            false,
        );
    }
}

/// A request the server accepted, waiting for the cycle thread.
pub(crate) struct Batch {
    pub id: u64,
    pub kind: Kind,
    pub conn: Arc<Conn>,
    /// The sender's uid, as the kernel gave it.
    pub uid: u32,
}

/// What a request asks the cycle for.
pub(crate) enum Kind {
    /// Writes, applied once.
    Write(Vec<Checked>),
    /// Values to hold (checked by `check_force`).
    Force(Vec<Checked>),
    /// Forces to end.
    Release(protocol::Release),
    /// A trace to record from now on (answered by the server already).
    Record(Box<Recording>),
    /// An operator's action on alarms, for the program's alarm manager.
    Alarm(Box<AlarmCommand>),
}

impl Kind {
    /// The values it writes or names, as the write counters count them.
    pub fn count(&self) -> u64 {
        match self {
            Kind::Write(w) | Kind::Force(w) => w.len() as u64,
            Kind::Release(r) => r.values.len().max(1) as u64,
            Kind::Record(_) => 0,
            Kind::Alarm(a) => a.alarms.len().max(1) as u64,
        }
    }

    /// What it costs the cycle, in writes of one value, against
    /// [`PER_CYCLE_WRITES`]: a force or release of a value does more than a write (it keeps
    /// the value's bytes, the table, and an event for the log) and each request rebuilds
    /// what the cycle applies from every held force.
    pub fn cost(&self) -> u64 {
        match self {
            Kind::Write(w) => w.len() as u64,
            // An alarm's action is a few stores and an event for the journal.
            Kind::Alarm(_) => self.count(),
            Kind::Force(_) | Kind::Release(_) => FORCE_COST * self.count() + FORCE_REQUEST_COST,
            Kind::Record(_) => 0,
        }
    }
}

/// A value forced or released costs the cycle this many writes of one value. Measured
/// (`plc-bench --only flood`: four tools flooding a 1,000-variable program at 1 ms with
/// requests of 1,024 values, a release build): a forced value costs the cycle two to three
/// times what a written one does (125 ns against 48 ns, the request's bytes read from another
/// core's cache included; most of the rest is capturing the value's place), so a force
/// request takes a cycle of its own where four write requests share one; counted as three, a
/// flood of forces overran no more than one of writes (3 against 5 overruns in 5 s).
const FORCE_COST: u64 = 3;
/// A force or release request costs this many writes more: the rebuild of the bytes every
/// held force writes, at most [`MAX_FORCES`](crate::limits::MAX_FORCES) of them.
const FORCE_REQUEST_COST: u64 = 256;

/// Checks a decoded request against the program's declaration with the one write check
/// ([`plc_core::write::check`]): the writes as they will be applied (values fitted to their
/// variables), or the first refused one and why.
pub(crate) fn validate(
    vars: &'static [VarInfo],
    request: &protocol::WriteRequest,
    force: bool,
) -> Result<Vec<Checked>, Refused> {
    let check = if force {
        write::check_force
    } else {
        write::check
    };
    request
        .writes
        .iter()
        .enumerate()
        .map(|(k, &w)| check(vars, w).map_err(|refusal| Refused::rejected(k, refusal.to_string())))
        .collect()
}

/// The cycle thread's end of the queue, for a program of type `T`.
pub(crate) struct Inbox<T: Memory> {
    pub rx: Mutex<Receiver<Batch>>,
    pub counters: Arc<Counters>,
    /// Requests applied and not yet published: their writers hear "applied" once a reader
    /// can see the value (after the next publish), so a tool's write-then-read holds; an
    /// owner that does not publish answers them at its next apply.
    pub unpublished: RefCell<Vec<(Arc<Conn>, u64)>>,
    /// The forces held.
    pub forces: RefCell<ForceTable<T>>,
    /// The traces being recorded.
    pub recordings: RefCell<Vec<Recording>>,
    /// Where the traces whose tools left go to be freed, off the cycle thread.
    pub spent: SpentTx,
    /// A request taken from the queue that did not fit the cycle's budget: the next cycle
    /// applies it first (it still counts as pending).
    pub held_over: RefCell<Option<Batch>>,
}

impl<T: Memory> Inbox<T> {
    /// Applies the queued requests to `gm`, in order, each all or none; answers each one.
    /// Returns how many writes were applied.
    pub fn apply(
        &self,
        gm: &mut T,
        base: &Base,
        off: &Offsets,
        audit: &mut impl FnMut(&Write, &Result<(), Rejection>),
        act: &mut impl FnMut(&AlarmCommand) -> Result<(), AlarmRefusal>,
    ) -> usize {
        // Nothing queued (the server counts a request before it queues it; one counted just
        // now waits for the next cycle): most cycles end here, without the lock or the queue.
        if self.counters.pending.load(Relaxed) == 0 {
            self.answer_applied();
            return 0;
        }
        // Only the cycle thread takes from the queue: the lock is never contended.
        let Ok(rx) = self.rx.try_lock() else {
            return 0;
        };
        self.answer_applied();
        let mut applied = 0;
        let mut taken = 0;
        for _ in 0..PER_CYCLE {
            if taken >= PER_CYCLE_WRITES {
                break;
            }
            let held_over = self.held_over.borrow_mut().take();
            let batch = match held_over.map_or_else(|| rx.try_recv(), Ok) {
                Ok(b) => b,
                Err(TryRecvError::Empty | TryRecvError::Disconnected) => break,
            };
            // A request that would take the cycle past its budget waits for the next one
            // (never split; the first of a cycle is always taken).
            let cost = batch.kind.cost();
            if taken > 0 && taken + cost > PER_CYCLE_WRITES {
                *self.held_over.borrow_mut() = Some(batch);
                break;
            }
            taken += cost;
            self.counters.queued(-1, base, off);
            batch.conn.outstanding.fetch_sub(1, Relaxed);
            let n = batch.kind.count();
            self.counters.waiting_writes.fetch_sub(n, Relaxed);
            let forces = &mut self.forces.borrow_mut();
            let done = match batch.kind {
                Kind::Write(writes) => {
                    let done = apply_batch(gm, &writes, forces, audit);
                    if done.is_ok() {
                        applied += writes.len();
                    }
                    self.spent.leave(Spent::Values(writes));
                    done
                }
                Kind::Force(writes) => {
                    let done = forces.force(gm, writes, batch.uid, utc_ns());
                    forces.publish(base, off);
                    done
                }
                Kind::Release(release) => {
                    let done = forces.release(gm, &release, batch.uid, utc_ns());
                    forces.publish(base, off);
                    done
                }
                Kind::Record(recording) => {
                    self.recordings.borrow_mut().push(*recording);
                    continue;
                }
                Kind::Alarm(command) => {
                    act(&command).map_err(|r| Refused::rejected(r.which, r.why))
                }
            };
            match done {
                Ok(()) => {
                    self.counters.add(Count::Applied, n, base, off);
                    self.unpublished.borrow_mut().push((batch.conn, batch.id));
                }
                Err(refused) => {
                    self.counters.add(Count::Rejected, n, base, off);
                    batch.conn.refuse(batch.id, refused);
                }
            }
        }
        applied
    }

    /// Writes this cycle's row of every trace, after handing those whose tool left to the
    /// server to be freed.
    #[inline]
    pub fn record(&self, image: &[u8], cycle: u64, time_ns: u64) {
        let mut recordings = self.recordings.borrow_mut();
        // Nearly every program traces nothing: one length check.
        if recordings.is_empty() {
            return;
        }
        retire_departed(&mut recordings, &self.spent);
        for r in recordings.iter_mut() {
            r.record(image, cycle, time_ns);
        }
    }

    /// Answers "applied" to the writers whose requests were applied since the last answer
    /// (called after a publish: the image holds them).
    pub fn answer_applied(&self) {
        let mut unpublished = self.unpublished.borrow_mut();
        // Twice a cycle, nearly always with nothing to answer.
        if unpublished.is_empty() {
            return;
        }
        for (conn, id) in unpublished.drain(..) {
            conn.answer(id, Code::Applied, 0, String::new());
        }
    }
}

/// Applies `writes` through the program's `set`; if it refuses one, the writes before it
/// are undone (their earlier values set again) and the refused one is named.
/// A write to a forced value refuses the request, naming the force.
fn apply_batch<T: Memory>(
    gm: &mut T,
    writes: &[Checked],
    forces: &ForceTable<T>,
    audit: &mut impl FnMut(&Write, &Result<(), Rejection>),
) -> Result<(), Refused> {
    if forces.len() > 0 {
        for (k, w) in writes.iter().map(Checked::write).enumerate() {
            if let Some(why) = forces.refusal(w.index, w.leaf) {
                return Err(Refused::forced(k, why));
            }
        }
    }
    let mut undo: Vec<(usize, usize, Option<Value>)> = Vec::with_capacity(writes.len());
    for (k, w) in writes.iter().map(Checked::write).enumerate() {
        let before = gm.try_get(w.index, w.leaf);
        if let Err(e) = gm.set(w.index, w.leaf, w.value) {
            for (index, element, old) in undo.into_iter().rev() {
                if let Some(old) = old {
                    let _ = gm.set(index, element, old);
                }
            }
            let rejection = Rejection::Set(e);
            audit(w, &Err(rejection));
            let name = gm.schema().variables.get(w.index).map_or("?", |v| v.name);
            return Err(Refused::rejected(k, format!("`{name}`: {rejection}")));
        }
        undo.push((w.index, w.leaf, before));
    }
    for w in writes {
        audit(w.write(), &Ok(()));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use crate::limits::{MAX_WRITES, PER_CYCLE_WRITES};
    use crate::{DynSegment, SharedGlobalMemory};
    use plc_core::write::Write;
    use plc_core::{GlobalMemory, Value};
    use std::time::{Duration, Instant};

    #[derive(GlobalMemory, Debug, Clone)]
    struct Gm {
        #[plc(direction = "command")]
        speeds: [i16; 300],
    }

    fn waits_until(what: &str, mut done: impl FnMut() -> bool) {
        let start = Instant::now();
        while !done() {
            assert!(start.elapsed() < Duration::from_secs(10), "{what}");
            std::thread::sleep(Duration::from_millis(1));
        }
    }

    #[test]
    fn a_cycle_takes_force_requests_by_what_they_cost_not_as_writes() {
        let name = format!("budget_{}", std::process::id());
        let mut owner = SharedGlobalMemory::<Gm>::create(&name).unwrap();
        let mut gm = Gm::default();
        // A write request and two force requests of 1,024 values each, from three tools.
        let tools: Vec<DynSegment> = (0..3).map(|_| DynSegment::attach(&name).unwrap()).collect();
        let index = tools[0].index_of("speeds").unwrap();
        let values = |lo: usize| -> Vec<Write> {
            (0..MAX_WRITES)
                .map(|k| Write {
                    index,
                    leaf: lo + k % 128,
                    value: Value::Int(k as i64),
                })
                .collect()
        };
        // Written as plain writes, three requests fit one cycle's budget; one of forces
        // costs about what three do.
        assert!(3 * MAX_WRITES as u64 <= PER_CYCLE_WRITES);
        let mut tools = tools.into_iter();
        std::thread::scope(|s| {
            let writer = tools.next().unwrap();
            let writes = values(0);
            s.spawn(move || writer.write_all(&writes).unwrap());
            waits_until("the write is queued", || owner.status().writes_pending == 1);
            for tool in tools {
                let forces: Vec<_> = (values(150).into_iter())
                    .map(|w| tool.check_force(w).unwrap())
                    .collect();
                s.spawn(move || tool.force(&forces).unwrap());
            }
            waits_until("the forces are queued", || {
                owner.status().writes_pending == 3
            });
            let applied = |owner: &crate::ShmOwner<Gm>| owner.status().writes_applied;
            owner.apply_requests(&mut gm);
            assert_eq!(applied(&owner), MAX_WRITES as u64, "the write, alone");
            assert_eq!(owner.status().writes_pending, 2);
            owner.apply_requests(&mut gm);
            assert_eq!(applied(&owner), 2 * MAX_WRITES as u64, "one force request");
            owner.apply_requests(&mut gm);
            assert_eq!(applied(&owner), 3 * MAX_WRITES as u64, "the other");
            assert_eq!(owner.status().writes_pending, 0);
            // The tools hear "applied" after the next publish.
            owner.publish(&gm).unwrap();
        });
        assert_eq!(owner.forces_held(), 128);
    }
}
