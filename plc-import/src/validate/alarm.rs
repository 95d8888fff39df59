//! A variable's `"alarm"`: its text alone (`"alarm": "Guard door open"`), or an object of the
//! derive's `alarm(...)` keys, read into the declaration model's `Alarm`. Whether the alarm
//! makes sense on its variable is the shared checker's rule; here are only the JSON kinds.

use super::fields::Reader;
use super::outcome::{ListAt, Problem};
use super::wording::text;
use plc_rules::decl::{Alarm, LIMIT_KEYS, Located};
use serde_json::{Map, Value};
use std::borrow::Cow;

/// The keys of an `"alarm"` object, as the derive's `alarm(...)` has them.
pub const ALARM_KEYS: &[&str] = &[
    "text",
    "severity",
    "delay",
    "latched",
    "suppress_when",
    "alarm_when",
    "low_low",
    "low",
    "high",
    "high_high",
    "deadband",
];

impl Reader<'_> {
    /// `alarm.<key>`: where a key of the alarm object is.
    fn alarm_at(&self, key: &str) -> ListAt {
        ListAt {
            ty: self.ty,
            var: self.var,
            field: Some(Cow::Owned(format!("alarm.{key}"))),
        }
    }

    fn alarm_err(&mut self, at: ListAt, message: String) {
        self.problems.push(Problem {
            at,
            message,
            kind: None,
        });
    }

    /// The variable's alarm, if it declares one (a malformed one is reported and left out).
    pub(super) fn alarm(&mut self) -> Option<Alarm<ListAt>> {
        let at = self.at("alarm");
        match self.obj.get("alarm")? {
            Value::Null => None,
            Value::String(s) => Some(Alarm::new(at.clone(), Located::new(s.clone(), at))),
            Value::Object(o) => self.alarm_object(at, o),
            other => {
                let message = format!(
                    "expected the alarm's text, such as \"Guard door open\", or an object such \
                     as {{ \"text\": \"Oil temperature\", \"high\": 80.0 }}, found {}",
                    text(other)
                );
                self.alarm_err(at, message);
                None
            }
        }
    }

    fn alarm_object(&mut self, at: ListAt, o: &Map<String, Value>) -> Option<Alarm<ListAt>> {
        let mut alarm = Alarm::new(at.clone(), Located::new(String::new(), at.clone()));
        let mut text_given = false;
        let mut ok = true;
        for (key, v) in o {
            let here = self.alarm_at(key);
            let wrong = |expected: &str| format!("expected {expected}, found {}", text(v));
            let read: Result<(), String> = match key.as_str() {
                "text" | "delay" | "suppress_when" => match v {
                    Value::String(s) => {
                        let s = Located::new(s.clone(), here.clone());
                        match key.as_str() {
                            "text" => {
                                text_given = true;
                                alarm.text = s;
                            }
                            "delay" => alarm.delay = Some(s),
                            _ => alarm.suppress_when = Some(s),
                        }
                        Ok(())
                    }
                    _ => Err(wrong("a string")),
                },
                "latched" => match v {
                    Value::Bool(true) => {
                        alarm.latched = Some(here.clone());
                        Ok(())
                    }
                    Value::Bool(false) => Ok(()),
                    _ => Err(wrong("true or false")),
                },
                "alarm_when" => match v {
                    Value::Bool(b) => {
                        alarm.when = Some(Located::new(*b, here.clone()));
                        Ok(())
                    }
                    _ => Err(wrong("true or false")),
                },
                // Beyond i64 is out of range all the same: the checker says which range.
                "severity" => match v {
                    Value::Number(n) if n.is_i64() || n.is_u64() => {
                        let s = n.as_i64().unwrap_or(i64::MAX);
                        alarm.severity = Some(Located::new(s, here.clone()));
                        Ok(())
                    }
                    _ => Err(wrong("a whole number 1..=1000, such as 700")),
                },
                "deadband" | "low_low" | "low" | "high" | "high_high" => match v.as_f64() {
                    Some(n) => {
                        let n = Some(Located::new(n, here.clone()));
                        match LIMIT_KEYS.iter().position(|k| k == key) {
                            Some(i) => alarm.limits[i] = n,
                            None => alarm.deadband = n,
                        }
                        Ok(())
                    }
                    None => Err(wrong("a number, such as 80.0 or -5")),
                },
                _ => Err(format!(
                    "unknown field of an alarm: use one of {}",
                    ALARM_KEYS.join(", ")
                )),
            };
            if let Err(message) = read {
                ok = false;
                self.alarm_err(here, message);
            }
        }
        if !text_given {
            ok = false;
            self.alarm_err(
                at,
                "an alarm needs \"text\": the message operators see when it is raised".into(),
            );
        }
        ok.then_some(alarm)
    }
}
