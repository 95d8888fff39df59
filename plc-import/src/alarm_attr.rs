//! A checked `"alarm"` written back as the derive's attribute: `alarm = "text"` when it has
//! nothing but its text, else `alarm(text = "...", ...)` with each key it gives, in the order
//! docs/alarms.md lists them.

use plc_rules::decl::{Alarm, LIMIT_KEYS};

/// The `#[plc(...)]` key of an alarm.
pub fn attribute<L>(a: &Alarm<L>) -> String {
    let mut keys = vec![format!("text = {:?}", a.text.value)];
    if let Some(w) = &a.when {
        keys.push(format!("alarm_when = {}", w.value));
    }
    // As docs/alarms.md writes them: the high limits, then the low ones.
    for i in [2, 3, 1, 0] {
        if let Some(l) = &a.limits[i] {
            keys.push(format!("{} = {:?}", LIMIT_KEYS[i], l.value));
        }
    }
    if let Some(d) = &a.deadband {
        keys.push(format!("deadband = {:?}", d.value));
    }
    if let Some(d) = &a.delay {
        keys.push(format!("delay = {:?}", d.value));
    }
    if let Some(s) = &a.severity {
        keys.push(format!("severity = {}", s.value));
    }
    if a.latched.is_some() {
        keys.push("latched".into());
    }
    if let Some(s) = &a.suppress_when {
        keys.push(format!("suppress_when = {:?}", s.value));
    }
    match keys.len() {
        1 => format!("alarm = {:?}", a.text.value),
        _ => format!("alarm({})", keys.join(", ")),
    }
}
