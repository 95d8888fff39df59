//! A compiled type's alarms (`GlobalMemory::ALARMS`) in its exported list: each alarm on the
//! variable, or on the structure type's member, that declares it, as `"alarm"` in the form
//! the importer reads. A running program's descriptor does not carry its alarms, so only the
//! export of a compiled type has them.

use plc_core::alarm::{AlarmDecl, AlarmKind, Condition, SuppressWhen, alarm_paths};
use plc_core::{Time, VarInfo};
use serde_json::{Map, Value, json};

/// Adds each alarm of `alarms` to `list` (`{ "types": .., "variables": .. }`, as
/// `descriptor_to_json` gives it for `vars`). An array of bools, or a structure type used
/// many times, declares its alarm once: the first instance's is written.
pub fn add(list: &mut Value, vars: &[VarInfo], alarms: &[AlarmDecl]) {
    for d in alarms {
        let Some(top) = vars.get(d.index) else {
            continue;
        };
        let (slot, suppress) = if top.is_structured() {
            let per = (top.leaves() / top.elements().max(1)).max(1);
            let Some((ty, member)) = member_at(top, d.leaf % per) else {
                continue;
            };
            // A structure's alarm is suppressed by a member of the same structure.
            let suppress = match d.suppress_when {
                SuppressWhen::At { leaf, .. } => member_at(top, leaf % per).map(|m| m.1.into()),
                SuppressWhen::Path(p) => Some(p.to_string()),
                SuppressWhen::Never => None,
            };
            (&mut list["types"][ty]["variables"][member], suppress)
        } else {
            let suppress = match d.suppress_when {
                SuppressWhen::At { index, leaf } => {
                    let at = AlarmDecl::new(index, leaf, "", Condition::discrete(true));
                    alarm_paths(vars, &[at]).pop()
                }
                SuppressWhen::Path(p) => Some(p.to_string()),
                SuppressWhen::Never => None,
            };
            (&mut list["variables"][top.name], suppress)
        };
        if let Value::Object(var) = slot
            && !var.contains_key("alarm")
        {
            var.insert("alarm".into(), alarm_json(d, suppress));
        }
    }
}

/// The basic member that leaf `leaf` of one element of structured `node` is in: its type's
/// name and its own.
fn member_at(node: &VarInfo, leaf: usize) -> Option<(&'static str, &'static str)> {
    let mut before = 0;
    for m in node.members() {
        let n = m.leaves();
        if leaf < before + n {
            if m.is_structured() {
                let per = (n / m.elements().max(1)).max(1);
                return member_at(m, (leaf - before) % per);
            }
            return Some((node.type_name(), m.name));
        }
        before += n;
    }
    None
}

/// The `"alarm"` of one declaration: its text alone when it has nothing else.
fn alarm_json(d: &AlarmDecl, suppress: Option<String>) -> Value {
    let mut o = Map::new();
    o.insert("text".into(), d.text.into());
    let c = d.condition;
    match c.kind {
        AlarmKind::Discrete { active: false } => {
            o.insert("alarm_when".into(), false.into());
        }
        AlarmKind::Discrete { active: true } => {}
        AlarmKind::Limit(l) => {
            let limits = [
                ("high", l.high),
                ("high_high", l.high_high),
                ("low", l.low),
                ("low_low", l.low_low),
            ];
            for (key, v) in limits {
                if let Some(v) = v {
                    o.insert(key.into(), json!(v));
                }
            }
            if l.deadband != 0.0 {
                o.insert("deadband".into(), json!(l.deadband));
            }
        }
    }
    if c.delay != Time::from_nanos(0) {
        o.insert("delay".into(), c.delay.to_string().into());
    }
    if d.severity != 500 {
        o.insert("severity".into(), d.severity.into());
    }
    if c.latched {
        o.insert("latched".into(), true.into());
    }
    if let Some(s) = suppress {
        o.insert("suppress_when".into(), s.into());
    }
    match o.len() {
        1 => d.text.into(),
        _ => Value::Object(o),
    }
}
