//! Each of the program's alarms as three read-only metrics of its device, after the alarm
//! counts, read from the segment's alarm table: `Alarms/<path>/Active` (Boolean: raised, or
//! latched), `Alarms/<path>/Acknowledged` (Boolean: nothing waits for an operator) and
//! `Alarms/<path>/State` (String: `high-high, active unacknowledged`, `shelved until ...`),
//! the last with the alarm's text as `description` and its `severity`. A host shows them as a
//! folder per alarm under `Alarms`; no variable's path holds a `/`, so they never meet one.

use crate::metric::{DataType, bool_property, string_property};
use crate::proto::{Metric, MetricValue, PropertySet, PropertyValue, PropertyValueKind};
use plc_shm::{AlarmDescriptor, AlarmEntry};

/// Metrics per alarm.
pub const PER_ALARM: usize = 3;

/// The metrics' last steps, in alias order.
const KINDS: [&str; PER_ALARM] = ["Active", "Acknowledged", "State"];

/// The name of metric `kind` (0..3) of `alarm`.
fn name(alarm: &AlarmDescriptor, kind: usize) -> String {
    format!("Alarms/{}/{}", alarm.path, KINDS[kind])
}

/// Metric `kind`'s datatype and value for `state`.
fn value(alarm: &AlarmDescriptor, state: &AlarmEntry, kind: usize) -> (DataType, MetricValue) {
    match kind {
        0 => (DataType::Boolean, MetricValue::BooleanValue(state.active())),
        1 => (
            DataType::Boolean,
            MetricValue::BooleanValue(state.acknowledged),
        ),
        _ => (
            DataType::String,
            MetricValue::StringValue(state.state_text(alarm)),
        ),
    }
}

/// The birth's metrics of every alarm, aliases from `first_alias` on, stamped `ts`.
pub fn birth(
    alarms: &[AlarmDescriptor],
    states: &[AlarmEntry],
    first_alias: usize,
    ts: u64,
) -> Vec<Metric> {
    let mut out = Vec::with_capacity(alarms.len() * PER_ALARM);
    for (k, (a, s)) in alarms.iter().zip(states).enumerate() {
        for kind in 0..PER_ALARM {
            let (datatype, v) = value(a, s, kind);
            let mut properties = PropertySet::default();
            let mut add = |key: &str, value: PropertyValue| {
                properties.keys.push(key.into());
                properties.values.push(value);
            };
            add("readOnly", bool_property(true));
            if kind == 2 {
                add("description", string_property(&a.text));
                add(
                    "severity",
                    PropertyValue {
                        r#type: Some(DataType::UInt16.code()),
                        is_null: None,
                        value: Some(PropertyValueKind::IntValue(u32::from(a.severity))),
                    },
                );
            }
            out.push(Metric {
                name: Some(name(a, kind)),
                alias: Some((first_alias + k * PER_ALARM + kind) as u64),
                timestamp: Some(ts),
                datatype: Some(datatype.code()),
                properties: Some(properties),
                value: Some(v),
                ..Metric::default()
            });
        }
    }
    out
}

/// The metrics of the alarms whose state differs from `sent`, by alias, or by name and marked
/// historical for the store; the time of each is its alarm's last transition.
pub fn changed(
    alarms: &[AlarmDescriptor],
    states: &[AlarmEntry],
    sent: &[AlarmEntry],
    first_alias: usize,
    historical: bool,
) -> Vec<Metric> {
    let mut out = Vec::new();
    for (k, ((a, s), old)) in alarms.iter().zip(states).zip(sent).enumerate() {
        if s == old {
            continue;
        }
        for kind in 0..PER_ALARM {
            let (_, new) = value(a, s, kind);
            if value(a, old, kind).1 == new {
                continue;
            }
            let mut m = Metric {
                timestamp: Some(u64::try_from(s.since_ns / 1_000_000).unwrap_or(0)),
                value: Some(new),
                ..Metric::default()
            };
            if historical {
                m.name = Some(name(a, kind));
                m.is_historical = Some(true);
            } else {
                m.alias = Some((first_alias + k * PER_ALARM + kind) as u64);
            }
            out.push(m);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use plc_core::alarm::{AlarmState, Level};

    fn oil() -> AlarmDescriptor {
        AlarmDescriptor {
            severity: 600,
            high_high: Some(95.0),
            high: Some(80.0),
            ..AlarmDescriptor::limit("oil", "Oil temperature", 0, 0)
        }
    }

    #[test]
    fn a_birth_names_three_per_alarm_and_data_carries_only_what_changed() {
        let alarms = [oil()];
        let normal = [AlarmEntry::NORMAL];
        let born = birth(&alarms, &normal, 12, 5);
        let names: Vec<_> = born.iter().map(|m| m.name.clone().unwrap()).collect();
        assert_eq!(
            names,
            [
                "Alarms/oil/Active",
                "Alarms/oil/Acknowledged",
                "Alarms/oil/State"
            ]
        );
        assert_eq!(born[2].alias, Some(14));
        assert_eq!(
            born[2].value,
            Some(MetricValue::StringValue("normal".into()))
        );
        let raised = [AlarmEntry {
            state: AlarmState::ActiveUnacknowledged,
            level: Level::HighHigh,
            acknowledged: false,
            since_ns: 7_000_000,
            shelved_until_ns: None,
        }];
        let data = changed(&alarms, &raised, &normal, 12, false);
        assert_eq!(data.len(), 3);
        assert_eq!(data[0].value, Some(MetricValue::BooleanValue(true)));
        assert_eq!(
            data[2].value,
            Some(MetricValue::StringValue(
                "high-high, active unacknowledged".into()
            ))
        );
        assert!(data.iter().all(|m| m.timestamp == Some(7)));
        assert!(changed(&alarms, &raised, &raised, 12, false).is_empty());
        let stored = changed(&alarms, &raised, &normal, 12, true);
        assert!(
            stored
                .iter()
                .all(|m| m.is_historical == Some(true) && m.alias.is_none())
        );
    }
}
