//! Alarms declared with a variable ([`Alarm`]) and their rules: which types can carry one,
//! limits in order, a deadband, a delay, a severity and a text that make sense, and a
//! `suppress_when` that names a bool. The alarm's states and how it is evaluated are IEC
//! 62682's (alarm management); the severity range is OPC UA's (IEC 62541-9, 1..=1000).

use super::issue::{Issue, IssueKind};
use super::keys::{FnvMap, NoCase};
use super::{Decl, DeclType, Located, Var};
use crate::{IecType, Time, TimeError, TypeFamily};
use std::string::{String, ToString};
use std::vec::Vec;

/// The severity of an alarm that does not give one: the middle of OPC UA's 1..=1000.
pub const DEFAULT_SEVERITY: i64 = 500;

/// The limit keys of a limit alarm, from the lowest level to the highest.
pub const LIMIT_KEYS: [&str; 4] = ["low_low", "low", "high", "high_high"];

/// `alarm = "..."` or `alarm(...)` on a variable, as written.
#[derive(Clone, Debug, PartialEq)]
pub struct Alarm<L> {
    /// Where `alarm` is written: the key.
    pub at: L,
    /// The message operators see.
    pub text: Located<String, L>,
    /// `alarm_when = false`: a bool alarm active when the value is false.
    pub when: Option<Located<bool, L>>,
    /// `severity = 700`.
    pub severity: Option<Located<i64, L>>,
    /// `delay = "2s"`: how long the condition must hold before the alarm is raised, as written.
    pub delay: Option<Located<String, L>>,
    /// `latched`: the alarm stays until reset, where it was written.
    pub latched: Option<L>,
    /// `suppress_when = "path"`: a bool that takes the alarm out of service while true.
    pub suppress_when: Option<Located<String, L>>,
    /// `low_low`, `low`, `high`, `high_high`, in the order of [`LIMIT_KEYS`].
    pub limits: [Option<Located<f64, L>>; 4],
    /// `deadband = 1.0`: how far a value must return past a limit to leave its level.
    pub deadband: Option<Located<f64, L>>,
}

impl<L> Alarm<L> {
    /// An alarm with only its text, active when a bool is true.
    pub fn new(at: L, text: Located<String, L>) -> Alarm<L> {
        Alarm {
            at,
            text,
            when: None,
            severity: None,
            delay: None,
            latched: None,
            suppress_when: None,
            limits: [None, None, None, None],
            deadband: None,
        }
    }

    /// Whether any limit is given: a limit alarm rather than one on a bool.
    pub fn has_limits(&self) -> bool {
        self.limits.iter().any(Option::is_some)
    }
}

/// Why a `delay` is not one.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DelayError {
    /// Not a duration.
    Time(TimeError),
    /// A negative duration: an alarm cannot be raised before its condition.
    Negative,
}

/// What a delay looks like: the duration grammar's own advice names the `T#` prefix, which a
/// delay may leave out.
const FORM: &str = "a delay is a number and a unit (d, h, m, s, ms, us, ns), such as \"2s\" or \
                    \"1m_30s\" (an IEC 61131-3 duration; `T#` in front is optional)";

impl core::fmt::Display for DelayError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            // The prefix is optional here, so the literal's own advice about it would mislead.
            DelayError::Time(TimeError::NoPrefix | TimeError::Empty) => f.write_str(FORM),
            DelayError::Time(TimeError::Unexpected { at }) => {
                write!(f, "unexpected character at byte {at}: {FORM}")
            }
            DelayError::Time(TimeError::MissingUnit { at }) => {
                write!(f, "the number ending at byte {at} has no unit: {FORM}")
            }
            DelayError::Time(e) => core::fmt::Display::fmt(e, f),
            DelayError::Negative => f.write_str(
                "a delay cannot be negative: it is how long the condition must hold before the \
                 alarm is raised",
            ),
        }
    }
}

/// A delay as a duration: `"2s"` or the IEC literal `"T#2s"` (a prefix is optional, since a
/// delay is never anything but a duration). Negative delays are refused.
///
/// ```
/// use plc_rules::decl::parse_delay;
/// use plc_rules::Time;
/// assert_eq!(parse_delay("1.5s"), Ok(Time::from_millis(1500)));
/// assert_eq!(parse_delay("T#2m"), Ok(Time::from_secs(120)));
/// assert!(parse_delay("-1s").is_err());
/// assert!(parse_delay("two seconds").is_err());
/// ```
pub fn parse_delay(text: &str) -> Result<Time, DelayError> {
    let t = text.trim();
    let parsed = if t.contains('#') {
        Time::parse(t)
    } else {
        Time::parse(&std::format!("T#{t}"))
    };
    // Positions in the text as written, not in the literal with the `T#` added.
    let shift = if t.contains('#') { 0 } else { 2 };
    match parsed {
        Ok(time) if time.is_negative() => Err(DelayError::Negative),
        Ok(time) => Ok(time),
        Err(TimeError::Unexpected { at }) => Err(DelayError::Time(TimeError::Unexpected {
            at: at.saturating_sub(shift),
        })),
        Err(TimeError::MissingUnit { at }) => Err(DelayError::Time(TimeError::MissingUnit {
            at: at.saturating_sub(shift),
        })),
        Err(e) => Err(DelayError::Time(e)),
    }
}

/// Applies the alarm rules to every variable of `decl` that declares one.
pub(super) fn alarms<L: Clone>(decl: &Decl<L>, issues: &mut Vec<Issue<L>>) {
    if decl.vars.iter().all(|v| v.alarm.is_none()) {
        return;
    }
    let by_name: FnvMap<NoCase, usize> = decl
        .vars
        .iter()
        .enumerate()
        .map(|(i, v)| (NoCase(&v.name.value), i))
        .collect();
    for v in &decl.vars {
        if let Some(a) = &v.alarm {
            own(v, a, issues);
            if let Some(s) = &a.suppress_when {
                suppress_target(decl, &by_name, s, issues);
            }
        }
    }
}

/// The rules of one alarm on its own.
fn own<L: Clone>(v: &Var<L>, a: &Alarm<L>, issues: &mut Vec<Issue<L>>) {
    let mut push = |kind, at: &L| issues.push(Issue::new(kind, at.clone()));
    if a.text.value.trim().is_empty() {
        push(IssueKind::AlarmEmptyText, &a.text.at);
    }
    if let Some(s) = &a.severity
        && !(1..=1000).contains(&s.value)
    {
        push(IssueKind::AlarmSeverity { value: s.value }, &s.at);
    }
    if let Some(d) = &a.delay
        && let Err(error) = parse_delay(&d.value)
    {
        let text = d.value.clone();
        push(IssueKind::AlarmBadDelay { text, error }, &d.at);
    }
    if let Some(d) = &a.deadband
        && (d.value < 0.0 || d.value.is_nan())
    {
        push(IssueKind::AlarmNegativeDeadband { value: d.value }, &d.at);
    }
    let DeclType::Known(k) = &v.ty.value else {
        return;
    };
    let iec = v.iec_type.as_ref().map_or(k.iec, |t| t.value);
    let family = k.iec.family();
    if matches!(family, TypeFamily::String | TypeFamily::Time) {
        let ty = k.element_name();
        push(IssueKind::AlarmOnType { ty, iec }, &a.at);
        return;
    }
    if family == TypeFamily::Bool {
        let given = LIMIT_KEYS
            .iter()
            .zip(&a.limits)
            .filter_map(|(k, l)| l.as_ref().map(|l| (*k, &l.at)))
            .chain(a.deadband.as_ref().map(|d| ("deadband", &d.at)));
        for (key, at) in given {
            push(IssueKind::AlarmLimitOnBool { key }, at);
        }
        return;
    }
    if let Some(w) = &a.when {
        push(IssueKind::AlarmWhenOnNumber { iec }, &w.at);
    }
    if !a.has_limits() {
        push(IssueKind::AlarmWithoutLimits { iec }, &a.at);
    }
    limit_order(a, issues);
}

/// Limits from the lowest level up: low_low <= low < high <= high_high, each against the
/// nearest one below it that is given.
fn limit_order<L: Clone>(a: &Alarm<L>, issues: &mut Vec<Issue<L>>) {
    let mut below: Option<(usize, f64)> = None;
    for (i, l) in a.limits.iter().enumerate() {
        let Some(l) = l else { continue };
        if let Some((j, lower)) = below {
            // A value on a low and a high limit at once would be in two levels.
            let strict = j <= 1 && i >= 2;
            if l.value < lower || (strict && l.value <= lower) {
                issues.push(Issue::new(
                    IssueKind::AlarmLimitOrder {
                        key: LIMIT_KEYS[i],
                        value: l.value,
                        below: LIMIT_KEYS[j],
                        below_value: lower,
                    },
                    l.at.clone(),
                ));
                continue;
            }
        }
        below = Some((i, l.value));
    }
}

/// `suppress_when` names a bool: a top-level variable or an element of a bool array (in a
/// structure, a member of the same structure) by its name. A path into a structure
/// (`stations[2].out_of_service`) is checked as far as its first name; the rest is resolved
/// when the program starts.
fn suppress_target<L: Clone>(
    decl: &Decl<L>,
    by_name: &FnvMap<NoCase, usize>,
    s: &Located<String, L>,
    issues: &mut Vec<Issue<L>>,
) {
    let path = s.value.trim();
    let unknown = |why| {
        Issue::new(
            IssueKind::AlarmSuppressUnknown {
                path: path.to_string(),
                structure: decl.structure,
                why,
            },
            s.at.clone(),
        )
    };
    let mut segments = crate::path::segments(path);
    let first = match segments.next() {
        Some(Ok(first)) => first,
        Some(Err(e)) => return issues.push(unknown(Some(e))),
        None => return issues.push(unknown(None)),
    };
    let Some(&t) = by_name.get(&NoCase(first.name)) else {
        return issues.push(unknown(None));
    };
    let deeper = segments.next().is_some();
    if decl.structure && (deeper || first.index.is_some()) {
        // Each instance's alarm is suppressed by its own member: a sibling, by name.
        return issues.push(unknown(None));
    }
    let DeclType::Known(k) = &decl.vars[t].ty.value else {
        return;
    };
    let not_bool = |past: Option<&str>| {
        Issue::new(
            IssueKind::AlarmSuppressNotBool {
                path: path.to_string(),
                ty: k.rust_type(),
                past: past.map(str::to_string),
            },
            s.at.clone(),
        )
    };
    // A basic variable: the whole path can be followed here.
    if deeper {
        return issues.push(not_bool(Some(first.name)));
    }
    if k.iec != IecType::Bool {
        return issues.push(not_bool(None));
    }
    match first.index {
        None if !k.is_scalar() => issues.push(not_bool(None)),
        None => {}
        Some(index) => {
            let dims: Vec<usize> = k.dims.iter().map(|&d| d as usize).collect();
            if let Err(e) = index.flat(&dims) {
                issues.push(unknown(Some(e)));
            }
        }
    }
}
