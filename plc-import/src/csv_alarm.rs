//! A variable's alarm in CSV: a column per key of the JSON `"alarm"` object, beside the
//! [`COLUMNS`](super::COLUMNS) (a sheet without alarms needs none of them), gathered into that
//! object so that CSV goes through the JSON checks; and the way back, for the messages, from
//! the object's keys to the columns.

use serde_json::{Map, Value};

/// The alarm columns: `alarm` is the text, the others the options (docs/alarms.md).
pub const ALARM_COLUMNS: [&str; 11] = [
    "alarm",
    "alarm_severity",
    "alarm_delay",
    "alarm_latched",
    "alarm_suppress_when",
    "alarm_when",
    "alarm_low_low",
    "alarm_low",
    "alarm_high",
    "alarm_high_high",
    "alarm_deadband",
];

/// The key of the `"alarm"` object a column gives (`alarm_high` is `high`, `alarm` the text).
pub fn key_of(column: &str) -> Option<&'static str> {
    Some(match column {
        "alarm" => "text",
        "alarm_when" => "alarm_when",
        _ => {
            let c = ALARM_COLUMNS.iter().find(|c| **c == column)?;
            c.strip_prefix("alarm_")?
        }
    })
}

/// The column a field of a message names: `alarm.high` is column `alarm_high`; other fields
/// are their own column.
pub fn column_of(field: &str) -> String {
    match field.strip_prefix("alarm.") {
        Some("text") => "alarm".into(),
        Some("alarm_when") => "alarm_when".into(),
        Some(key) => format!("alarm_{key}"),
        None => field.to_string(),
    }
}

/// Moves a row's alarm cells into one `"alarm"` field: the text alone as a string, as a JSON
/// list writes it, else an object.
pub fn gather(fields: &mut Map<String, Value>) {
    let mut alarm = Map::new();
    for column in ALARM_COLUMNS {
        if let (Some(v), Some(key)) = (fields.remove(column), key_of(column)) {
            alarm.insert(key.into(), v);
        }
    }
    let value = match alarm.len() {
        0 => return,
        1 if alarm.contains_key("text") => alarm.remove("text").unwrap_or(Value::Null),
        _ => Value::Object(alarm),
    };
    fields.insert("alarm".into(), value);
}
