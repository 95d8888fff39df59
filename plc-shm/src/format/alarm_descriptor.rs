//! The program's alarms in the segment's descriptor: what each one watches and what raises it,
//! in the order of the alarm table ([`alarm_table`](super::alarm_table)), so that tools
//! (`plc alarms`, the OPC UA server, the Sparkplug node) name and describe them without the
//! program's Rust types.

use plc_core::VarInfo;
use plc_core::alarm::{AlarmDecl, AlarmKind, Condition, SuppressWhen, alarm_paths};
use serde::{Deserialize, Serialize};

/// Alarms a tool accepts in one descriptor (a program with more is refused as damaged, not
/// read, so another process cannot make a tool allocate what it likes).
pub const MAX_ALARMS: usize = 1 << 16;

/// One declared alarm, owned.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct AlarmDescriptor {
    /// Its name: the path of the value it watches (`door`, `stations[2].door`).
    pub path: String,
    /// The message operators see.
    pub text: String,
    /// 1 (least urgent) to 1000.
    pub severity: u16,
    /// Index of the top-level variable it watches.
    pub variable: usize,
    /// The basic value within it.
    pub leaf: usize,
    /// `Some(active)` for a bool alarm: the value that makes it active.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub active_when: Option<bool>,
    /// A limit alarm's second level above.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub high_high: Option<f64>,
    /// Its first level above.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub high: Option<f64>,
    /// Its first level below.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub low: Option<f64>,
    /// Its second level below.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub low_low: Option<f64>,
    /// How far a value comes back past a limit before its level clears.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub deadband: f64,
    /// How long the condition holds before the alarm is raised, nanoseconds.
    #[serde(default, skip_serializing_if = "is_zero_ns")]
    pub delay_ns: i64,
    /// Stays until reset.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub latched: bool,
    /// The path of the bool that suppresses it by design.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub suppress_when: Option<String>,
}

fn is_zero(x: &f64) -> bool {
    *x == 0.0
}

fn is_zero_ns(x: &i64) -> bool {
    *x == 0
}

impl AlarmDescriptor {
    /// A bool alarm on leaf `leaf` of variable `variable`, active when true, severity 500,
    /// without delay, latching or suppression: for tools and tests that describe an alarm
    /// without a program's Rust type. Set the rest with struct update syntax.
    ///
    /// ```
    /// use plc_shm::AlarmDescriptor;
    /// let oil = AlarmDescriptor {
    ///     high: Some(80.0),
    ///     ..AlarmDescriptor::limit("oil", "Oil temperature", 0, 0)
    /// };
    /// assert!(oil.is_limit() && !AlarmDescriptor::discrete("door", "Door open", 1, 0).is_limit());
    /// ```
    pub fn discrete(path: &str, text: &str, variable: usize, leaf: usize) -> AlarmDescriptor {
        AlarmDescriptor {
            path: path.to_string(),
            text: text.to_string(),
            severity: 500,
            variable,
            leaf,
            active_when: Some(true),
            high_high: None,
            high: None,
            low: None,
            low_low: None,
            deadband: 0.0,
            delay_ns: 0,
            latched: false,
            suppress_when: None,
        }
    }

    /// A limit alarm on a number, with no limit yet (set them with struct update syntax).
    pub fn limit(path: &str, text: &str, variable: usize, leaf: usize) -> AlarmDescriptor {
        AlarmDescriptor {
            active_when: None,
            ..AlarmDescriptor::discrete(path, text, variable, leaf)
        }
    }

    /// Whether it is a limit alarm on a number (else a bool's).
    pub fn is_limit(&self) -> bool {
        self.active_when.is_none()
    }

    /// The alarms `decls` declares on `vars`, in their order.
    pub fn all(vars: &[VarInfo], decls: &[AlarmDecl]) -> Vec<AlarmDescriptor> {
        let paths = alarm_paths(vars, decls);
        decls
            .iter()
            .zip(paths)
            .map(|(d, path)| {
                let limits = match d.condition.kind {
                    AlarmKind::Limit(l) => l,
                    AlarmKind::Discrete { .. } => Default::default(),
                };
                AlarmDescriptor {
                    path,
                    text: d.text.to_string(),
                    severity: d.severity,
                    variable: d.index,
                    leaf: d.leaf,
                    active_when: match d.condition.kind {
                        AlarmKind::Discrete { active } => Some(active),
                        AlarmKind::Limit(_) => None,
                    },
                    high_high: limits.high_high,
                    high: limits.high,
                    low: limits.low,
                    low_low: limits.low_low,
                    deadband: limits.deadband,
                    delay_ns: d.condition.delay.as_nanos(),
                    latched: d.condition.latched,
                    suppress_when: suppress_path(vars, d.suppress_when),
                }
            })
            .collect()
    }

    /// Checks what another process wrote: a severity in range, a named variable, no limits on
    /// a bool alarm.
    pub fn check(list: &[AlarmDescriptor], variables: usize) -> Result<(), String> {
        if list.len() > MAX_ALARMS {
            return Err(format!(
                "its descriptor declares {} alarms, more than the {MAX_ALARMS} a tool reads",
                list.len()
            ));
        }
        for a in list {
            let bad = if !(1..=1000).contains(&a.severity) {
                Some(format!("severity {} outside 1..=1000", a.severity))
            } else if a.variable >= variables {
                Some(format!("variable {} of {variables}", a.variable))
            } else if a.active_when.is_some()
                && [a.high_high, a.high, a.low, a.low_low]
                    .iter()
                    .any(Option::is_some)
            {
                Some("limits on a bool alarm".to_string())
            } else {
                None
            };
            if let Some(bad) = bad {
                // The path comes from another process: quoted, its control characters escaped.
                return Err(format!(
                    "its descriptor's alarm {:?} is damaged: {bad}",
                    a.path
                ));
            }
        }
        Ok(())
    }
}

/// The path of the bool an alarm's `suppress_when` names.
fn suppress_path(vars: &[VarInfo], s: SuppressWhen) -> Option<String> {
    match s {
        SuppressWhen::Never => None,
        SuppressWhen::Path(p) => Some(p.to_string()),
        SuppressWhen::At { index, leaf } => {
            let at = AlarmDecl::new(index, leaf, "", Condition::discrete(true));
            alarm_paths(vars, &[at]).pop()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::AlarmDescriptor;
    use plc_core::GlobalMemory;

    #[derive(GlobalMemory, Debug, Clone)]
    #[plc(crate = "plc_core")]
    struct Gm {
        #[plc(alarm(text = "Door open", suppress_when = "service"))]
        door: bool,
        service: bool,
        #[plc(alarm(
            text = "Oil",
            high = 80.0,
            high_high = 95.0,
            deadband = 1.0,
            delay = "2s",
            severity = 700,
            latched
        ))]
        oil: f32,
    }

    #[test]
    fn every_declared_option_is_in_the_descriptor_and_checked_when_read() {
        let list = AlarmDescriptor::all(Gm::VARIABLES, Gm::ALARMS);
        assert_eq!(list.len(), 2);
        assert_eq!(list[0].path, "door");
        assert_eq!(list[0].active_when, Some(true));
        assert_eq!(list[0].suppress_when.as_deref(), Some("service"));
        let oil = &list[1];
        assert!(oil.is_limit() && oil.latched);
        assert_eq!(
            (oil.high, oil.high_high, oil.low),
            (Some(80.0), Some(95.0), None)
        );
        assert_eq!((oil.severity, oil.delay_ns), (700, 2_000_000_000));
        let json = serde_json::to_string(&list).unwrap();
        let back: Vec<AlarmDescriptor> = serde_json::from_str(&json).unwrap();
        assert_eq!(back, list);
        assert_eq!(AlarmDescriptor::check(&back, 3), Ok(()));
        let mut bad = back.clone();
        bad[1].severity = 0;
        assert!(
            AlarmDescriptor::check(&bad, 3)
                .unwrap_err()
                .contains("\"oil\"")
        );
        let mut bad = back;
        bad[0].high = Some(1.0);
        assert!(
            AlarmDescriptor::check(&bad, 3)
                .unwrap_err()
                .contains("limits on a bool")
        );
        assert!(
            AlarmDescriptor::check(&list, 2).is_err(),
            "variable beyond the list"
        );
    }
}
