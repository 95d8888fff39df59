//! The program's alarm counts, from its status block, as two read-only metrics of its device
//! after its variables: `Alarms/Active` and `Alarms/Unacknowledged` (UInt64). A host shows
//! them as a folder `Alarms`; no variable's path holds a `/`, so they never meet a variable.
//! Each alarm's own metrics follow them ([`alarm_states`](crate::alarm_states)).

use crate::metric::{DataType, bool_property, string_property};
use crate::proto::{Metric, MetricValue, PropertySet};

/// The metrics' names, in alias order.
pub const NAMES: [&str; 2] = ["Alarms/Active", "Alarms/Unacknowledged"];

/// What each metric says, as its `description` property.
const DESCRIPTIONS: [&str; 2] = [
    "The program's alarms now active",
    "The program's alarms waiting for an acknowledgement",
];

/// Active and unacknowledged alarms, as the status block counts them.
pub type Counts = [u64; 2];

/// The counts of `status`.
pub fn of(status: &plc_shm::Status) -> Counts {
    [status.alarms_active, status.alarms_unacknowledged]
}

/// The birth's two metrics, with aliases `first_alias` and the next, stamped `ts`.
pub fn birth(counts: Counts, first_alias: usize, ts: u64) -> impl Iterator<Item = Metric> {
    (0..NAMES.len()).map(move |i| {
        let mut properties = PropertySet::default();
        for (k, v) in [
            ("description", string_property(DESCRIPTIONS[i])),
            ("readOnly", bool_property(true)),
        ] {
            properties.keys.push(k.into());
            properties.values.push(v);
        }
        Metric {
            name: Some(NAMES[i].into()),
            alias: Some((first_alias + i) as u64),
            timestamp: Some(ts),
            datatype: Some(DataType::UInt64.code()),
            properties: Some(properties),
            value: Some(MetricValue::LongValue(counts[i])),
            ..Metric::default()
        }
    })
}

/// The metrics whose count differs from `sent`, by alias, or by name and marked historical
/// for the store (`historical`).
pub fn changed(
    counts: Counts,
    sent: Counts,
    first_alias: usize,
    ts: u64,
    historical: bool,
) -> impl Iterator<Item = Metric> {
    (0..NAMES.len())
        .filter(move |&i| counts[i] != sent[i])
        .map(move |i| {
            let mut m = Metric {
                timestamp: Some(ts),
                value: Some(MetricValue::LongValue(counts[i])),
                ..Metric::default()
            };
            if historical {
                m.name = Some(NAMES[i].into());
                m.is_historical = Some(true);
            } else {
                m.alias = Some((first_alias + i) as u64);
            }
            m
        })
}

/// Whether a command's metric names one of these (by alias past the variables, or by name):
/// they are read-only.
pub fn is_named(m: &Metric, first_alias: usize) -> bool {
    match (m.alias, &m.name) {
        (Some(a), _) => a >= first_alias as u64 && a < (first_alias + NAMES.len()) as u64,
        (None, Some(n)) => NAMES.contains(&n.as_str()),
        (None, None) => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_birth_names_both_and_data_carries_only_what_changed() {
        let born: Vec<Metric> = birth([2, 1], 10, 5).collect();
        assert_eq!(born.len(), 2);
        assert_eq!(born[1].name.as_deref(), Some("Alarms/Unacknowledged"));
        assert_eq!(born[1].alias, Some(11));
        assert_eq!(born[1].value, Some(MetricValue::LongValue(1)));
        let changed: Vec<Metric> = changed([2, 0], [2, 1], 10, 6, false).collect();
        assert_eq!(changed.len(), 1);
        assert_eq!(
            (changed[0].alias, changed[0].name.as_deref()),
            (Some(11), None)
        );
        let stored: Vec<Metric> = changed_all([3, 0], [2, 1]);
        assert!(
            stored
                .iter()
                .all(|m| m.is_historical == Some(true) && m.alias.is_none())
        );
        assert_eq!(stored.len(), 2);
    }

    fn changed_all(counts: Counts, sent: Counts) -> Vec<Metric> {
        changed(counts, sent, 10, 7, true).collect()
    }

    #[test]
    fn commands_to_them_are_recognised_by_alias_and_by_name() {
        let by_alias = |a| Metric {
            alias: Some(a),
            ..Metric::default()
        };
        assert!(is_named(&by_alias(10), 10));
        assert!(is_named(&by_alias(11), 10));
        assert!(!is_named(&by_alias(9), 10));
        assert!(!is_named(&by_alias(12), 10));
        let by_name = Metric {
            name: Some("Alarms/Active".into()),
            ..Metric::default()
        };
        assert!(is_named(&by_name, 0));
    }
}
