//! `SharedGlobalMemory<T>`: a program's variables in a named segment, as [`ShmOwner`] for its
//! owner (the control program, which publishes) and as [`ShmReader`] for typed readers in other
//! processes.

use super::descriptor::LayoutDescriptor;
use super::error::not_writable_reason;
use super::layout::*;
use super::mailbox::{self, Consumer, Rejection, Request};
use super::segment::{self, Segment};
use super::status::{OwnerState, RunState, Status, now_ns, write_report};
use super::view::View;
use super::{ShmError, bytes};
use crate::runtime::{CycleStats, IoStatus};
use plc_core::{GlobalMemory, Value};
use std::cell::Cell;
use std::marker::PhantomData;
use std::mem::size_of;
use std::sync::atomic::{Ordering, fence};
use std::time::{Duration, Instant};
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
/// never a torn image), reads single variables, and posts writes to the mailbox, which the
/// owner applies at the start of its next cycle through [`GlobalMemory::set`]. Owner-only
/// calls do not exist on a reader.
///
/// ```
/// use plc_core::GlobalMemory;
/// use plc_io::shm::SharedGlobalMemory;
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
/// reader.write("setpoint", plc_core::Value::Real(2.5))?;
/// assert_eq!(owner.apply_mailbox(&mut gm), 1);
/// assert_eq!(gm.setpoint, 2.5);
/// # Ok::<(), plc_io::shm::ShmError>(())
/// ```
pub struct SharedGlobalMemory<T: GlobalMemory> {
    _never: std::convert::Infallible,
    _t: PhantomData<fn() -> T>,
}

impl<T: GlobalMemory> SharedGlobalMemory<T> {
    /// Creates segment `name` as its owner (mode 0600). A segment left by a dead owner is taken
    /// over with a new generation; one owned by a live process is refused.
    pub fn create(name: &str) -> Result<ShmOwner<T>, ShmError> {
        let name = segment::normalise(name)?;
        let desc = LayoutDescriptor::of::<T>();
        let json = serde_json::to_vec(&desc).map_err(|e| ShmError::Corrupt {
            name: name.clone(),
            why: e.to_string(),
        })?;
        let off = Offsets::new(size_of::<T::Image>());
        let (seg, generation) = Segment::create(&name, off.descriptor + json.len())?;
        let base = seg.base();
        let header = Header {
            json,
            hash: T::LAYOUT_HASH,
            off,
        };
        header.write(&base, generation, RunState::Starting);
        base.store(H_SEQ, 0);
        base.store(S_HEARTBEAT_NS, now_ns());
        mailbox::init(&base, &off);
        // Last, so an attaching reader sees either nothing or a complete segment.
        base.store(H_MAGIC, MAGIC);
        Ok(ShmOwner {
            view: View {
                seg,
                base,
                off,
                desc,
                generation,
                checked_alive: Default::default(),
            },
            consumer: Consumer::default(),
            seq: Cell::new(0),
            header,
            run_state: Cell::new(RunState::Starting),
            checked: Instant::now(),
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

/// The owner of a segment (the control program): publishes, applies the mailbox, reports.
/// From [`SharedGlobalMemory::create`].
pub struct ShmOwner<T: GlobalMemory> {
    view: View,
    consumer: Consumer,
    /// The owner's seqlock counter, in its own memory: the shared word is only ever written
    /// from it, never read back, so whatever another process stores there is overwritten at
    /// the next publish instead of steering it.
    seq: Cell<u64>,
    /// What the header and descriptor must say, kept to write them again.
    header: Header,
    /// The state it reports, kept here for the same reason.
    run_state: Cell<RunState>,
    /// When the shared words were last checked and repaired.
    checked: Instant,
    _t: PhantomData<fn() -> T>,
}

/// How often the owner writes its header and descriptor again and checks the mailbox ring: a
/// process that scribbled over them breaks the tools for at most this long.
const REPAIR_EVERY: Duration = Duration::from_millis(100);

/// The header and descriptor of a segment, in the owner's memory.
struct Header {
    json: Vec<u8>,
    hash: u64,
    off: Offsets,
}

impl Header {
    fn write(&self, base: &Base, generation: u64, state: RunState) {
        base.store(H_VERSION, plc_rules::layout::FORMAT_VERSION as u64);
        base.store(H_LAYOUT_HASH, self.hash);
        base.store(H_IMAGE_SIZE, self.off.image_size as u64);
        base.store(H_GENERATION, generation);
        base.store(H_DESC_OFFSET, self.off.descriptor as u64);
        base.store(H_DESC_LEN, self.json.len() as u64);
        base.store(S_PID, std::process::id() as u64);
        base.store(S_STATE, state as u64);
        bytes::store(base, self.off.descriptor, &self.json);
    }
}

impl<T: GlobalMemory> ShmOwner<T> {
    /// Undoes what another process did to the segment: a truncated one is replaced by a new
    /// segment (a new generation; readers attach again), and every [`REPAIR_EVERY`] the header,
    /// the descriptor and the mailbox's words are written again from the owner's memory (a
    /// ring whose words no longer fit together starts empty again; requests in it are lost).
    /// Called at each [`apply_mailbox`](Self::apply_mailbox), so at every cycle.
    fn repair(&mut self) {
        if self.view.seg.damaged() {
            let size = self.header.off.descriptor + self.header.json.len();
            let Ok(base) = self.view.seg.renew(size) else {
                return; // tried again at the next cycle
            };
            let generation = segment::next_generation(self.view.generation);
            self.view.base = base;
            self.view.generation = generation;
            self.header.write(&base, generation, self.run_state.get());
            self.seq.set(0);
            base.store(H_SEQ, 0);
            base.store(S_HEARTBEAT_NS, now_ns());
            self.consumer.restart(&base, &self.header.off);
            base.store(H_MAGIC, MAGIC);
            self.checked = Instant::now();
            return;
        }
        if self.checked.elapsed() < REPAIR_EVERY {
            return;
        }
        self.checked = Instant::now();
        let base = self.view.base;
        base.store(H_MAGIC, MAGIC);
        self.header
            .write(&base, self.view.generation, self.run_state.get());
        base.store(H_SEQ, self.seq.get());
        self.consumer.repair(&base, &self.header.off);
    }

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
        let base = &self.view.base;
        let seq = base.word(H_SEQ);
        // Even: no write in progress. Wrapping keeps the parity.
        let s = self.seq.get();
        seq.store(s.wrapping_add(1), Ordering::Relaxed);
        fence(Ordering::Release);
        bytes::store(base, IMAGE, image.as_bytes());
        seq.store(s.wrapping_add(2), Ordering::Release);
        self.seq.set(s.wrapping_add(2));
        base.store(S_HEARTBEAT_NS, now_ns());
        Ok(())
    }

    /// Applies the mailbox's requests to `gm` in order. Returns
    /// how many were taken. A request that is refused is counted, not applied: the owner checks
    /// again that the variable may be written from outside and that `set` accepts the value,
    /// since any process that maps the segment can post anything.
    pub fn apply_mailbox(&mut self, gm: &mut T) -> usize {
        self.apply_mailbox_with(gm, |_, _| {})
    }

    /// Like [`apply_mailbox`](Self::apply_mailbox), calling `audit` with each request and the
    /// outcome of applying it (to log operator writes, for example).
    pub fn apply_mailbox_with(
        &mut self,
        gm: &mut T,
        mut audit: impl FnMut(&Request, &Result<(), Rejection>),
    ) -> usize {
        self.repair();
        let consumer = &mut self.consumer;
        let base = self.view.base;
        let (mut ok, mut bad) = (0u64, 0u64);
        let n = consumer.drain(&base, &self.view.off, |r| {
            let result = writable::<T>(r.index, r.element)
                .and_then(|()| gm.set(r.index, r.element, r.value).map_err(Rejection::Set));
            match result {
                Ok(()) => ok += 1,
                Err(_) => bad += 1,
            }
            audit(&r, &result);
            result.is_ok()
        });
        // Counted here and stored: the shared words are for tools, never read back.
        consumer.applied = consumer.applied.wrapping_add(ok);
        consumer.rejected = consumer.rejected.wrapping_add(bad);
        base.store(S_MB_APPLIED, consumer.applied);
        base.store(S_MB_REJECTED, consumer.rejected);
        n
    }

    /// A consistent copy of the image as readers see it, into `image` (for tests and
    /// benchmarks of the whole round trip; the program itself has its variables).
    pub fn snapshot_image_into(&self, image: &mut T::Image) -> Result<(), ShmError> {
        let out = image.as_mut_bytes();
        self.view
            .consistent(|| bytes::load(&self.view.base, IMAGE, out))
    }

    /// Whether another process truncated the segment while this handle maps it. The handle
    /// keeps working (it reads zeros, and what it publishes reaches nobody) instead of the
    /// process dying of SIGBUS, until the next [`apply_mailbox`](Self::apply_mailbox) replaces
    /// the segment by a new one (a new generation, which tools attach to again).
    pub fn damaged(&self) -> bool {
        self.view.seg.damaged()
    }

    /// Publishes the figures of cycle `cycle_count` and a heartbeat.
    pub fn report(&self, cycle_count: u64, stats: &CycleStats, io: &IoStatus) {
        write_report(&self.view.base, cycle_count, stats, io);
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
/// writes through the mailbox. From [`SharedGlobalMemory::attach`].
///
/// A reader cannot publish: a second seqlock writer would let readers take torn images, so the
/// call does not exist.
///
/// ```compile_fail,E0599
/// # use plc_core::GlobalMemory;
/// # #[derive(GlobalMemory, Debug, Clone)]
/// # struct Gm { count: u32 }
/// let reader = plc_io::shm::SharedGlobalMemory::<Gm>::attach("press")?;
/// reader.publish(&Gm::default())?;
/// # Ok::<(), plc_io::shm::ShmError>(())
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

    /// Posts a write to the mailbox; refused up front for unknown names, read-only, input and
    /// status variables, wrong kinds, out-of-range values and over-long strings.
    pub fn write(&self, name: &str, value: Value) -> Result<(), ShmError> {
        self.view.write_element(name, 0, value).map(drop)
    }

    /// Posts a write of one array element.
    pub fn write_element(&self, name: &str, element: usize, value: Value) -> Result<(), ShmError> {
        self.view.write_element(name, element, value).map(drop)
    }
}

/// Whether element (leaf) `element` of variable `index` of `T` may be written from outside:
/// its declaration decides, not the descriptor in the segment, which any process could have
/// changed. Inside a structure, the member and every structure on the way must be writable.
fn writable<T: GlobalMemory>(index: usize, element: usize) -> Result<(), Rejection> {
    let Some(var) = T::VARIABLES.get(index) else {
        return Err(Rejection::Set(plc_core::SetError::UnknownIndex { index }));
    };
    let Some(found) = plc_rules::path::leaf(T::VARIABLES, index, element) else {
        return Err(Rejection::Set(plc_core::SetError::ElementOutOfRange {
            name: var.name,
            element,
            len: var.leaves(),
        }));
    };
    if found.writable {
        return Ok(());
    }
    let leaf = found.node;
    // The first thing on the way that is not writable says why.
    let (read_only, direction, name) = if !var.writable_from_outside() {
        (
            var.access == plc_core::Access::ReadOnly,
            var.direction,
            var.name,
        )
    } else {
        (true, leaf.direction, leaf.name)
    };
    Err(Rejection::NotWritable {
        variable: name,
        reason: not_writable_reason(read_only, direction),
    })
}

impl<T: GlobalMemory> Drop for ShmOwner<T> {
    fn drop(&mut self) {
        // A fault stays visible to readers still attached: only a running owner stops.
        if self.run_state.get() != RunState::Faulted {
            self.set_run_state(RunState::Stopped);
        }
    }
}
