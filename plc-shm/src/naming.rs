//! How messages and logs name a value and show it: by its path, as tools take it back, and
//! with its text escaped so that a value cannot forge log lines.

use plc_core::Value;
use plc_core::write;

/// The path of basic value `leaf` of variable `index`: the variable or member's path, with
/// the element of an array of basic values (`speeds[2]`, `axes[1].pos`).
pub fn path_of<N: plc_rules::path::Node>(vars: &[N], index: usize, leaf: usize) -> String {
    let mut text = write::label(vars, index, leaf).to_string();
    if let Some(found) = plc_rules::path::leaf(vars, index, leaf)
        && !found.node.dims().is_empty()
    {
        let coords = plc_rules::path::coordinates(found.element, found.node.dims());
        text.push_str(&format!("[{coords}]"));
    }
    text
}

/// A value in a log line: text quoted with its control characters escaped, so a value cannot
/// forge lines or drive a terminal.
///
/// ```
/// use plc_core::{FixedString, Value};
/// let text = Value::Text(FixedString::from_str_truncate("ok\n\u{1b}[2J"));
/// assert_eq!(plc_shm::shown_in_log(&text), r#""ok\n\u{1b}[2J""#);
/// assert_eq!(plc_shm::shown_in_log(&Value::Int(-3)), "-3");
/// ```
pub fn shown_in_log(value: &Value) -> String {
    match value {
        Value::Text(t) => format!("{:?}", t.as_str()),
        other => other.to_string(),
    }
}
