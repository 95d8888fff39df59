//! A declaration's alarms (the descriptor's list: a compiled type's, or a running program's
//! segment's) in its exported list: each alarm on the variable, or on the structure type's
//! member, that declares it, as `"alarm"` in the form the importer reads.

use plc_core::Time;
use plc_rules::path::element_leaves;
use plc_shm::{AlarmDescriptor, VarDescriptor};
use serde_json::{Map, Value, json};

/// Adds each alarm of `alarms` to `list` (`{ "types": .., "variables": .. }`, as
/// `descriptor_to_json` gives it for `vars`). An array of bools, or a structure type used
/// many times, declares its alarm once: the first instance's is written.
pub fn add(list: &mut Value, vars: &[VarDescriptor], alarms: &[AlarmDescriptor]) {
    for a in alarms {
        let Some(top) = vars.get(a.variable) else {
            continue;
        };
        let (slot, suppress) = if top.members.is_empty() {
            (
                &mut list["variables"][top.name.as_str()],
                a.suppress_when.clone(),
            )
        } else {
            let Some((ty, member)) = member_at(top, a.leaf % element_leaves(top).max(1)) else {
                continue;
            };
            // A structure's alarm is suppressed by a member of the same structure: the last
            // step of its path.
            let suppress = a
                .suppress_when
                .as_deref()
                .map(|p| p.rsplit('.').next().unwrap_or(p).to_string());
            (&mut list["types"][ty]["variables"][member], suppress)
        };
        if let Value::Object(var) = slot
            && !var.contains_key("alarm")
        {
            var.insert("alarm".into(), alarm_json(a, suppress));
        }
    }
}

/// The basic member that leaf `leaf` of one element of structured `node` is in: its type's
/// name and its own.
fn member_at(node: &VarDescriptor, leaf: usize) -> Option<(&str, &str)> {
    let mut before = 0;
    for m in &node.members {
        let n = plc_rules::path::leaves(m);
        if leaf < before + n {
            if !m.members.is_empty() {
                return member_at(m, (leaf - before) % element_leaves(m).max(1));
            }
            return Some((node.type_name.as_deref()?, m.name.as_str()));
        }
        before += n;
    }
    None
}

/// The `"alarm"` of one declaration: its text alone when it has nothing else.
fn alarm_json(a: &AlarmDescriptor, suppress: Option<String>) -> Value {
    let mut o = Map::new();
    o.insert("text".into(), a.text.clone().into());
    if a.active_when == Some(false) {
        o.insert("alarm_when".into(), false.into());
    }
    let limits = [
        ("high", a.high),
        ("high_high", a.high_high),
        ("low", a.low),
        ("low_low", a.low_low),
    ];
    for (key, v) in limits {
        if let Some(v) = v {
            o.insert(key.into(), json!(v));
        }
    }
    if a.deadband != 0.0 {
        o.insert("deadband".into(), json!(a.deadband));
    }
    if a.delay_ns != 0 {
        o.insert(
            "delay".into(),
            Time::from_nanos(a.delay_ns).to_string().into(),
        );
    }
    if a.severity != 500 {
        o.insert("severity".into(), a.severity.into());
    }
    if a.latched {
        o.insert("latched".into(), true.into());
    }
    if let Some(s) = suppress {
        o.insert("suppress_when".into(), s.into());
    }
    match o.len() {
        1 => a.text.clone().into(),
        _ => Value::Object(o),
    }
}
