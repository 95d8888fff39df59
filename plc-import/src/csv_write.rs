//! Writing a JSON variable list as CSV: the header of [`COLUMNS`] (then the alarm columns, if
//! a variable has an alarm), one row per variable, RFC
//! 4180 quoting (CRLF line ends, fields with commas, quotes or line breaks in double quotes).
//! The cells are written so that reading them back gives the same JSON values.

use super::csv_alarm::{ALARM_COLUMNS, key_of};
use super::csv_read::{COLUMNS, STRUCT};
use serde_json::Value;

fn cell(col: &str, v: Option<&Value>) -> String {
    match (col, v) {
        (_, None) | (_, Some(Value::Null)) => String::new(),
        // `false` is the default: an empty cell, as the JSON leaves the key out.
        (_, Some(Value::Bool(false))) if !matches!(col, "initial" | "alarm_when") => String::new(),
        (_, Some(Value::String(s))) => s.clone(),
        (_, Some(other)) => other.to_string(),
    }
}

/// The CSV text of `{ "types": { .. }, "variables": { name: { ... } } }`: each type as its
/// `STRUCT` row and its members' `<type>.<member>` rows, then the variables.
pub fn to_csv(list: &Value) -> String {
    let write = || -> Result<Vec<u8>, Box<dyn std::error::Error>> {
        let mut w = csv::WriterBuilder::new()
            .terminator(csv::Terminator::CRLF)
            .from_writer(Vec::new());
        // The alarm columns only where a variable has an alarm: a list without keeps the
        // columns it always had.
        let members = list["types"]
            .as_object()
            .into_iter()
            .flatten()
            .filter_map(|(_, def)| def["variables"].as_object())
            .flatten();
        let with_alarms = list["variables"]
            .as_object()
            .into_iter()
            .flatten()
            .chain(members)
            .any(|(_, v)| v.get("alarm").is_some());
        let alarm_columns: &[&str] = if with_alarms { &ALARM_COLUMNS } else { &[] };
        let columns: Vec<&str> = COLUMNS.iter().chain(alarm_columns).copied().collect();
        w.write_record(&columns)?;
        let mut row = |name: &str, var: &Value| {
            w.write_record(columns.iter().map(|&col| match (col, key_of(col)) {
                ("name", _) => name.to_string(),
                (_, Some(key)) => match var.get("alarm") {
                    Some(Value::String(text)) if key == "text" => text.clone(),
                    Some(alarm) => cell(col, alarm.get(key)),
                    None => String::new(),
                },
                _ => cell(col, var.get(col)),
            }))
        };
        for (ty, def) in list["types"].as_object().into_iter().flatten() {
            let mut head = serde_json::Map::new();
            head.insert("type".into(), STRUCT.into());
            if let Some(d) = def.get("description") {
                head.insert("description".into(), d.clone());
            }
            row(ty, &Value::Object(head))?;
            for (member, var) in def["variables"].as_object().into_iter().flatten() {
                row(&format!("{ty}.{member}"), var)?;
            }
        }
        for (name, var) in list["variables"].as_object().into_iter().flatten() {
            row(name, var)?;
        }
        Ok(w.into_inner().map_err(|e| e.to_string())?)
    };
    // Writing into memory cannot fail.
    write()
        .map(|b| String::from_utf8_lossy(&b).into_owned())
        .unwrap_or_default()
}
