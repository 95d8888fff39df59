//! A program's alarms as OPC UA conditions (Part 9): each alarm a condition object under the
//! program's object, OffNormalAlarmType for a bool alarm and ExclusiveLimitAlarmType for a limit
//! alarm, its state read from the segment's alarm table and its transitions sent to event
//! subscribers.
//!
//! The program keeps the alarms (the runtime evaluates them each cycle, the alarm table holds
//! their states): the server only mirrors them. One thread per segment ([`poller`]) polls the
//! table every 10 ms and turns changes into events; [`nodes`] puts the conditions into the
//! address space and answers reads of their variables from the same mirror; [`events`] is the
//! event a subscriber's filter sees; [`methods`] answers Acknowledge and ConditionRefresh,
//! which [`front`] takes off the core node manager (they are methods of namespace 0).

pub mod events;
pub mod front;
pub mod methods;
pub mod nodes;
pub mod poller;

use opcua::types::{ByteString, DateTime, NodeId, StatusCode};
use plc_shm::{AlarmDescriptor, AlarmEntry, ShmError};
use std::collections::HashMap;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::mpsc::{SyncSender, TrySendError};
use std::sync::{Arc, Mutex, MutexGuard, PoisonError, RwLock};
use tokio::sync::oneshot;

/// What a condition's NodeId adds to its alarm's path: `ns=<ns>;s=<path>#alarm`, its variables
/// `…#alarm/ActiveState/Id`. A variable's path never holds `#`, so neither collides with a
/// variable's node.
const CONDITION_SUFFIX: &str = "#alarm";

/// A limit alarm's limits (an ExclusiveLimitAlarmType's HighHighLimit, ...).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Limits {
    /// HighHighLimit.
    pub high_high: Option<f64>,
    /// HighLimit.
    pub high: Option<f64>,
    /// LowLimit.
    pub low: Option<f64>,
    /// LowLowLimit.
    pub low_low: Option<f64>,
}

/// One alarm as the server mirrors it: what its descriptor says, and its state as last polled.
#[derive(Clone, Debug)]
pub struct Condition {
    /// Its number in the program's alarm list (what `act_on_alarms` takes).
    pub number: usize,
    /// The path of the value it watches: SourceName and ConditionName.
    pub path: String,
    /// The message operators see.
    pub text: String,
    /// 1..=1000.
    pub severity: u16,
    /// `None` for a bool alarm (OffNormalAlarmType).
    pub limits: Option<Limits>,
    /// The condition's node.
    pub node: NodeId,
    /// The watched variable's node (InputNode, SourceNode).
    pub input: NodeId,
    /// Its state as last polled.
    pub entry: AlarmEntry,
    /// The EventId of its last event (an Acknowledge names it).
    pub event_id: ByteString,
    /// When the server saw that transition.
    pub received: DateTime,
    /// The comment of its last acknowledgement through this server.
    pub comment: String,
    /// Who gave it.
    pub user: String,
}

impl Condition {
    /// The condition of `alarm` numbered `number` in namespace `ns`.
    pub fn new(ns: u16, number: usize, alarm: &AlarmDescriptor) -> Condition {
        let limit = alarm.active_when.is_none();
        Condition {
            number,
            path: alarm.path.clone(),
            text: alarm.text.clone(),
            severity: alarm.severity.clamp(1, 1000),
            limits: limit.then_some(Limits {
                high_high: alarm.high_high,
                high: alarm.high,
                low: alarm.low,
                low_low: alarm.low_low,
            }),
            node: condition_node_id(ns, &alarm.path),
            input: crate::mapping::variable_node_id(ns, &alarm.path),
            entry: AlarmEntry::NORMAL,
            event_id: ByteString::null(),
            received: DateTime::now(),
            comment: String::new(),
            user: String::new(),
        }
    }

    /// Whether clients should keep showing it (Retain): anything but normal.
    pub fn retain(&self) -> bool {
        self.entry.state != plc_core::alarm::AlarmState::Normal
    }
}

/// The NodeId of the condition of the alarm at `path`.
pub fn condition_node_id(ns: u16, path: &str) -> NodeId {
    NodeId::new(ns, format!("{path}{CONDITION_SUFFIX}"))
}

/// The alarm path and the field names (`["ActiveState", "Id"]`; none for the condition
/// itself) a node of a condition stands for, if it is one.
pub fn parse_node_id(id: &NodeId) -> Option<(&str, Vec<&str>)> {
    let opcua::types::Identifier::String(s) = &id.identifier else {
        return None;
    };
    let (path, rest) = s.as_ref().split_once(CONDITION_SUFFIX)?;
    if rest.is_empty() {
        return Some((path, Vec::new()));
    }
    let fields = rest.strip_prefix('/')?;
    // The deepest field is three names down (ShelvingState/CurrentState/Id).
    let names: Vec<&str> = fields.splitn(4, '/').collect();
    (names.len() <= 3).then_some((path, names))
}

/// A segment's conditions and whether its program is there.
#[derive(Debug, Default)]
pub struct Table {
    /// In the order of the program's alarms.
    pub conditions: Vec<Condition>,
    by_path: HashMap<String, usize>,
    /// Whether the last poll read the alarm table (Quality Good) or the program is gone.
    pub connected: bool,
}

impl Table {
    /// The table of `alarms` in namespace `ns`, all normal until polled.
    pub fn new(ns: u16, alarms: &[AlarmDescriptor]) -> Table {
        let conditions: Vec<Condition> = alarms
            .iter()
            .enumerate()
            .map(|(i, a)| Condition::new(ns, i, a))
            .collect();
        let by_path = conditions
            .iter()
            .map(|c| (c.path.clone(), c.number))
            .collect();
        Table {
            conditions,
            by_path,
            connected: false,
        }
    }

    /// The condition of the alarm at `path`.
    pub fn by_path(&self, path: &str) -> Option<&Condition> {
        self.by_path.get(path).and_then(|&i| self.conditions.get(i))
    }

    /// The condition whose node is `id`.
    pub fn by_node(&self, id: &NodeId) -> Option<&Condition> {
        match parse_node_id(id) {
            Some((path, fields)) if fields.is_empty() => self.by_path(path),
            _ => None,
        }
    }

    /// Mutable, by number.
    pub fn get_mut(&mut self, number: usize) -> Option<&mut Condition> {
        self.conditions.get_mut(number)
    }
}

/// The most events a monitored item holds between two publishes (a value's item holds
/// [`VALUE_QUEUE`]).
pub const EVENT_QUEUE: usize = 1000;

/// The most values a monitored item of a value holds between two publishes (async-opcua's
/// default).
pub const VALUE_QUEUE: usize = 10;

/// The acknowledgements that may wait for a segment's alarm thread (each waits for a cycle of
/// the program): more at once are refused, so signed-in users cannot queue without bound.
pub const ACK_QUEUE: usize = 64;

/// An acknowledgement for the segment's alarm thread to send the program.
pub struct AckJob {
    /// The alarm's number.
    pub number: usize,
    /// The operator's comment.
    pub comment: String,
    /// The OPC UA user it is done for (the program's journal names them).
    pub user: String,
    /// The program's answer.
    pub reply: oneshot::Sender<Result<(), ShmError>>,
}

/// One segment's alarms, shared by its node manager, its alarm thread and the method handler.
pub struct AlarmSpace {
    /// The segment's name.
    pub segment: String,
    /// The segment's namespace index.
    pub ns: u16,
    table: Mutex<Table>,
    acks: Mutex<Option<SyncSender<AckJob>>>,
    /// Numbers events: with `epoch`, an EventId no other event of this server had.
    sequence: AtomicU64,
    epoch: u64,
}

fn lock<T>(m: &Mutex<T>) -> MutexGuard<'_, T> {
    m.lock().unwrap_or_else(PoisonError::into_inner)
}

impl AlarmSpace {
    /// The alarms of `segment` (namespace `ns`), as its first descriptor lists them.
    pub fn new(segment: String, ns: u16, alarms: &[AlarmDescriptor]) -> AlarmSpace {
        let epoch = std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(0, |d| d.as_nanos() as u64);
        AlarmSpace {
            segment,
            ns,
            table: Mutex::new(Table::new(ns, alarms)),
            acks: Mutex::new(None),
            sequence: AtomicU64::new(0),
            epoch,
        }
    }

    /// The conditions, locked: hold it briefly, and never while notifying subscribers (their
    /// locks are taken in the other order by ConditionRefresh).
    pub fn table(&self) -> MutexGuard<'_, Table> {
        lock(&self.table)
    }

    /// The program object's NodeId (the conditions' parent and their events' emitter).
    pub fn program_node(&self) -> NodeId {
        NodeId::new(self.ns, crate::mapping::PROGRAM_OBJECT_ID)
    }

    /// A new EventId for an event of alarm `number`: the server's start time, the alarm's
    /// number and a sequence number.
    pub fn next_event_id(&self, number: usize) -> ByteString {
        let seq = self.sequence.fetch_add(1, Ordering::Relaxed);
        let mut id = Vec::with_capacity(20);
        id.extend_from_slice(&self.epoch.to_be_bytes());
        id.extend_from_slice(&(number as u32).to_be_bytes());
        id.extend_from_slice(&seq.to_be_bytes());
        ByteString::from(id)
    }

    /// Connects the alarm thread's queue of acknowledgements.
    pub fn set_ack_queue(&self, acks: SyncSender<AckJob>) {
        *lock(&self.acks) = Some(acks);
    }

    /// Queues an acknowledgement for the alarm thread: BadTooManyOperations while
    /// [`ACK_QUEUE`] wait already, BadServerHalted once the thread has stopped.
    pub fn send_ack(&self, job: AckJob) -> Result<(), StatusCode> {
        let acks = lock(&self.acks);
        let Some(acks) = acks.as_ref() else {
            return Err(StatusCode::BadServerHalted);
        };
        acks.try_send(job).map_err(|e| match e {
            TrySendError::Full(_) => StatusCode::BadTooManyOperations,
            TrySendError::Disconnected(_) => StatusCode::BadServerHalted,
        })
    }
}

/// Every served segment's alarms, by namespace: the method handler finds a condition's
/// segment by its NodeId's namespace.
#[derive(Default)]
pub struct Registry {
    spaces: RwLock<Vec<Arc<AlarmSpace>>>,
    /// Numbers the RefreshStartEvents and RefreshEndEvents.
    sequence: AtomicU64,
}

impl Registry {
    /// A new EventId for a RefreshStartEvent or RefreshEndEvent (`refresh` and a sequence
    /// number: no alarm's EventId starts so).
    pub fn next_event_id(&self) -> ByteString {
        let seq = self.sequence.fetch_add(1, Ordering::Relaxed);
        let mut id = b"refresh".to_vec();
        id.extend_from_slice(&seq.to_be_bytes());
        ByteString::from(id)
    }

    /// Adds a segment's alarms.
    pub fn add(&self, space: Arc<AlarmSpace>) {
        self.spaces
            .write()
            .unwrap_or_else(PoisonError::into_inner)
            .push(space);
    }

    /// The alarms of the segment of namespace `ns`.
    pub fn by_namespace(&self, ns: u16) -> Option<Arc<AlarmSpace>> {
        self.all().into_iter().find(|s| s.ns == ns)
    }

    /// Every segment's alarms.
    pub fn all(&self) -> Vec<Arc<AlarmSpace>> {
        self.spaces
            .read()
            .unwrap_or_else(PoisonError::into_inner)
            .clone()
    }
}

/// Lets event filters select ConditionId: the NodeId attribute of a condition type with an
/// empty browse path (Part 9, 5.5.2). async-opcua checks each select clause against the type
/// tree, where no such path is registered, and drops a clause it refuses from the answer (the
/// fields after it then shift, and a client reads them under the wrong names); registered,
/// the clause passes and [`events::AlarmEvent`] answers it with the condition's NodeId.
pub fn register_condition_id(type_tree: &mut opcua::nodes::DefaultTypeTree) {
    use opcua::types::{NodeClass, ObjectTypeId};
    let types = events::OFF_NORMAL.iter().chain(events::EXCLUSIVE_LIMIT);
    for &t in types.filter(|&&t| t != ObjectTypeId::BaseEventType) {
        let type_id = NodeId::from(t);
        // A NodeId of no node: the type tree wants one for the property it records.
        let property = NodeId::new(0, format!("plc-vars:ConditionId:{}", t as u32));
        type_tree.add_type_property(&property, &type_id, &[], NodeClass::Object);
    }
}

/// The status a refused acknowledgement answers with.
pub fn ack_refusal(e: &ShmError) -> StatusCode {
    match e {
        // The program found nothing to acknowledge (acknowledged meanwhile, or normal).
        ShmError::AlarmRefused { .. } => StatusCode::BadConditionBranchAlreadyAcked,
        // The program's write policy does not let the server's uid act on its alarms.
        ShmError::WriteRefused { .. } | ShmError::PermissionDenied { .. } => {
            StatusCode::BadUserAccessDenied
        }
        ShmError::NoAnswer { .. } => StatusCode::BadTimeout,
        other => crate::mapping::write_refusal(other),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn condition_node_ids_name_their_alarm_and_field() {
        let id = NodeId::new(3, "stations[2].door#alarm/ActiveState/Id");
        assert_eq!(
            parse_node_id(&id),
            Some(("stations[2].door", vec!["ActiveState", "Id"]))
        );
        let cond = condition_node_id(3, "oil");
        assert_eq!(parse_node_id(&cond), Some(("oil", vec![])));
        assert_eq!(parse_node_id(&NodeId::new(3, "oil")), None);
        assert_eq!(parse_node_id(&NodeId::new(3, "oil#alarm/a/b/c/d")), None);
        assert_eq!(parse_node_id(&NodeId::new(3, "oil#alarmX")), None);
    }
}
