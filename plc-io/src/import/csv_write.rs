//! Writing a JSON variable list as CSV: the header of [`COLUMNS`], one row per variable, RFC
//! 4180 quoting (CRLF line ends, fields with commas, quotes or line breaks in double quotes).
//! The cells are written so that reading them back gives the same JSON values.

use super::csv_read::COLUMNS;
use serde_json::Value;

fn cell(col: &str, v: Option<&Value>) -> String {
    match (col, v) {
        (_, None) | (_, Some(Value::Null)) => String::new(),
        // `false` is the default: an empty cell, as the JSON leaves the key out.
        (_, Some(Value::Bool(false))) if col != "initial" => String::new(),
        (_, Some(Value::String(s))) => s.clone(),
        (_, Some(other)) => other.to_string(),
    }
}

/// The CSV text of `{ "variables": { name: { ... } } }`.
pub fn to_csv(list: &Value) -> String {
    let write = || -> Result<Vec<u8>, Box<dyn std::error::Error>> {
        let mut w = csv::WriterBuilder::new()
            .terminator(csv::Terminator::CRLF)
            .from_writer(Vec::new());
        w.write_record(COLUMNS)?;
        if let Some(vars) = list["variables"].as_object() {
            for (name, var) in vars {
                w.write_record(COLUMNS.iter().map(|&col| match col {
                    "name" => name.clone(),
                    _ => cell(col, var.get(col)),
                }))?;
            }
        }
        Ok(w.into_inner().map_err(|e| e.to_string())?)
    };
    // Writing into memory cannot fail.
    write()
        .map(|b| String::from_utf8_lossy(&b).into_owned())
        .unwrap_or_default()
}
