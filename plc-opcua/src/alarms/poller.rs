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
        let (events, changed) = {
            let mut table = self.alarms.table();
            table.connected = true;
            let bound = if self.mirrored {
                EVENTS_PER_POLL
            } else {
                usize::MAX
            };
            let (changed, cursor) = mirror(&mut table, &states, self.cursor, bound, |i| {
                self.alarms.next_event_id(i)
            });
            self.cursor = cursor;
            let events: Vec<AlarmEvent> = match self.mirrored {
                true => changed
                    .iter()
                    .map(|&i| AlarmEvent::new(table.conditions[i].clone(), nodes::quality(true)))
                    .collect(),
                false => Vec::new(),
            };
            let paths: HashSet<String> = changed
                .iter()
                .map(|&i| table.conditions[i].path.clone())
                .collect();
            (events, paths)
        };
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
                && parse_node_id(id)
                    .is_some_and(|(path, f)| !f.is_empty() && changed.contains(path))
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

/// Mirrors `states` into `table`: each condition whose state changed takes it, with a new
/// EventId (`event_id`) and receive time. At most `bound` of them, starting at `cursor`;
/// returns the numbers of those that changed and where the next call starts (where this one
/// stopped when it hit the bound, so every alarm gets its turn).
fn mirror(
    table: &mut Table,
    states: &[plc_shm::AlarmEntry],
    cursor: usize,
    bound: usize,
    mut event_id: impl FnMut(usize) -> opcua::types::ByteString,
) -> (Vec<usize>, usize) {
    let n = table.conditions.len().min(states.len());
    let start = if n == 0 { 0 } else { cursor % n };
    let now = DateTime::now();
    let mut changed = Vec::new();
    for k in 0..n {
        let i = (start + k) % n;
        if table.conditions[i].entry == states[i] {
            continue;
        }
        if changed.len() >= bound {
            return (changed, i);
        }
        let c = &mut table.conditions[i];
        c.entry = states[i];
        c.received = now;
        c.event_id = event_id(i);
        changed.push(i);
    }
    (changed, start)
}

#[cfg(test)]
mod tests {
    use super::*;
    use plc_core::alarm::{AlarmState, Level};
    use plc_shm::AlarmEntry;

    fn alarms(n: usize) -> Vec<AlarmDescriptor> {
        (0..n)
            .map(|i| AlarmDescriptor::discrete(&format!("doors[{i}]"), "Door open", 0, i))
            .collect()
    }

    const RAISED: AlarmEntry = AlarmEntry {
        state: AlarmState::ActiveUnacknowledged,
        level: Level::Active,
        acknowledged: false,
        since_ns: 1,
        shelved_until_ns: None,
    };

    #[test]
    fn a_flood_of_transitions_is_sent_a_bounded_batch_per_poll_and_every_alarm_gets_its_turn() {
        let mut table = Table::new(2, &alarms(1000));
        let states = vec![RAISED; 1000];
        let mut seen = HashSet::new();
        let mut cursor = 0;
        let mut polls = 0;
        loop {
            let (changed, next) = mirror(&mut table, &states, cursor, EVENTS_PER_POLL, |_| {
                opcua::types::ByteString::null()
            });
            if changed.is_empty() {
                break;
            }
            assert!(changed.len() <= EVENTS_PER_POLL);
            seen.extend(changed);
            cursor = next;
            polls += 1;
        }
        assert_eq!(seen.len(), 1000);
        assert_eq!(polls, 1000_usize.div_ceil(EVENTS_PER_POLL));
        assert!(table.conditions.iter().all(|c| c.entry == RAISED));
    }

    #[test]
    fn a_table_shorter_or_longer_than_the_conditions_is_mirrored_as_far_as_both_go() {
        let mut table = Table::new(2, &alarms(3));
        let (changed, _) = mirror(&mut table, &[RAISED; 5], 7, usize::MAX, |_| {
            opcua::types::ByteString::null()
        });
        assert_eq!(changed.len(), 3);
        let (changed, _) = mirror(&mut table, &[AlarmEntry::NORMAL], 0, usize::MAX, |_| {
            opcua::types::ByteString::null()
        });
        assert_eq!(changed, vec![0]);
    }
}
