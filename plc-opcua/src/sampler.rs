//! A segment's sampler thread: the one place that reads the program's shared memory. As often
//! as the fastest monitored item asks (at most once per owner period) it looks at the status
//! block; after each new cycle it takes one seqlock snapshot and hands the monitored items the values that changed, stamped with the cycle's
//! UTC time. It answers Read requests from a fresh snapshot. It follows the owner: values turn
//! Bad or Uncertain when it is gone, stalled or faulted (GoodLocalOverride while a force holds
//! them); after a restart or takeover it attaches again, and rebuilds the namespace if the
//! declaration changed.
//!
//! It only ever copies out of the segment (the seqlock reader retries, never blocks the owner),
//! so however slow the clients are, the program's cycle does not wait for them.

use crate::address::Layout;
use crate::mapping;
use crate::shared::{ReadJob, Shared};
use opcua::server::SubscriptionCache;
use opcua::server::address_space::AddressSpace;
use opcua::sync::RwLock;
use opcua::types::{
    AttributeId, DataValue, DateTime, NodeId, NumericRange, StatusCode, TimestampsToReturn,
};
use plc_shm::{DynSegment, OwnerState};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{Receiver, RecvTimeoutError};
use std::time::{Duration, Instant};

/// How often a lost segment is looked for again.
const REATTACH_EVERY: Duration = Duration::from_millis(250);

/// How often a segment without monitored items is looked at.
const IDLE_POLL: Duration = Duration::from_millis(100);

/// The sampler of one segment.
pub struct Sampler {
    shared: Arc<Shared>,
    space: Arc<RwLock<AddressSpace>>,
    subscriptions: Arc<SubscriptionCache>,
    seg: Option<DynSegment>,
    period: Duration,
    /// The image and owner state the monitored items were last given.
    last_image: Vec<u8>,
    last_state: OwnerState,
    last_cycle: Option<u64>,
    /// The forced values the monitored items were last given, sorted.
    last_forced: Vec<(usize, usize)>,
    next_attach: Instant,
}

/// One snapshot's values with their status and source time.
struct Snapshot<'a> {
    image: &'a [u8],
    status: StatusCode,
    source: Option<DateTime>,
    /// The values held by forces ((variable index, leaf), sorted).
    forced: &'a [(usize, usize)],
}

impl Sampler {
    /// The sampler of `shared`'s segment (whose owner runs with `period`), feeding `space`'s
    /// monitored items. It attaches in its own thread, at its first poll.
    pub fn new(
        shared: Arc<Shared>,
        period: Duration,
        space: Arc<RwLock<AddressSpace>>,
        subscriptions: Arc<SubscriptionCache>,
    ) -> Sampler {
        Sampler {
            shared,
            space,
            subscriptions,
            period: clamp_period(period),
            seg: None,
            last_image: Vec::new(),
            last_state: OwnerState::Running,
            last_cycle: None,
            last_forced: Vec::new(),
            next_attach: Instant::now(),
        }
    }

    /// Runs until `stop` is set or the node manager is gone.
    pub fn run(mut self, reads: Receiver<ReadJob>, stop: Arc<AtomicBool>) {
        let mut next_poll = Instant::now();
        while !stop.load(Ordering::Relaxed) {
            let now = Instant::now();
            if now >= next_poll {
                self.poll();
                // As often as the fastest monitored item asks (never faster than the program
                // cycles): an HMI sampling at 100 ms costs the program's machine ten
                // snapshots a second, not one per cycle. Without monitored items only the
                // owner's state is followed, ten times a second. Missed polls are skipped,
                // not caught up: only the newest cycle matters.
                let every = match self.shared.fastest_sampling() {
                    Some(asked) => self.period.max(asked),
                    None => self.period.max(IDLE_POLL),
                };
                next_poll = (next_poll + every).max(now);
            }
            match reads.recv_timeout(next_poll.saturating_duration_since(Instant::now())) {
                Ok(job) => self.read(job),
                Err(RecvTimeoutError::Timeout) => {}
                Err(RecvTimeoutError::Disconnected) => break,
            }
        }
    }

    /// Follows the owner and feeds the monitored items after each new cycle.
    fn poll(&mut self) {
        if self.seg.is_none() {
            if Instant::now() < self.next_attach {
                return;
            }
            self.attach();
        }
        let Some(seg) = &self.seg else { return };
        let state = seg.owner_state();
        if state == OwnerState::Gone {
            self.lose("its program is gone");
            return;
        }
        let status = seg.status();
        let monitored = self.shared.monitored();
        let refresh = self.shared.take_refresh();
        if monitored.is_empty()
            || (refresh.is_empty()
                && self.last_cycle == Some(status.cycle_count)
                && state == self.last_state)
        {
            self.last_state = state;
            return;
        }
        let image = match seg.snapshot_bytes() {
            Ok(image) => image,
            Err(e) => {
                self.lose(&e.to_string());
                return;
            }
        };
        let forced = forced(seg, status.forces);
        let snap = Snapshot {
            image: &image,
            status: mapping::value_status(state),
            source: mapping::source_time(status.cycle_utc_ns),
            forced: &forced,
        };
        let layout = self.shared.layout();
        let state_changed = state != self.last_state || self.last_cycle.is_none();
        let (previous, previous_forced) = (&self.last_image, &self.last_forced);
        let changed = monitored.iter().filter(|id| {
            let Some(node) = layout.var(id) else {
                return false;
            };
            let var = &node.var;
            let bytes = |img: &[u8]| {
                img.get(var.offset..var.offset + var.size)
                    .map(<[u8]>::to_vec)
            };
            // A force to the value it holds already, or a release that leaves it, changes only
            // its status.
            let holds = |f: &[(usize, usize)]| {
                mapping::holds_force(f, node.index, node.first_leaf, var.elements())
            };
            state_changed
                || bytes(previous) != bytes(&image)
                || holds(previous_forced) != holds(&forced)
                || refresh.contains(id)
        });
        self.subscriptions.maybe_notify(
            changed.map(|id| (id, AttributeId::Value)),
            |id, _, range, _| Some(snap.value(&layout, id, range, TimestampsToReturn::Both)),
        );
        self.last_image = image;
        self.last_forced = forced;
        self.last_state = state;
        self.last_cycle = Some(status.cycle_count);
    }

    /// Drops the segment after its owner went away and tells the monitored items.
    fn lose(&mut self, why: &str) {
        log::warn!(
            "segment `{}`: {why}; its values are Bad until it runs again",
            self.shared.segment
        );
        self.seg = None;
        self.last_cycle = None;
        self.next_attach = Instant::now() + REATTACH_EVERY;
        let layout = self.shared.layout();
        let monitored = self.shared.monitored();
        let bad = mapping::status_only(StatusCode::BadNoCommunication);
        self.subscriptions.maybe_notify(
            monitored
                .iter()
                .filter(|id| layout.by_node.contains_key(id))
                .map(|id| (id, AttributeId::Value)),
            |_, _, _, _| Some(bad.clone()),
        );
    }

    /// Attaches again (a restarted program, a takeover); rebuilds the namespace if the
    /// declaration changed.
    fn attach(&mut self) {
        self.next_attach = Instant::now() + REATTACH_EVERY;
        let Ok(seg) = DynSegment::attach(&self.shared.segment) else {
            return;
        };
        if seg.owner_state() == OwnerState::Gone {
            return;
        }
        let layout = self.shared.layout();
        if !layout.same_nodes(seg.descriptor()) {
            let new = Arc::new(Layout::new(seg.descriptor().clone(), layout.ns));
            {
                let mut space = self.space.write();
                layout.remove_from(&mut space);
                new.insert_into(&mut space, &self.shared.segment, seg.status().stats.period);
                crate::alarms::nodes::relink(&mut space, &self.shared.alarms);
            }
            self.shared.set_layout(new);
            log::info!(
                "segment `{}`: the program's declaration changed; its namespace was rebuilt",
                self.shared.segment
            );
        }
        log::info!(
            "segment `{}`: attached (generation {})",
            self.shared.segment,
            seg.status().generation
        );
        self.period = clamp_period(seg.status().stats.period);
        self.last_image.clear();
        self.seg = Some(seg);
    }

    /// Answers a Read from a fresh snapshot.
    fn read(&mut self, job: ReadJob) {
        let layout = self.shared.layout();
        let fresh = self.fresh();
        let values = match (fresh, self.seg.as_ref()) {
            (Some((image, status, source)), Some(seg)) => {
                let forced = forced(seg, seg.status().forces);
                let snap = Snapshot {
                    image: &image,
                    status,
                    source,
                    forced: &forced,
                };
                job.items
                    .iter()
                    .map(|(id, range)| snap.value(&layout, id, range, job.timestamps))
                    .collect()
            }
            _ => {
                let bad = mapping::status_only(StatusCode::BadNoCommunication);
                vec![bad; job.items.len()]
            }
        };
        // The client may have given up; nothing to do then.
        let _ = job.reply.send(values);
    }

    /// A snapshot now, with the status and source time of its values.
    fn fresh(&mut self) -> Option<(Vec<u8>, StatusCode, Option<DateTime>)> {
        let seg = self.seg.as_ref()?;
        let state = seg.owner_state();
        let status = seg.status();
        match seg.snapshot_bytes() {
            Ok(image) => Some((
                image,
                mapping::value_status(state),
                mapping::source_time(status.cycle_utc_ns),
            )),
            Err(e) => {
                self.lose(&e.to_string());
                None
            }
        }
    }
}

impl Snapshot<'_> {
    /// The Value attribute of node `id` (an index range applied), as a DataValue.
    fn value(
        &self,
        layout: &Layout,
        id: &NodeId,
        range: &NumericRange,
        timestamps: TimestampsToReturn,
    ) -> DataValue {
        let Some(node) = layout.var(id) else {
            return mapping::status_only(StatusCode::BadNodeIdUnknown);
        };
        let var = &node.var;
        let elements: Option<Vec<_>> = (0..var.elements())
            .map(|e| var.value_in(self.image, e))
            .collect();
        let Some(elements) = elements else {
            return mapping::status_only(StatusCode::BadInternalError);
        };
        let variant = mapping::to_value_variant(var, elements);
        let variant = match range {
            NumericRange::None => variant,
            range => match variant.range_of(range) {
                Ok(v) => v,
                Err(status) => return mapping::status_only(status),
            },
        };
        // The whole node's status, also for an index range that leaves its forced element out:
        // the node is what a client monitors.
        let forced = mapping::holds_force(self.forced, node.index, node.first_leaf, var.elements());
        let dv = DataValue {
            value: Some(variant),
            status: Some(mapping::forced_status(self.status, forced)),
            source_timestamp: self.source,
            source_picoseconds: None,
            server_timestamp: Some(DateTime::now()),
            server_picoseconds: None,
        };
        mapping::keep_timestamps(dv, timestamps)
    }
}

/// The values held by forces ((variable index, leaf), sorted), looked up only while the status
/// block counts `count` of them. A table the owner is rewriting all the time counts as none:
/// their values are served all the same, only not marked.
fn forced(seg: &DynSegment, count: u64) -> Vec<(usize, usize)> {
    if count == 0 {
        return Vec::new();
    }
    let mut forced: Vec<(usize, usize)> = seg
        .forces()
        .map(|held| held.iter().map(|f| (f.index, f.leaf)).collect())
        .unwrap_or_default();
    forced.sort_unstable();
    forced
}

/// How often to look at a segment: its owner's period, at least a millisecond (OPC UA intervals
/// are counted in milliseconds), at most a second (a slow program is still followed).
fn clamp_period(period: Duration) -> Duration {
    period.clamp(Duration::from_millis(1), Duration::from_secs(1))
}
