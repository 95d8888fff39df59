//! The conditions in the address space: one object per alarm under the program's object, typed
//! OffNormalAlarmType or ExclusiveLimitAlarmType, with the variables of Part 9 a client reads
//! (ActiveState and its Id, AckedState, Severity, Message, Time, ...). The in-memory node
//! manager keeps the nodes and answers Browse; their values come from the mirror of the alarm
//! table ([`value`]), the same fields the events carry, so a Read and an event never disagree.

use super::{AlarmSpace, Condition};
use opcua::nodes::{ObjectBuilder, VariableBuilder};
use opcua::server::address_space::{AccessLevel, AddressSpace};
use opcua::types::{
    DataTypeId, DataValue, DateTime, LocalizedText, MethodId, NodeId, ObjectTypeId, QualifiedName,
    ReferenceTypeId, StatusCode, VariableTypeId, Variant,
};

/// One variable of a condition.
struct Var {
    /// Its browse path under the condition, `/` between names.
    path: &'static str,
    data_type: DataTypeId,
    type_def: VariableTypeId,
    /// HasProperty (else HasComponent) from its parent.
    property: bool,
    /// Only a limit alarm has it.
    limit_only: bool,
}

const fn var(path: &'static str, data_type: DataTypeId, property: bool) -> Var {
    Var {
        path,
        data_type,
        type_def: if property {
            VariableTypeId::PropertyType
        } else {
            VariableTypeId::BaseDataVariableType
        },
        property,
        limit_only: false,
    }
}

const fn two_state(path: &'static str) -> Var {
    Var {
        path,
        data_type: DataTypeId::LocalizedText,
        type_def: VariableTypeId::TwoStateVariableType,
        property: false,
        limit_only: false,
    }
}

const fn limit(mut v: Var) -> Var {
    v.limit_only = true;
    v
}

/// The condition's objects (state machines) with their type, parents before their variables.
const OBJECTS: &[(&str, ObjectTypeId, bool)] = &[
    (
        "ShelvingState",
        ObjectTypeId::ShelvedStateMachineType,
        false,
    ),
    (
        "LimitState",
        ObjectTypeId::ExclusiveLimitStateMachineType,
        true,
    ),
];

/// The condition's variables, each after its parent.
const VARS: &[Var] = &[
    var("EventId", DataTypeId::ByteString, true),
    var("EventType", DataTypeId::NodeId, true),
    var("SourceNode", DataTypeId::NodeId, true),
    var("SourceName", DataTypeId::String, true),
    var("Time", DataTypeId::UtcTime, true),
    var("ReceiveTime", DataTypeId::UtcTime, true),
    var("Message", DataTypeId::LocalizedText, true),
    var("Severity", DataTypeId::UInt16, true),
    var("ConditionClassId", DataTypeId::NodeId, true),
    var("ConditionClassName", DataTypeId::LocalizedText, true),
    var("ConditionName", DataTypeId::String, true),
    var("BranchId", DataTypeId::NodeId, true),
    var("Retain", DataTypeId::Boolean, true),
    two_state("EnabledState"),
    var("EnabledState/Id", DataTypeId::Boolean, true),
    var("Quality", DataTypeId::StatusCode, false),
    var("LastSeverity", DataTypeId::UInt16, false),
    var("Comment", DataTypeId::LocalizedText, false),
    var("ClientUserId", DataTypeId::String, true),
    two_state("AckedState"),
    var("AckedState/Id", DataTypeId::Boolean, true),
    two_state("ActiveState"),
    var("ActiveState/Id", DataTypeId::Boolean, true),
    var("InputNode", DataTypeId::NodeId, true),
    two_state("SuppressedState"),
    var("SuppressedState/Id", DataTypeId::Boolean, true),
    var("SuppressedOrShelved", DataTypeId::Boolean, true),
    Var {
        path: "ShelvingState/CurrentState",
        data_type: DataTypeId::LocalizedText,
        type_def: VariableTypeId::FiniteStateVariableType,
        property: false,
        limit_only: false,
    },
    var("ShelvingState/CurrentState/Id", DataTypeId::NodeId, true),
    var("ShelvingState/UnshelveTime", DataTypeId::Duration, true),
    limit(Var {
        path: "LimitState/CurrentState",
        data_type: DataTypeId::LocalizedText,
        type_def: VariableTypeId::FiniteStateVariableType,
        property: false,
        limit_only: true,
    }),
    limit(var("LimitState/CurrentState/Id", DataTypeId::NodeId, true)),
    limit(var("HighHighLimit", DataTypeId::Double, true)),
    limit(var("HighLimit", DataTypeId::Double, true)),
    limit(var("LowLimit", DataTypeId::Double, true)),
    limit(var("LowLowLimit", DataTypeId::Double, true)),
];

/// The node of the field at `path` (`ActiveState/Id`) of condition `cond`.
fn field_node(cond: &NodeId, path: &str) -> NodeId {
    let opcua::types::Identifier::String(s) = &cond.identifier else {
        return cond.clone();
    };
    NodeId::new(cond.namespace, format!("{}/{path}", s.as_ref()))
}

/// Whether condition `c` has the field at `path`: a limit alarm's own fields only for a limit
/// alarm, and of its limits only those it sets.
fn has(c: &Condition, v: &Var) -> bool {
    if !v.limit_only {
        return true;
    }
    if c.limits.is_none() {
        return false;
    }
    !v.path.ends_with("Limit") || !matches!(c.field(&[v.path], StatusCode::Good), Variant::Empty)
}

/// Adds every condition of `alarms` under the program's object.
pub fn insert(space: &mut AddressSpace, alarms: &AlarmSpace) {
    let program = alarms.program_node();
    let table = alarms.table();
    for c in &table.conditions {
        insert_condition(space, alarms.ns, &program, c);
    }
}

fn insert_condition(space: &mut AddressSpace, ns: u16, program: &NodeId, c: &Condition) {
    ObjectBuilder::new(
        &c.node,
        QualifiedName::new(ns, c.path.as_str()),
        c.path.as_str(),
    )
    .description(LocalizedText::from(c.text.as_str()))
    .has_type_definition(c.types()[0])
    .insert(space);
    link(space, program, c);
    // The type's Acknowledge, which a client calls with the condition as the object.
    space.insert_reference(
        &c.node,
        &NodeId::from(MethodId::AcknowledgeableConditionType_Acknowledge),
        ReferenceTypeId::HasComponent,
    );
    for (path, type_id, limit_only) in OBJECTS {
        if *limit_only && c.limits.is_none() {
            continue;
        }
        ObjectBuilder::new(
            &field_node(&c.node, path),
            QualifiedName::new(0, *path),
            *path,
        )
        .has_type_definition(*type_id)
        .component_of(c.node.clone())
        .insert(space);
    }
    let read = AccessLevel::CURRENT_READ;
    for v in VARS.iter().filter(|v| has(c, v)) {
        let (parent, name) = match v.path.rsplit_once('/') {
            Some((parent, name)) => (field_node(&c.node, parent), name),
            None => (c.node.clone(), v.path),
        };
        let builder = VariableBuilder::new(
            &field_node(&c.node, v.path),
            QualifiedName::new(0, name),
            name,
        )
        .data_type(v.data_type)
        .access_level(read)
        .user_access_level(read)
        .has_type_definition(v.type_def);
        let builder = if v.property {
            builder.property_of(parent)
        } else {
            builder.component_of(parent)
        };
        builder.insert(space);
    }
}

/// The references into a condition from nodes the sampler may rebuild: the program's
/// HasComponent and the watched variable's HasCondition.
fn link(space: &mut AddressSpace, program: &NodeId, c: &Condition) {
    space.insert_reference(program, &c.node, ReferenceTypeId::HasComponent);
    space.insert_reference(&c.input, &c.node, ReferenceTypeId::HasCondition);
}

/// Links the conditions again after the program's object and variables were rebuilt (a
/// changed declaration deletes them with their references).
pub fn relink(space: &mut AddressSpace, alarms: &AlarmSpace) {
    let program = alarms.program_node();
    for c in &alarms.table().conditions {
        link(space, &program, c);
    }
}

/// Removes every condition of `alarms` with its variables.
pub fn remove(space: &mut AddressSpace, alarms: &AlarmSpace) {
    for c in &alarms.table().conditions {
        for v in VARS.iter().rev() {
            space.delete(&field_node(&c.node, v.path), true);
        }
        for (path, _, _) in OBJECTS {
            space.delete(&field_node(&c.node, path), true);
        }
        space.delete(&c.node, true);
    }
}

/// The Value of node `id` if it is a condition's variable in `alarms`' namespace.
pub fn value(alarms: &AlarmSpace, id: &NodeId) -> Option<DataValue> {
    if id.namespace != alarms.ns {
        return None;
    }
    let (path, names) = super::parse_node_id(id)?;
    let table = alarms.table();
    let c = table.by_path(path)?;
    if names.is_empty() {
        // The condition object has no Value.
        return Some(crate::mapping::status_only(
            StatusCode::BadAttributeIdInvalid,
        ));
    }
    let quality = quality(table.connected);
    let status = if table.connected {
        StatusCode::Good
    } else {
        StatusCode::UncertainLastUsableValue
    };
    Some(DataValue {
        value: Some(c.field(&names, quality)),
        status: Some(status),
        source_timestamp: Some(c.time()).filter(|t| !t.is_null()),
        source_picoseconds: None,
        server_timestamp: Some(DateTime::now()),
        server_picoseconds: None,
    })
}

/// A condition's Quality: Good while the program's alarm table is read.
pub fn quality(connected: bool) -> StatusCode {
    if connected {
        StatusCode::Good
    } else {
        StatusCode::BadNoCommunication
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_variable_follows_its_parent_and_answers_a_value() {
        let mut seen: Vec<&str> = OBJECTS.iter().map(|o| o.0).collect();
        let c = Condition::new(
            2,
            0,
            &plc_shm::AlarmDescriptor {
                severity: 600,
                high_high: Some(95.0),
                high: Some(80.0),
                ..plc_shm::AlarmDescriptor::limit("oil", "Oil temperature", 0, 0)
            },
        );
        for v in VARS {
            if let Some((parent, _)) = v.path.rsplit_once('/') {
                assert!(seen.contains(&parent), "{} before its parent", v.path);
            }
            seen.push(v.path);
            let names: Vec<&str> = v.path.split('/').collect();
            let value = c.field(&names, StatusCode::Good);
            let may_be_empty = v.path.starts_with("LimitState") || v.path == "EventId";
            assert!(
                may_be_empty || !matches!(value, Variant::Empty) || !has(&c, v),
                "{} has no value",
                v.path
            );
        }
        assert!(!has(
            &c,
            VARS.iter().find(|v| v.path == "LowLimit").unwrap()
        ));
    }
}
