//! How a list's messages are worded: names as JSON writes them, a variable's line where the
//! format has lines, and a JSON value as messages quote it.

use super::outcome::ListAt;
use plc_rules::decl::Wording;
use serde_json::Value;

/// The line of a variable (of the list, or a type's member) where the format has lines (CSV).
pub type Lines<'a> = &'a dyn Fn(Option<usize>, usize) -> Option<u64>;

/// How a variable list words the checker's messages: names in double quotes, as JSON writes
/// them; `lines` gives the line of a variable where the format has lines (CSV).
pub struct ListWording<'a> {
    pub lines: Lines<'a>,
}

impl Wording<ListAt> for ListWording<'_> {
    fn name(&self, name: &str) -> String {
        format!("{name:?}")
    }

    fn place(&self, at: &ListAt) -> String {
        (self.lines)(at.ty, at.var).map_or_else(String::new, |l| format!(" (line {l})"))
    }
}

/// JSON text of a value, as messages quote it.
pub(super) fn text(v: &Value) -> String {
    match v {
        Value::String(s) => format!("{s:?}"),
        other => other.to_string(),
    }
}
