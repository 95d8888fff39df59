//! A segment's alarm thread: every 10 ms it reads the program's alarm table (a copy, never a
//! lock the program waits on), mirrors it into the conditions and sends each transition
//! (raised, acknowledged, returned to normal, shelved, ...) to the event subscribers with the
//! program's transition time as Time. It also carries acknowledgements to the program over the
//! segment's socket, so the shared memory is touched by the segment's own threads only.
//!
//! Bounded whatever the program declares: the mirror is one entry per alarm, each poll sends at
//! most [`EVENTS_PER_POLL`] events (the rest follow at the next polls, starting where this one
//! stopped, so no alarm starves), and each subscriber's queue is async-opcua's, bounded by its
//! queue size.

use super::events::AlarmEvent;
use super::{AckJob, AlarmSpace, Table, nodes, parse_node_id};
use crate::shared::Shared;
use opcua::nodes::Event;
use opcua::server::SubscriptionCache;
use opcua::server::address_space::AddressSpace;
use opcua::sync::RwLock;
use opcua::types::{AttributeId, DateTime, NumericRange};
use plc_shm::protocol::AlarmAction;
use plc_shm::{AlarmDescriptor, DynSegment, OwnerState, ShmError};
use std::collections::HashSet;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{Receiver, RecvTimeoutError};
use std::time::{Duration, Instant};

/// How often the alarm table is read: a transition reaches subscribers within this (plus
/// their publishing interval).
pub const POLL: Duration = Duration::from_millis(10);

/// The most events one poll sends (a flood of transitions, 1,000 alarms at once, is spread
/// over a few polls instead of one burst).
pub const EVENTS_PER_POLL: usize = 256;

/// How often a lost segment is looked for again.
const REATTACH_EVERY: Duration = Duration::from_millis(250);

/// The alarm thread of one segment.
pub struct AlarmPoller {
    alarms: Arc<AlarmSpace>,
    shared: Arc<Shared>,
    space: Arc<RwLock<AddressSpace>>,
    subscriptions: Arc<SubscriptionCache>,
    seg: Option<DynSegment>,
    /// The descriptors the conditions were built from.
    built: Vec<AlarmDescriptor>,
    /// Whether the mirror holds a polled state yet (the first poll sends no events: nothing
    /// changed, the server only started; ConditionRefresh gives the active ones).
    mirrored: bool,
    /// Where the next poll starts comparing (after a poll that hit the bound).
    cursor: usize,
    next_attach: Instant,
}

impl AlarmPoller {
    /// The alarm thread of `alarms`' segment, whose conditions were built from `built`.
    pub fn new(
        alarms: Arc<AlarmSpace>,
        built: Vec<AlarmDescriptor>,
        shared: Arc<Shared>,
        space: Arc<RwLock<AddressSpace>>,
        subscriptions: Arc<SubscriptionCache>,
    ) -> AlarmPoller {
        AlarmPoller {
            alarms,
            shared,
            space,
            subscriptions,
            seg: None,
            built,
            mirrored: false,
            cursor: 0,
            next_attach: Instant::now(),
        }
    }

    /// Runs until `stop` is set or the acknowledgement queue's senders are gone.
    pub fn run(mut self, acks: Receiver<AckJob>, stop: Arc<AtomicBool>) {
        let mut next_poll = Instant::now();
        while !stop.load(Ordering::Relaxed) {
            let now = Instant::now();
            if now >= next_poll {
                self.poll();
                next_poll = (next_poll + POLL).max(now);
            }
            match acks.recv_timeout(next_poll.saturating_duration_since(Instant::now())) {
                Ok(job) => self.acknowledge(job),
                Err(RecvTimeoutError::Timeout) => {}
                Err(RecvTimeoutError::Disconnected) => break,
            }
        }
    }

    /// Attaches again (the program restarted or a new one took the segment over); rebuilds
    /// the conditions if its alarms changed.
    fn attach(&mut self) {
        self.next_attach = Instant::now() + REATTACH_EVERY;
        let Ok(seg) = DynSegment::attach(&self.alarms.segment) else {
            return;
        };
        if seg.owner_state() == OwnerState::Gone {
            return;
        }
        if seg.alarms() != self.built.as_slice() {
            let mut space = self.space.write();
            nodes::remove(&mut space, &self.alarms);
            *self.alarms.table() = Table::new(self.alarms.ns, seg.alarms());
            nodes::insert(&mut space, &self.alarms);
            self.built = seg.alarms().to_vec();
            self.mirrored = false;
            self.cursor = 0;
            log::info!(
                "segment `{}`: the program's alarms changed; {} conditions now",
                self.alarms.segment,
                self.built.len()
            );
        }
        self.seg = Some(seg);
    }

    /// Forgets the attachment; the conditions' Quality turns bad until the program is back.
    fn lose(&mut self, why: &ShmError) {
        if self.seg.take().is_some() {
            log::warn!(
                "segment `{}`: its alarms are not read: {why}",
                self.alarms.segment
            );
        }
        self.alarms.table().connected = false;
    }

    /// Reads the alarm table and sends its transitions.
    fn poll(&mut self) {
        if self.seg.is_none() {
            if Instant::now() < self.next_attach {
                return;
            }
            self.attach();
        }
        let Some(seg) = &self.seg else { return };
        let states = match seg.alarm_states() {
            Ok(states) => states,
            Err(e) => {
                self.lose(&e);
                return;
            }
        };
        let mut events = Vec::new();
        let mut changed = HashSet::new();
        {
            let mut table = self.alarms.table();
            table.connected = true;
            let n = table.conditions.len().min(states.len());
            let start = if n == 0 { 0 } else { self.cursor % n };
            let now = DateTime::now();
            for k in 0..n {
                let i = (start + k) % n;
                if table.conditions[i].entry == states[i] {
                    continue;
                }
                if self.mirrored && events.len() >= EVENTS_PER_POLL {
                    // The rest at the next poll, from here.
                    self.cursor = i;
                    break;
                }
                let c = &mut table.conditions[i];
                c.entry = states[i];
                c.received = now;
                c.event_id = self.alarms.next_event_id(i);
                changed.insert(c.path.clone());
                if self.mirrored {
                    events.push(AlarmEvent::new(c.clone(), nodes::quality(true)));
                }
            }
        }
        self.mirrored = true;
        if changed.is_empty() {
            return;
        }
        // The table's lock is released: notifying takes the subscriptions' locks.
        let program = self.alarms.program_node();
        self.subscriptions
            .notify_events(events.iter().map(|e| (e as &dyn Event, &program)));
        // Data changes for monitored variables of the conditions that changed.
        let monitored = self.shared.monitored();
        let of_changed = monitored.iter().filter(|id| {
            id.namespace == self.alarms.ns
                && parse_node_id(id).is_some_and(|(path, f)| !f.is_empty() && changed.contains(path))
        });
        self.subscriptions.maybe_notify(
            of_changed.map(|id| (id, AttributeId::Value)),
            |id, _, range, _| {
                let mut dv = nodes::value(&self.alarms, id)?;
                if *range != NumericRange::None {
                    dv.value = dv.value.and_then(|v| v.range_of(range).ok());
                }
                Some(dv)
            },
        );
    }

    /// Sends an acknowledgement to the program and answers its outcome.
    fn acknowledge(&mut self, job: AckJob) {
        if self.seg.is_none() {
            self.attach();
        }
        let result = match &self.seg {
            Some(seg) => seg.act_on_alarms(
                AlarmAction::Acknowledge,
                &[job.number],
                &job.comment,
                &job.user,
            ),
            None => Err(ShmError::OwnerGone(self.alarms.segment.clone())),
        };
        if result.is_ok() {
            // The next poll sees the new state and sends it with this comment and user.
            if let Some(c) = self.alarms.table().get_mut(job.number) {
                c.comment = job.comment.clone();
                c.user = job.user.clone();
            }
        }
        let _ = job.reply.send(result);
    }
}
