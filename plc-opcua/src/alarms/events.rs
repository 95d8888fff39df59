//! The events subscribers get: an alarm's transition (its condition's fields as they were then),
//! and the RefreshStartEvent and RefreshEndEvent that bracket a ConditionRefresh.
//!
//! They implement async-opcua's `Event` themselves rather than use its generated condition
//! types: those answer no ConditionId (the select clause of the NodeId attribute with an empty
//! browse path gives an empty variant), and a client needs it to acknowledge. A field is
//! answered for a select clause whose TypeDefinitionId is the event's type or one of its
//! supertypes (BaseEventType included, which OPC UA lets clients use for any field), and for a
//! null one; the condition's fields are the same ones [`super::nodes`] serves as variables.

use super::Condition;
use opcua::nodes::Event;
use opcua::types::{
    AttributeId, ByteString, DateTime, EventField, LocalizedText, NodeId, NumericRange, ObjectId,
    ObjectTypeId, QualifiedName, StatusCode, UAString, Variant,
};
use plc_core::alarm::{AlarmState, Level};

/// The supertypes of an OffNormalAlarmType, itself first.
pub(crate) const OFF_NORMAL: &[ObjectTypeId] = &[
    ObjectTypeId::OffNormalAlarmType,
    ObjectTypeId::DiscreteAlarmType,
    ObjectTypeId::AlarmConditionType,
    ObjectTypeId::AcknowledgeableConditionType,
    ObjectTypeId::ConditionType,
    ObjectTypeId::BaseEventType,
];

/// The supertypes of an ExclusiveLimitAlarmType, itself first.
pub(crate) const EXCLUSIVE_LIMIT: &[ObjectTypeId] = &[
    ObjectTypeId::ExclusiveLimitAlarmType,
    ObjectTypeId::LimitAlarmType,
    ObjectTypeId::AlarmConditionType,
    ObjectTypeId::AcknowledgeableConditionType,
    ObjectTypeId::ConditionType,
    ObjectTypeId::BaseEventType,
];

/// OPC UA's DateTime of a UTC time in nanoseconds (null for 0, never set).
pub fn utc(ns: i64) -> DateTime {
    u64::try_from(ns)
        .ok()
        .and_then(crate::mapping::source_time)
        .unwrap_or_else(DateTime::null)
}

fn text(s: &str) -> Variant {
    Variant::from(LocalizedText::new("", s))
}

/// A two-state variable (ActiveState, ...): its text, or under it its Id.
fn two_state(rest: &[&str], on: bool, texts: (&str, &str), since: DateTime) -> Variant {
    match rest {
        [] => text(if on { texts.0 } else { texts.1 }),
        ["Id"] => Variant::from(on),
        ["TransitionTime"] => Variant::from(since),
        _ => Variant::Empty,
    }
}

impl Condition {
    /// Its type: OffNormalAlarmType or ExclusiveLimitAlarmType, with their supertypes.
    pub fn types(&self) -> &'static [ObjectTypeId] {
        if self.limits.is_some() {
            EXCLUSIVE_LIMIT
        } else {
            OFF_NORMAL
        }
    }

    /// The time of its last transition, as the program stamped it.
    pub fn time(&self) -> DateTime {
        utc(self.entry.since_ns)
    }

    /// The value of its field at browse path `names` (`["ActiveState", "Id"]`); empty for one
    /// it does not have. `quality`: Good while its program is there.
    pub fn field(&self, names: &[&str], quality: StatusCode) -> Variant {
        let e = &self.entry;
        let since = self.time();
        let suppressed = e.state == AlarmState::SuppressedByDesign;
        let shelved = e.state == AlarmState::Shelved;
        match names {
            ["EventId"] => Variant::from(self.event_id.clone()),
            ["EventType"] => Variant::from(NodeId::from(self.types()[0])),
            ["SourceNode"] | ["InputNode"] => Variant::from(self.input.clone()),
            ["SourceName"] | ["ConditionName"] => Variant::from(UAString::from(&self.path)),
            ["Time"] => Variant::from(since),
            ["ReceiveTime"] => Variant::from(self.received),
            ["Message"] => text(&self.text),
            ["Severity"] | ["LastSeverity"] => Variant::from(self.severity),
            ["ConditionClassId"] => {
                Variant::from(NodeId::from(ObjectTypeId::ProcessConditionClassType))
            }
            ["ConditionClassName"] => text("Process"),
            ["BranchId"] => Variant::from(NodeId::null()),
            ["Retain"] => Variant::from(self.retain()),
            ["Quality"] => Variant::from(quality),
            ["Comment"] => text(&self.comment),
            ["ClientUserId"] => Variant::from(UAString::from(&self.user)),
            ["EnabledState", rest @ ..] => two_state(rest, true, ("Enabled", "Disabled"), since),
            ["ActiveState", rest @ ..] => {
                two_state(rest, e.active(), ("Active", "Inactive"), since)
            }
            ["AckedState", rest @ ..] => two_state(
                rest,
                e.acknowledged,
                ("Acknowledged", "Unacknowledged"),
                since,
            ),
            ["SuppressedState", rest @ ..] => {
                two_state(rest, suppressed, ("Suppressed", "Unsuppressed"), since)
            }
            ["SuppressedOrShelved"] => Variant::from(suppressed || shelved),
            ["ShelvingState", rest @ ..] => self.shelving(rest),
            ["LimitState", rest @ ..] => self.limit_state(rest),
            [limit] => self.limit(limit),
            _ => Variant::Empty,
        }
    }

    /// ShelvingState/CurrentState (+ Id) and ShelvingState/UnshelveTime.
    fn shelving(&self, rest: &[&str]) -> Variant {
        let (name, id) = match (self.entry.state, self.entry.shelved_until_ns) {
            (AlarmState::Shelved, Some(_)) => (
                "TimedShelved",
                ObjectId::ShelvedStateMachineType_TimedShelved,
            ),
            (AlarmState::Shelved, None) => (
                "OneShotShelved",
                ObjectId::ShelvedStateMachineType_OneShotShelved,
            ),
            _ => ("Unshelved", ObjectId::ShelvedStateMachineType_Unshelved),
        };
        match rest {
            ["CurrentState"] => text(name),
            ["CurrentState", "Id"] => Variant::from(NodeId::from(id)),
            ["UnshelveTime"] => {
                // Milliseconds left on the shelf (a Duration); 0 when not shelved for a time.
                let left = self.entry.shelved_until_ns.map_or(0.0, |until| {
                    let now = std::time::SystemTime::now()
                        .duration_since(std::time::UNIX_EPOCH)
                        .map_or(0, |d| d.as_nanos() as i64);
                    (until.saturating_sub(now).max(0) as f64) / 1e6
                });
                Variant::from(left)
            }
            _ => Variant::Empty,
        }
    }

    /// A limit alarm's LimitState/CurrentState (+ Id): the level it is at, empty while normal.
    fn limit_state(&self, rest: &[&str]) -> Variant {
        if self.limits.is_none() {
            return Variant::Empty;
        }
        let (name, id) = match self.entry.level {
            Level::HighHigh => (
                "HighHigh",
                ObjectId::ExclusiveLimitStateMachineType_HighHigh,
            ),
            Level::High => ("High", ObjectId::ExclusiveLimitStateMachineType_High),
            Level::Low => ("Low", ObjectId::ExclusiveLimitStateMachineType_Low),
            Level::LowLow => ("LowLow", ObjectId::ExclusiveLimitStateMachineType_LowLow),
            Level::Normal | Level::Active => return Variant::Empty,
        };
        match rest {
            ["CurrentState"] => text(name),
            ["CurrentState", "Id"] => Variant::from(NodeId::from(id)),
            _ => Variant::Empty,
        }
    }

    /// HighHighLimit, HighLimit, LowLimit, LowLowLimit of a limit alarm that has it.
    fn limit(&self, name: &str) -> Variant {
        let Some(l) = &self.limits else {
            return Variant::Empty;
        };
        let value = match name {
            "HighHighLimit" => l.high_high,
            "HighLimit" => l.high,
            "LowLimit" => l.low,
            "LowLowLimit" => l.low_low,
            _ => None,
        };
        value.map_or(Variant::Empty, Variant::from)
    }
}

/// A browse path of namespace-0 names, as field names; `None` for one no field has.
fn names(path: &[QualifiedName]) -> Option<Vec<&str>> {
    if path.len() > 3 || path.iter().any(|q| q.namespace_index != 0) {
        return None;
    }
    Some(path.iter().map(|q| q.name.as_ref()).collect())
}

/// A field's value with an index range applied.
fn ranged(v: Variant, range: &NumericRange) -> Variant {
    match range {
        NumericRange::None => v,
        r => v.range_of(r).unwrap_or(Variant::Empty),
    }
}

/// An alarm's transition as subscribers see it: its condition at that moment.
#[derive(Debug)]
pub struct AlarmEvent {
    /// The condition as it was.
    pub condition: Condition,
    /// Quality: Good while its program is there.
    pub quality: StatusCode,
    type_id: NodeId,
    time: DateTime,
}

impl AlarmEvent {
    /// The event of `condition` as it is now.
    pub fn new(condition: Condition, quality: StatusCode) -> AlarmEvent {
        AlarmEvent {
            type_id: NodeId::from(condition.types()[0]),
            time: condition.time(),
            condition,
            quality,
        }
    }
}

/// Whether a select clause's TypeDefinitionId lets one of `types` answer it.
fn answers(types: &[ObjectTypeId], asked: &NodeId) -> bool {
    asked.is_null() || types.iter().any(|t| asked == t)
}

impl EventField for AlarmEvent {
    fn get_value(
        &self,
        attribute_id: AttributeId,
        index_range: &NumericRange,
        remaining_path: &[QualifiedName],
    ) -> Variant {
        match attribute_id {
            // ConditionId: the condition's node.
            AttributeId::NodeId if remaining_path.is_empty() => {
                Variant::from(self.condition.node.clone())
            }
            AttributeId::Value => names(remaining_path).map_or(Variant::Empty, |n| {
                ranged(self.condition.field(&n, self.quality), index_range)
            }),
            _ => Variant::Empty,
        }
    }
}

impl Event for AlarmEvent {
    fn get_field(
        &self,
        type_definition_id: &NodeId,
        attribute_id: AttributeId,
        index_range: &NumericRange,
        browse_path: &[QualifiedName],
    ) -> Variant {
        if !answers(self.condition.types(), type_definition_id) {
            return Variant::Empty;
        }
        self.get_value(attribute_id, index_range, browse_path)
    }

    fn time(&self) -> &DateTime {
        &self.time
    }

    fn event_type_id(&self) -> &NodeId {
        &self.type_id
    }
}

/// RefreshStartEvent or RefreshEndEvent, sent by the Server object.
#[derive(Debug)]
pub struct RefreshEvent {
    types: [ObjectTypeId; 3],
    type_id: NodeId,
    event_id: ByteString,
    time: DateTime,
}

impl RefreshEvent {
    /// A RefreshStartEvent (`start`) or RefreshEndEvent, with EventId `event_id`.
    pub fn new(start: bool, event_id: ByteString) -> RefreshEvent {
        let own = if start {
            ObjectTypeId::RefreshStartEventType
        } else {
            ObjectTypeId::RefreshEndEventType
        };
        RefreshEvent {
            types: [
                own,
                ObjectTypeId::SystemEventType,
                ObjectTypeId::BaseEventType,
            ],
            type_id: NodeId::from(own),
            event_id,
            time: DateTime::now(),
        }
    }
}

impl EventField for RefreshEvent {
    fn get_value(
        &self,
        attribute_id: AttributeId,
        index_range: &NumericRange,
        remaining_path: &[QualifiedName],
    ) -> Variant {
        if attribute_id != AttributeId::Value {
            return Variant::Empty;
        }
        let v = match names(remaining_path).as_deref() {
            Some(["EventId"]) => Variant::from(self.event_id.clone()),
            Some(["EventType"]) => Variant::from(self.type_id.clone()),
            Some(["SourceNode"]) => Variant::from(NodeId::from(ObjectId::Server)),
            Some(["SourceName"]) => Variant::from(UAString::from("Server")),
            Some(["Time"] | ["ReceiveTime"]) => Variant::from(self.time),
            Some(["Message"]) => text(if self.types[0] == ObjectTypeId::RefreshStartEventType {
                "ConditionRefresh starts"
            } else {
                "ConditionRefresh ends"
            }),
            Some(["Severity"]) => Variant::from(1u16),
            _ => Variant::Empty,
        };
        ranged(v, index_range)
    }
}

impl Event for RefreshEvent {
    fn get_field(
        &self,
        type_definition_id: &NodeId,
        attribute_id: AttributeId,
        index_range: &NumericRange,
        browse_path: &[QualifiedName],
    ) -> Variant {
        if !answers(&self.types, type_definition_id) {
            return Variant::Empty;
        }
        self.get_value(attribute_id, index_range, browse_path)
    }

    fn time(&self) -> &DateTime {
        &self.time
    }

    fn event_type_id(&self) -> &NodeId {
        &self.type_id
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use plc_shm::{AlarmDescriptor, AlarmEntry};

    fn event(limit: bool) -> AlarmEvent {
        let mut c = Condition::new(
            4,
            0,
            &AlarmDescriptor {
                severity: 600,
                high_high: Some(95.0),
                high: Some(80.0),
                active_when: (!limit).then_some(true),
                ..AlarmDescriptor::limit("oil", "Oil temperature", 0, 0)
            },
        );
        c.entry = AlarmEntry {
            state: AlarmState::ActiveUnacknowledged,
            level: if limit { Level::High } else { Level::Active },
            acknowledged: false,
            since_ns: 1_700_000_000_000_000_000,
            shelved_until_ns: None,
        };
        AlarmEvent::new(c, StatusCode::Good)
    }

    fn path(names: &[&str]) -> Vec<QualifiedName> {
        names.iter().map(|n| QualifiedName::new(0, *n)).collect()
    }

    fn field(e: &AlarmEvent, type_id: impl Into<NodeId>, names: &[&str]) -> Variant {
        let (range, path) = (NumericRange::None, path(names));
        e.get_field(&type_id.into(), AttributeId::Value, &range, &path)
    }

    #[test]
    fn fields_answer_for_the_event_type_its_supertypes_and_base_event_type_only() {
        let e = event(true);
        for t in EXCLUSIVE_LIMIT {
            assert_eq!(field(&e, *t, &["Severity"]), Variant::from(600u16), "{t:?}");
        }
        assert_eq!(
            field(&e, NodeId::null(), &["ActiveState", "Id"]),
            true.into()
        );
        assert_eq!(
            field(&e, ObjectTypeId::OffNormalAlarmType, &["Severity"]),
            Variant::Empty,
            "a bool alarm's type is not a limit alarm's"
        );
        assert_eq!(
            field(
                &e,
                ObjectTypeId::BaseEventType,
                &["LimitState", "CurrentState"]
            ),
            text("High")
        );
        assert_eq!(
            field(&e, ObjectTypeId::BaseEventType, &["Nonsense"]),
            Variant::Empty
        );
        let other_ns = vec![QualifiedName::new(3, "Severity")];
        let base = NodeId::from(ObjectTypeId::BaseEventType);
        let none = NumericRange::None;
        let v = e.get_field(&base, AttributeId::Value, &none, &other_ns);
        assert_eq!(v, Variant::Empty, "fields are of namespace 0");
        assert_eq!(
            e.event_type_id(),
            &NodeId::from(ObjectTypeId::ExclusiveLimitAlarmType)
        );
        assert_eq!(*e.time(), utc(1_700_000_000_000_000_000));
    }

    #[test]
    fn condition_id_is_the_condition_node() {
        let e = event(false);
        let condition = NodeId::from(ObjectTypeId::ConditionType);
        let id = e.get_field(&condition, AttributeId::NodeId, &NumericRange::None, &[]);
        assert_eq!(id, Variant::from(NodeId::new(4, "oil#alarm")));
        assert_eq!(
            field(
                &e,
                ObjectTypeId::BaseEventType,
                &["LimitState", "CurrentState"]
            ),
            Variant::Empty,
            "a bool alarm has no LimitState"
        );
    }

    #[test]
    fn refresh_events_answer_base_event_fields() {
        let start = RefreshEvent::new(true, ByteString::from(b"r1".to_vec()));
        let base = NodeId::from(ObjectTypeId::BaseEventType);
        let (none, event_type) = (NumericRange::None, path(&["EventType"]));
        let v = start.get_field(&base, AttributeId::Value, &none, &event_type);
        assert_eq!(
            v,
            Variant::from(NodeId::from(ObjectTypeId::RefreshStartEventType))
        );
        let condition = NodeId::from(ObjectTypeId::ConditionType);
        let v = start.get_field(&condition, AttributeId::Value, &none, &event_type);
        assert_eq!(v, Variant::Empty, "a refresh event is no condition");
    }
}
