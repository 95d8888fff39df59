//! What a segment's node manager (async, on the server's threads) and its segment threads (which
//! alone touch the shared memory) share: the current layout, the monitored nodes, and the job
//! queues from one to the other.

use crate::address::Layout;
use crate::alarms::AlarmSpace;
use opcua::server::MonitoredItemHandle;
use opcua::types::{DataValue, NodeId, NumericRange, StatusCode, TimestampsToReturn};
use plc_core::Value;
use std::collections::{BTreeMap, HashMap};
use std::sync::mpsc::Sender;
use std::sync::{Arc, Mutex, PoisonError, RwLock};
use std::time::Duration;
use tokio::sync::oneshot;

/// Values to read: each node with its index range.
pub struct ReadJob {
    /// The nodes to read, in the order of the answer.
    pub items: Vec<(NodeId, NumericRange)>,
    /// The timestamps the client asked for.
    pub timestamps: TimestampsToReturn,
    /// Where the values go.
    pub reply: oneshot::Sender<Vec<DataValue>>,
}

/// One Write of a Value attribute, checked against the layout (access, user, kind).
pub struct WriteJob {
    /// The node written.
    pub node: NodeId,
    /// The elements written, with their new values.
    pub elements: Vec<(usize, Value)>,
    /// The OPC UA user, for the log.
    pub user: String,
    /// Where the outcome goes.
    pub reply: oneshot::Sender<StatusCode>,
}

/// The nodes that have monitored items being sampled (not Disabled), with a count per node,
/// and the same set as a list the sampler takes without holding the lock; and the nodes whose
/// items were enabled again, to be given their current value at the next sample.
///
/// A change of an item costs a hash update; the list is made again only when the sampler asks
/// for it after a change, once per sample at most: a CreateMonitoredItems of 10,000 items is
/// 10,000 updates and one list, not 10,000 lists.
#[derive(Default)]
struct Monitored {
    counts: HashMap<NodeId, usize>,
    list: Arc<Vec<NodeId>>,
    /// Whether `list` is older than `counts`.
    stale: bool,
    /// Each item's node, whether it is sampled, and its sampling interval (microseconds).
    enabled: HashMap<MonitoredItemHandle, (NodeId, bool, u64)>,
    /// The sampling intervals of the sampled items, with a count each: the sampler samples
    /// as fast as the fastest asks, not every cycle of the program.
    intervals: BTreeMap<u64, usize>,
    refresh: Vec<NodeId>,
}

impl Monitored {
    fn count(&mut self, node: &NodeId, interval_us: u64, up: bool) {
        if up {
            *self.counts.entry(node.clone()).or_default() += 1;
            *self.intervals.entry(interval_us).or_default() += 1;
        } else {
            if let Some(n) = self.counts.get_mut(node) {
                *n -= 1;
                if *n == 0 {
                    self.counts.remove(node);
                }
            }
            if let Some(n) = self.intervals.get_mut(&interval_us) {
                *n -= 1;
                if *n == 0 {
                    self.intervals.remove(&interval_us);
                }
            }
        }
        self.stale = true;
    }

    fn list(&mut self) -> Arc<Vec<NodeId>> {
        if self.stale {
            self.list = Arc::new(self.counts.keys().cloned().collect());
            self.stale = false;
        }
        self.list.clone()
    }
}

/// State shared between a segment's node manager and its threads.
pub struct Shared {
    /// The segment's name.
    pub segment: String,
    /// The program's alarms, as conditions.
    pub alarms: Arc<AlarmSpace>,
    layout: RwLock<Arc<Layout>>,
    monitored: Mutex<Monitored>,
    reads: Mutex<Sender<ReadJob>>,
    writes: Mutex<Sender<WriteJob>>,
}

/// Lock helpers that survive a panicked holder (the data stays consistent: each update is one
/// assignment).
fn lock<T>(m: &Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    m.lock().unwrap_or_else(PoisonError::into_inner)
}

impl Shared {
    /// State for `segment`, its first layout, its alarms and the senders of its job queues.
    pub fn new(
        segment: String,
        layout: Layout,
        alarms: Arc<AlarmSpace>,
        reads: Sender<ReadJob>,
        writes: Sender<WriteJob>,
    ) -> Shared {
        Shared {
            segment,
            alarms,
            layout: RwLock::new(Arc::new(layout)),
            monitored: Mutex::default(),
            reads: Mutex::new(reads),
            writes: Mutex::new(writes),
        }
    }

    /// The current layout.
    pub fn layout(&self) -> Arc<Layout> {
        self.layout
            .read()
            .unwrap_or_else(PoisonError::into_inner)
            .clone()
    }

    /// Replaces the layout (after the program's declaration changed).
    pub fn set_layout(&self, layout: Arc<Layout>) {
        *self.layout.write().unwrap_or_else(PoisonError::into_inner) = layout;
    }

    /// Records monitored item `item` on `node`, sampled every `interval` unless `sampling` is
    /// false (created Disabled).
    pub fn monitor(
        &self,
        item: MonitoredItemHandle,
        node: &NodeId,
        sampling: bool,
        interval: Duration,
    ) {
        let us = u64::try_from(interval.as_micros()).unwrap_or(u64::MAX);
        let mut m = lock(&self.monitored);
        if let Some((old, was, old_us)) = m.enabled.insert(item, (node.clone(), sampling, us))
            && was
        {
            m.count(&old, old_us, false);
        }
        if sampling {
            m.count(node, us, true);
        }
    }

    /// How often the fastest sampled item asks to be sampled (`None`: no item is sampled).
    pub fn fastest_sampling(&self) -> Option<Duration> {
        let m = lock(&self.monitored);
        m.intervals
            .keys()
            .next()
            .map(|&us| Duration::from_micros(us))
    }

    /// Sets whether item `item` is sampled (its monitoring mode is not Disabled); one enabled
    /// again gets its node's current value at the next sample.
    pub fn set_sampling(&self, item: MonitoredItemHandle, sampling: bool) {
        let mut m = lock(&self.monitored);
        let Some((node, was, us)) = m.enabled.get(&item).cloned() else {
            return;
        };
        if was == sampling {
            return;
        }
        m.enabled.insert(item, (node.clone(), sampling, us));
        m.count(&node, us, sampling);
        if sampling {
            m.refresh.push(node);
        }
    }

    /// Forgets monitored item `item`.
    pub fn unmonitor(&self, item: MonitoredItemHandle) {
        let mut m = lock(&self.monitored);
        if let Some((node, true, us)) = m.enabled.remove(&item) {
            m.count(&node, us, false);
        }
    }

    /// The nodes to give their current value whether it changed or not (items enabled again).
    pub fn take_refresh(&self) -> Vec<NodeId> {
        std::mem::take(&mut lock(&self.monitored).refresh)
    }

    /// The monitored nodes now.
    pub fn monitored(&self) -> Arc<Vec<NodeId>> {
        lock(&self.monitored).list()
    }

    /// Sends a read to the segment's sampler; `None` once it has stopped.
    pub fn send_read(&self, job: ReadJob) -> Option<()> {
        lock(&self.reads).send(job).ok()
    }

    /// Sends a write to the segment's writer; `None` once it has stopped.
    pub fn send_write(&self, job: WriteJob) -> Option<()> {
        lock(&self.writes).send(job).ok()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_fastest_sampled_interval_is_kept_as_items_come_and_go() {
        let mut m = Monitored::default();
        let (a, b) = (NodeId::new(1, "a"), NodeId::new(1, "b"));
        m.count(&a, 100_000, true);
        m.count(&b, 10_000, true);
        m.count(&a, 10_000, true);
        assert_eq!(m.intervals.keys().next(), Some(&10_000));
        assert_eq!(m.list().len(), 2);
        m.count(&b, 10_000, false);
        assert_eq!(m.intervals.keys().next(), Some(&10_000), "a's second item");
        m.count(&a, 10_000, false);
        assert_eq!(m.intervals.keys().next(), Some(&100_000));
        assert_eq!(m.list().as_slice(), std::slice::from_ref(&a));
        m.count(&a, 100_000, false);
        assert!(m.intervals.is_empty() && m.list().is_empty());
    }
}
