//! `SharedGlobalMemory<T>`: a program's variables in a named segment, as [`ShmOwner`] for its
//! owner (the control program, which publishes) and as [`ShmReader`] for typed readers in other
//! processes.

use super::descriptor::LayoutDescriptor;
use super::forces::ForceTable;
use super::layout::*;
use super::mailbox::{Counters, Inbox, Rejection};
use super::policy::{Policy, Sharing};
use super::protocol::Code;
use super::segment::{self, Segment};
use super::server::{QUEUE, Setup};
use super::status::{OwnerState, RunState, Status, now_ns, utc_ns, write_report};
use super::view::View;
use super::{ShmError, bytes};
use crate::{CycleStats, IoStatus};
use plc_core::write::Write;
use plc_core::{GlobalMemory, Value};
use std::cell::{Cell, RefCell};
use std::marker::PhantomData;
use std::mem::size_of;
use std::sync::atomic::{Ordering, fence};
use std::sync::{Arc, Mutex};
use zerocopy::{FromZeros, IntoBytes};

/// The calls owners and readers share, on their `view`.
macro_rules! segment_accessors {
    () => {
        /// The segment's name.
        pub fn name(&self) -> &str {
            self.view.name()
        }

        /// The generation: it grows with each new owner of this name (after a clean stop or a
        /// takeover), so a reader can tell two runs apart.
        pub fn generation(&self) -> u64 {
            self.view.generation
        }

        /// The status block.
        pub fn status(&self) -> Status {
            self.view.status()
        }

        /// The owner's state as tools show it.
        pub fn owner_state(&self) -> OwnerState {
            self.view.owner_state()
        }

        /// The layout descriptor stored in the segment.
        pub fn descriptor(&self) -> &LayoutDescriptor {
            &self.view.desc
        }
    };
}

/// A `GlobalMemory` struct in a named shared-memory segment: the two ways in.
///
/// The owner [`create`](Self::create)s it, getting a [`ShmOwner`] that
/// [`publish`](ShmOwner::publish)es every cycle; other processes [`attach`](Self::attach),
/// getting a [`ShmReader`] that takes consistent [`snapshot`](ShmReader::snapshot)s (a seqlock:
/// never a torn image), reads single variables, and sends writes over the segment's socket,
/// which the owner applies at the start of its next cycle through [`GlobalMemory::set`].
/// Owner-only calls do not exist on a reader.
///
/// The segment is sealed memory that readers map read-only; the owner's socket and lock file
/// are in its runtime directory (the crate documentation says who may connect, and how a
/// killed owner's files are taken over; the repository's README, "Security and failure
/// model", the whole model).
///
/// ```
/// use plc_core::GlobalMemory;
/// use plc_shm::SharedGlobalMemory;
///
/// #[derive(GlobalMemory, Debug, Clone)]
/// struct Gm {
///     count: u32,
///     #[plc(direction = "command")]
///     setpoint: f32,
/// }
///
/// let name = format!("doc_example_{}", std::process::id());
/// let mut owner = SharedGlobalMemory::<Gm>::create(&name)?;
/// let mut gm = Gm::default();
/// gm.count = 7;
/// owner.publish(&gm)?;
///
/// let reader = SharedGlobalMemory::<Gm>::attach(&name)?; // usually another process
/// assert_eq!(reader.snapshot()?.count, 7);
/// // A write waits for the owner's next cycle, which applies it and publishes the image that
/// // holds it: here another thread is the cycle.
/// std::thread::scope(|s| {
///     s.spawn(|| {
///         while owner.apply_mailbox(&mut gm) == 0 {}
///         owner.publish(&gm)
///     });
///     reader.write("setpoint", plc_core::Value::Real(2.5))
/// })?;
/// assert_eq!(gm.setpoint, 2.5);
/// # Ok::<(), plc_shm::ShmError>(())
/// ```
pub struct SharedGlobalMemory<T: GlobalMemory> {
    _never: std::convert::Infallible,
    _t: PhantomData<fn() -> T>,
}

impl<T: GlobalMemory> SharedGlobalMemory<T> {
    /// Creates segment `name` as its owner, read and written by this process's user only. A
    /// segment left by a dead owner is replaced (with a later generation); one owned by a live
    /// process is refused.
    pub fn create(name: &str) -> Result<ShmOwner<T>, ShmError> {
        Self::create_with(name, &Sharing::new())
    }

    /// Creates segment `name` as its owner, shared with the groups `sharing` names.
    pub fn create_with(name: &str, sharing: &Sharing) -> Result<ShmOwner<T>, ShmError> {
        let name = segment::normalise(name)?;
        let policy = Policy::resolve(&name, sharing)?;
        let desc = LayoutDescriptor::of::<T>();
        let json = serde_json::to_vec(&desc).map_err(|e| ShmError::Corrupt {
            name: name.clone(),
            why: e.to_string(),
        })?;
        let off = Offsets::new(size_of::<T::Image>());
        let mut seg = Segment::create(&name, off.descriptor + json.len(), &policy)?;
        let base = seg.base();
        let generation = segment::next_generation(0);
        write_header(&base, &json, T::LAYOUT_HASH, &off, generation);
        base.store(H_SEQ, 0);
        base.store(S_HEARTBEAT_NS, now_ns());
        base.store(H_MAGIC, MAGIC);
        let counters = Arc::new(Counters::default());
        counters.publish(&base, &off);
        let (queue, rx) = std::sync::mpsc::sync_channel(QUEUE);
        let (log, log_rx) = std::sync::mpsc::sync_channel(FORCE_LOG);
        // Last: tools connect only to a complete segment.
        seg.serve(Setup {
            name: name.clone(),
            policy,
            vars: T::VARIABLES,
            off,
            counters: counters.clone(),
            queue,
            log: log_rx,
        })?;
        Ok(ShmOwner {
            view: View {
                seg,
                base,
                off,
                desc,
                generation,
                checked_alive: Default::default(),
                names: Default::default(),
            },
            inbox: Inbox {
                rx: Mutex::new(rx),
                counters,
                unpublished: Default::default(),
                forces: RefCell::new(ForceTable::new(T::VARIABLES, log)),
                recordings: Default::default(),
            },
            seq: Cell::new(0),
            run_state: Cell::new(RunState::Starting),
            _t: PhantomData,
        })
    }

    /// Attaches to segment `name`, checking that it holds exactly `T`'s layout.
    pub fn attach(name: &str) -> Result<ShmReader<T>, ShmError> {
        let view = View::attach(name)?;
        if view.desc.layout_hash != T::LAYOUT_HASH || view.off.image_size != size_of::<T::Image>() {
            return Err(ShmError::LayoutMismatch {
                name: view.name().to_string(),
                expected: T::LAYOUT_HASH,
                found: view.desc.layout_hash,
            });
        }
        Ok(ShmReader {
            view,
            _t: PhantomData,
        })
    }
}

/// The owner of a segment (the control program): publishes, applies writes, reports.
/// From [`SharedGlobalMemory::create`].
pub struct ShmOwner<T: GlobalMemory> {
    inbox: Inbox<T>,
    view: View,
    /// The owner's seqlock counter, in its own memory: the shared word is only ever written
    /// from it, never read back.
    seq: Cell<u64>,
    /// The state it reports.
    run_state: Cell<RunState>,
    _t: PhantomData<fn() -> T>,
}

/// Log lines of forces waiting for the server's thread, at most (a release of every force
/// is 256).
const FORCE_LOG: usize = 1024;

/// Writes the header and the descriptor (the owner, once, before it serves the segment).
fn write_header(base: &Base, json: &[u8], hash: u64, off: &Offsets, generation: u64) {
    base.store(H_VERSION, plc_rules::layout::FORMAT_VERSION as u64);
    base.store(H_LAYOUT_HASH, hash);
    base.store(H_IMAGE_SIZE, off.image_size as u64);
    base.store(H_GENERATION, generation);
    base.store(H_DESC_OFFSET, off.descriptor as u64);
    base.store(H_DESC_LEN, json.len() as u64);
    base.store(S_PID, std::process::id() as u64);
    base.store(S_STATE, RunState::Starting as u64);
    bytes::store(base, off.descriptor, json);
}

impl<T: GlobalMemory> ShmOwner<T> {
    /// Whether this handle owns the segment (always).
    pub fn is_owner(&self) -> bool {
        true
    }

    segment_accessors!();

    /// Publishes `gm`: the image goes out under the seqlock, through atomics.
    pub fn publish(&self, gm: &T) -> Result<(), ShmError> {
        let image = gm.to_image();
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
        let base = &self.view.base;
        let seq = base.word(H_SEQ);
        // Even: no write in progress. Wrapping keeps the parity.
        let s = self.seq.get();
        seq.store(s.wrapping_add(1), Ordering::Relaxed);
        fence(Ordering::Release);
        bytes::store(base, IMAGE, image.as_bytes());
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
    pub fn apply_mailbox(&mut self, gm: &mut T) -> usize {
        self.apply_mailbox_with(gm, |_, _| {})
    }

    /// Like [`apply_mailbox`](Self::apply_mailbox), calling `audit` with each write and the
    /// outcome of applying it (to log operator writes, for example).
    pub fn apply_mailbox_with(
        &mut self,
        gm: &mut T,
        mut audit: impl FnMut(&Write, &Result<(), Rejection>),
    ) -> usize {
        self.inbox
            .apply(gm, &self.view.base, &self.view.off, &mut audit)
    }

    /// Sets every forced value in `gm`. The runtime calls it at both of the cycle's
    /// boundaries: after the inputs are read and the writes from outside applied, before the
    /// tick (so the program reads forced values), and after the tick, before the outputs are
    /// packed and published (so the bus and the tools get them, whatever the program wrote).
    /// A program that drives its own cycle does the same. Forces arrive with the writes (at
    /// most 256 held); each is a store or a few where its value lies in `T` (its bytes as
    /// `set` wrote them when it was forced: [`plc_core::place`]). A cycle that holds none
    /// pays two length checks.
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
        self.inbox.record(image.as_bytes(), cycle, time_ns);
    }

    /// A consistent copy of the image as readers see it, into `image` (for tests and
    /// benchmarks of the whole round trip; the program itself has its variables).
    pub fn snapshot_image_into(&self, image: &mut T::Image) -> Result<(), ShmError> {
        let out = image.as_mut_bytes();
        self.view
            .consistent(|| bytes::load(&self.view.base, IMAGE, out))
    }

    /// Whether the segment was cut short under this handle. Its seals make that impossible
    /// (no process can shrink it); the SIGBUS guard behind this stays as a second line.
    pub fn damaged(&self) -> bool {
        self.view.seg.damaged()
    }

    /// Publishes the figures of cycle `cycle_count` and a heartbeat, stamped with the time
    /// now.
    pub fn report(&self, cycle_count: u64, stats: &CycleStats, io: &IoStatus) {
        self.view.base.store(S_HEARTBEAT_NS, now_ns());
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
        write_report(
            &self.view.base,
            &self.view.off,
            cycle_count,
            stats,
            io,
            utc_ns,
        );
    }

    /// Test hook: stores `data` at byte `offset` of the segment (8-aligned) through the
    /// owner's own mapping, as a damaged or hostile owner would, to test a tool's checks (no
    /// other process can write the sealed segment).
    #[cfg(feature = "fault-injection")]
    #[doc(hidden)]
    pub fn scribble(&self, offset: usize, data: &[u8]) {
        let start = offset - offset % 8;
        let mut region = vec![0u8; offset - start + data.len()];
        bytes::load(&self.view.base, start, &mut region);
        region[offset - start..].copy_from_slice(data);
        bytes::store(&self.view.base, start, &region);
    }

    /// Test hook: the word at byte `offset` of the segment.
    #[cfg(feature = "fault-injection")]
    #[doc(hidden)]
    pub fn word(&self, offset: usize) -> u64 {
        self.view.base.load(offset)
    }

    /// Publishes how many saves of retained values failed so far.
    pub fn set_retain_failures(&self, failures: u64) {
        self.view.base.store(S_RETAIN_FAILED, failures);
    }

    /// Sets the state the owner reports.
    pub fn set_run_state(&self, state: RunState) {
        self.run_state.set(state);
        self.view.base.store(S_STATE, state as u64);
    }
}

/// A typed reader of a segment (an HMI, a tool with the program's type): snapshots, reads and
/// writes over the segment's socket. From [`SharedGlobalMemory::attach`].
///
/// A reader cannot publish: a second seqlock writer would let readers take torn images, so the
/// call does not exist.
///
/// ```compile_fail,E0599
/// # use plc_core::GlobalMemory;
/// # #[derive(GlobalMemory, Debug, Clone)]
/// # struct Gm { count: u32 }
/// let reader = plc_shm::SharedGlobalMemory::<Gm>::attach("press")?;
/// reader.publish(&Gm::default())?;
/// # Ok::<(), plc_shm::ShmError>(())
/// ```
pub struct ShmReader<T: GlobalMemory> {
    view: View,
    _t: PhantomData<fn() -> T>,
}

impl<T: GlobalMemory> ShmReader<T> {
    /// Whether this handle owns the segment (never).
    pub fn is_owner(&self) -> bool {
        false
    }

    segment_accessors!();

    /// A consistent copy of the variables: retries while the owner writes, never torn; an error
    /// if the owner is gone, was replaced, or stays mid-write.
    pub fn snapshot(&self) -> Result<T, ShmError> {
        let image = self.snapshot_image()?;
        Ok(T::from_image(&image))
    }

    /// A consistent copy of the image.
    pub fn snapshot_image(&self) -> Result<T::Image, ShmError> {
        let mut image = T::Image::new_zeroed();
        self.snapshot_image_into(&mut image)?;
        Ok(image)
    }

    /// A consistent copy of the image into `image`, which the caller reuses from cycle to cycle
    /// (no image-sized value is built or moved). On error `image` holds unspecified bytes.
    pub fn snapshot_image_into(&self, image: &mut T::Image) -> Result<(), ShmError> {
        let out = image.as_mut_bytes();
        self.view
            .consistent(|| bytes::load(&self.view.base, IMAGE, out))
    }

    /// One variable's value (element 0 of an array), by symbol name (case-insensitive).
    pub fn read(&self, name: &str) -> Result<Value, ShmError> {
        self.view.read_element(name, 0)
    }

    /// One element of a variable.
    pub fn read_element(&self, name: &str, element: usize) -> Result<Value, ShmError> {
        self.view.read_element(name, element)
    }

    /// Writes a variable, checked here first (unknown names, read-only, input and status
    /// variables, wrong kinds, out-of-range values, over-long strings), then applied by the
    /// owner at its next cycle: returns once applied, or with the owner's refusal.
    pub fn write(&self, name: &str, value: Value) -> Result<(), ShmError> {
        self.write_element(name, 0, value)
    }

    /// Writes one array element, as [`write`](Self::write) does.
    pub fn write_element(&self, name: &str, element: usize, value: Value) -> Result<(), ShmError> {
        self.view.write_element(name, element, value)
    }
}

impl<T: GlobalMemory> Drop for ShmOwner<T> {
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
            for _ in 0..QUEUE {
                let Ok(batch) = rx.try_recv() else { break };
                batch
                    .conn
                    .answer(batch.id, Code::Stopped, 0, "the program stopped".into());
            }
        }
    }
}
