//! The owner's side: a program's variables in a named segment, published every cycle, and the
//! requests of tools (writes, forces, releases, traces) received on the segment's socket,
//! checked off the cycle and applied at the start of the next one.
//!
//! Nothing here uses the tool's side: both meet in the segment's format and the protocol.

mod alarm_commands;
mod by_value;
mod carry;
mod force_log;
mod forces;
mod placed;
pub(crate) mod policy;
mod recording;
mod refused;
mod requests;
mod segment;
mod server;
mod spent;

pub use alarm_commands::{AlarmCommand, AlarmRefusal};
pub use carry::HeldForce;
pub use requests::Rejection;
use spent::SpentTx;

use crate::error::ShmError;
use crate::format::alarm_table::{self, AlarmEntry, AlarmTable};
use crate::format::cycle_stats::CycleStats;
use crate::format::descriptor::LayoutDescriptor;
use crate::format::io_status::IoStatus;
use crate::format::layout::{
    H_MAGIC, H_SEQ, IMAGE, MAGIC, Offsets, S_HEARTBEAT_NS, S_RETAIN_FAILED, S_STATE,
};
use crate::format::status::{OwnerState, RunState, Status, write_report};
use crate::format::{bytes, header, seqlock};
use crate::limits::{FORCE_LOG_LINES, MAX_QUEUED, MAX_TRACES};
use crate::protocol::Code;
use crate::sys::base::Base;
use crate::sys::clock::{now_ns, utc_ns};
use crate::sys::rundir;
use force_log::ForceLog;
use forces::ForceTable;
use plc_core::memory::{Memory, Schema};
use plc_core::write::Write;
use policy::{Policy, Sharing};
use requests::{Counters, Inbox};
use segment::OwnedSegment;
use server::Setup;
use std::cell::{Cell, RefCell};
use std::marker::PhantomData;
use std::sync::atomic::{Ordering, fence};
use std::sync::{Arc, Mutex};

/// The owner of a segment (the control program): publishes, applies writes, reports.
/// From [`SharedGlobalMemory::create`](crate::SharedGlobalMemory::create).
pub struct ShmOwner<T: Memory> {
    inbox: Inbox<T>,
    seg: OwnedSegment,
    /// The mapping (the segment's, kept here for the cycle's stores).
    base: Base,
    off: Offsets,
    desc: LayoutDescriptor,
    generation: u64,
    /// The owner's seqlock counter, in its own memory: the shared word is only ever written
    /// from it, never read back.
    seq: Cell<u64>,
    /// Where the alarm states lie.
    alarms: AlarmTable,
    /// The state it reports.
    run_state: Cell<RunState>,
    _t: PhantomData<fn() -> T>,
}

impl<T: Memory> ShmOwner<T> {
    /// Creates segment `name` as the owner of a program whose variables `schema` describes,
    /// shared with the groups `sharing` names: its header and descriptor written, then served
    /// (tools connect only to a complete segment). A compiled program's owner comes from
    /// [`SharedGlobalMemory::create_with`](crate::SharedGlobalMemory::create_with).
    pub fn create(name: &str, sharing: &Sharing, schema: Schema) -> Result<ShmOwner<T>, ShmError> {
        let name = rundir::normalise(name)?;
        let policy = Policy::resolve(&name, sharing)?;
        let mut desc = LayoutDescriptor::of_schema(&schema);
        if let Some((path, records)) = sharing.alarm_history_file() {
            desc.alarm_journal = Some(path.display().to_string());
            desc.alarm_journal_capacity = Some(records);
        }
        let json = serde_json::to_vec(&desc).map_err(|e| ShmError::Corrupt {
            name: name.clone(),
            why: e.to_string(),
        })?;
        let off = Offsets::new(schema.image_size);
        // A new segment is zeroed: every alarm normal, never raised.
        let alarms = AlarmTable::after(off.descriptor + json.len(), schema.alarms.len());
        let size = alarms.end().ok_or_else(|| ShmError::Corrupt {
            name: name.clone(),
            why: format!("{} alarms do not fit in a segment", schema.alarms.len()),
        })?;
        let mut seg = OwnedSegment::create(&name, size, &policy)?;
        let base = seg.base();
        let generation = segment::next_generation(0);
        header::write(&base, &json, schema.layout_hash, &off, generation);
        base.store(H_SEQ, 0);
        base.store(S_HEARTBEAT_NS, now_ns());
        base.store(H_MAGIC, MAGIC);
        let counters = Arc::new(Counters::default());
        counters.publish(&base, &off);
        let (queue, rx) = std::sync::mpsc::sync_channel(MAX_QUEUED);
        let (spent, spent_rx) = SpentTx::channel(MAX_TRACES);
        let (log, log_rx) = ForceLog::channel(FORCE_LOG_LINES, spent.clone());
        // Last: tools connect only to a complete segment.
        seg.serve(Setup {
            name: name.clone(),
            policy,
            vars: schema.variables,
            alarms: schema.alarms.len(),
            off,
            counters: counters.clone(),
            queue,
            log: log_rx,
            spent: spent_rx,
        })?;
        Ok(ShmOwner {
            seg,
            base,
            off,
            desc,
            alarms,
            generation,
            inbox: Inbox {
                rx: Mutex::new(rx),
                counters,
                unpublished: Default::default(),
                forces: RefCell::new(ForceTable::new(schema.variables, log)),
                recordings: Default::default(),
                spent,
                held_over: RefCell::new(None),
            },
            seq: Cell::new(0),
            run_state: Cell::new(RunState::Starting),
            _t: PhantomData,
        })
    }

    /// Whether this handle owns the segment (always).
    pub fn is_owner(&self) -> bool {
        true
    }

    /// The segment's name.
    pub fn name(&self) -> &str {
        self.seg.name()
    }

    /// The generation: it grows with each new owner of this name (after a clean stop or a
    /// takeover), so a reader can tell two runs apart.
    pub fn generation(&self) -> u64 {
        self.generation
    }

    /// The status block.
    pub fn status(&self) -> Status {
        Status::read(&self.base, &self.off)
    }

    /// The owner's state as tools show it.
    pub fn owner_state(&self) -> OwnerState {
        if self.base.load(H_MAGIC) != MAGIC {
            return OwnerState::Gone;
        }
        self.status().owner_state(true)
    }

    /// The layout descriptor stored in the segment.
    pub fn descriptor(&self) -> &LayoutDescriptor {
        &self.desc
    }

    /// Publishes `gm`: the image goes out under the seqlock, through atomics.
    pub fn publish(&self, gm: &T) -> Result<(), ShmError> {
        let mut image = gm.new_image();
        gm.store_image(&mut image);
        self.publish_image(&image)
    }

    /// Publishes an image already built (the runtime reuses one buffer). Readers have no such
    /// call: a second seqlock writer would let readers take torn images.
    pub fn publish_image(&self, image: &T::Image) -> Result<(), ShmError> {
        self.publish_image_at(image, now_ns())
    }

    /// [`publish_image`](Self::publish_image) with the heartbeat `heartbeat_ns` on
    /// CLOCK_MONOTONIC (the runtime's cycle has just read that clock: the coarse one the
    /// heartbeat is compared with is the same clock, read at a lower resolution).
    pub fn publish_image_at(&self, image: &T::Image, heartbeat_ns: u64) -> Result<(), ShmError> {
        let base = &self.base;
        let seq = base.word(H_SEQ);
        // Even: no write in progress. Wrapping keeps the parity.
        let s = self.seq.get();
        seq.store(s.wrapping_add(1), Ordering::Relaxed);
        fence(Ordering::Release);
        bytes::store(base, IMAGE, T::image_bytes(image));
        seq.store(s.wrapping_add(2), Ordering::Release);
        self.seq.set(s.wrapping_add(2));
        base.store(S_HEARTBEAT_NS, heartbeat_ns);
        self.inbox.answer_applied();
        Ok(())
    }

    /// Applies the writes received since the last call to `gm`, in order, each request all
    /// or none, and answers their writers: a refusal at once, "applied" after the next
    /// [`publish`](Self::publish) (so a tool that reads after its write returned sees it), or
    /// at the next call if the owner did not publish. Returns how many writes were applied. The socket
    /// server checked each one against `T`'s declaration already (writable from outside,
    /// element, value); `set` decides last.
    pub fn apply_requests(&mut self, gm: &mut T) -> usize {
        self.apply_requests_with(gm, |_, _| {})
    }

    /// Like [`apply_requests`](Self::apply_requests), calling `audit` with each write and the
    /// outcome of applying it (to log operator writes, for example).
    /// Operators' actions on alarms are refused: a program that evaluates its alarms takes
    /// them with [`apply_requests_with_alarms`](Self::apply_requests_with_alarms).
    pub fn apply_requests_with(
        &mut self,
        gm: &mut T,
        mut audit: impl FnMut(&Write, &Result<(), Rejection>),
    ) -> usize {
        let mut act = alarm_commands::unmanaged;
        self.inbox
            .apply(gm, &self.base, &self.off, &mut audit, &mut act)
    }

    /// Like [`apply_requests_with`](Self::apply_requests_with), handing each operator's
    /// action on alarms (checked against the write policy and the program's alarm count) to
    /// `act`, in order with the writes: its refusal is the tool's answer, and an action it
    /// takes is answered "applied" after the next [`publish`](Self::publish) (publish the
    /// alarm states with [`publish_alarms`](Self::publish_alarms) before it, so that a tool
    /// reads what it did).
    pub fn apply_requests_with_alarms(
        &mut self,
        gm: &mut T,
        mut audit: impl FnMut(&Write, &Result<(), Rejection>),
        mut act: impl FnMut(&AlarmCommand) -> Result<(), AlarmRefusal>,
    ) -> usize {
        self.inbox
            .apply(gm, &self.base, &self.off, &mut audit, &mut act)
    }

    /// Stores the states of the alarms that changed (number in the schema's alarms, state) into the
    /// segment's alarm table, which tools read (`plc alarms`, OPC UA); numbers beyond the
    /// table are skipped.
    pub fn publish_alarms(&self, changed: impl Iterator<Item = (usize, AlarmEntry)>) {
        alarm_table::store(&self.base, &self.alarms, changed);
    }

    /// Sets every forced value in `gm`. The runtime calls it at both of the cycle's
    /// boundaries: after the inputs are read and the writes from outside applied, before the
    /// tick (so the program reads forced values), and after the tick, before the outputs are
    /// packed and published (so the bus and the tools get them, whatever the program wrote).
    /// A program that drives its own cycle does the same. Forces arrive with the writes (at
    /// most [`MAX_FORCES`](crate::limits::MAX_FORCES) held); each is a store or a few where its
    /// value lies in `T` (its bytes as `set` wrote them when it was forced:
    /// [`plc_core::place`]). A cycle that holds none pays two length checks.
    #[inline]
    pub fn apply_forces(&self, gm: &mut T) {
        self.inbox.forces.borrow().apply(gm);
    }

    /// How many forces are held.
    pub fn forces_held(&self) -> usize {
        self.inbox.forces.borrow().len()
    }

    /// Records the cycle's row of every trace a tool started (`plc trace`), from `image` as
    /// published, with the cycle's number and its time (nanoseconds since the program
    /// started). A program that traces nothing pays one length check.
    #[inline]
    pub fn record_traces(&self, image: &T::Image, cycle: u64, time_ns: u64) {
        self.inbox.record(T::image_bytes(image), cycle, time_ns);
    }

    /// A consistent copy of the image as readers see it, into `image` (for tests and
    /// benchmarks of the whole round trip; the program itself has its variables).
    pub fn snapshot_image_into(&self, out: &mut [u8]) -> Result<(), ShmError> {
        let owner_ok = || header::check_current(&self.base, self.generation, self.name());
        owner_ok()?;
        seqlock::read(
            &self.base,
            self.name(),
            || bytes::load(&self.base, IMAGE, out),
            owner_ok,
        )
    }

    /// Whether the segment was cut short under this handle. Its seals make that impossible
    /// (no process can shrink it); the SIGBUS guard behind this stays as a second line.
    pub fn damaged(&self) -> bool {
        self.seg.damaged()
    }

    /// Publishes the figures of cycle `cycle_count` and a heartbeat, stamped with the time
    /// now.
    pub fn report(&self, cycle_count: u64, stats: &CycleStats, io: &IoStatus) {
        self.base.store(S_HEARTBEAT_NS, now_ns());
        self.report_published(cycle_count, stats, io, utc_ns());
    }

    /// The runtime's [`report`](Self::report), right after its publish (which stamped the
    /// heartbeat): the cycle's values published at `utc_ns`.
    pub fn report_published(
        &self,
        cycle_count: u64,
        stats: &CycleStats,
        io: &IoStatus,
        utc_ns: u64,
    ) {
        write_report(&self.base, &self.off, cycle_count, stats, io, utc_ns);
    }

    /// Test hook: stores `data` at byte `offset` of the segment (8-aligned) through the
    /// owner's own mapping, as a damaged or hostile owner would, to test a tool's checks (no
    /// other process can write the sealed segment).
    #[cfg(feature = "fault-injection")]
    #[doc(hidden)]
    pub fn scribble(&self, offset: usize, data: &[u8]) {
        let start = offset - offset % 8;
        let mut region = vec![0u8; offset - start + data.len()];
        bytes::load(&self.base, start, &mut region);
        region[offset - start..].copy_from_slice(data);
        bytes::store(&self.base, start, &region);
    }

    /// Test hook: the word at byte `offset` of the segment.
    #[cfg(feature = "fault-injection")]
    #[doc(hidden)]
    pub fn word(&self, offset: usize) -> u64 {
        self.base.load(offset)
    }

    /// Publishes how many of the program's alarms are active and how many wait for an
    /// acknowledgement (the runtime calls it when they change).
    pub fn set_alarm_counts(&self, active: u64, unacknowledged: u64) {
        self.base.store(self.off.a_active(), active);
        self.base.store(self.off.a_unacknowledged(), unacknowledged);
    }

    /// Publishes how many saves of retained values failed so far.
    pub fn set_retain_failures(&self, failures: u64) {
        self.base.store(S_RETAIN_FAILED, failures);
    }

    /// Sets the state the owner reports.
    pub fn set_run_state(&self, state: RunState) {
        self.run_state.set(state);
        self.base.store(S_STATE, state as u64);
    }
}

impl<T: Memory> Drop for ShmOwner<T> {
    fn drop(&mut self) {
        // A fault stays visible to readers still attached: only a running owner stops.
        if self.run_state.get() != RunState::Faulted {
            self.set_run_state(RunState::Stopped);
        }
        // Forces end with the program: say which were still held.
        let held = self.inbox.forces.borrow().held_lines();
        if !held.is_empty() {
            let (n, what) = match held.len() {
                1 => (1, "force held, which ends"),
                n => (n, "forces held, which end"),
            };
            log::warn!(target: "plc_io::shm",
                "segment `{}`: the program stops with {n} {what} with it: {}",
                self.name(), held.join("; "));
        }
        for r in self.inbox.recordings.borrow().iter() {
            r.end();
        }
        // Writes applied and never published are answered as applied (the program had them);
        // writes received and never applied are answered too: their writers need not wait.
        self.inbox.answer_applied();
        if let Ok(rx) = self.inbox.rx.lock() {
            let mut held_over = self.inbox.held_over.borrow_mut().take();
            for _ in 0..=MAX_QUEUED {
                let Ok(batch) = held_over.take().map_or_else(|| rx.try_recv(), Ok) else {
                    break;
                };
                batch
                    .conn
                    .answer(batch.id, Code::Stopped, 0, "the program stopped".into());
            }
        }
    }
}
