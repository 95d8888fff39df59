//! Reading a CSV variable list: one row per variable under a header line naming the columns,
//! RFC 4180 quoting. Each cell becomes the JSON value the same field has in a project file, so
//! CSV goes through exactly the checks JSON does; this file only knows about rows and cells.
//!
//! Structure types take rows of their own (docs/variable-lists.md, "CSV"): a row of type
//! `STRUCT` declares a type (`Axis,STRUCT`, its description in the description column), and
//! rows named `<type>.<member>` declare its members (`Axis.pos,f64`), in any order; a variable
//! of the type is a row like any other (`axes,Axis` with `dims` 3). A member row names its
//! type rather than a variable's path, so one type used by many variables is declared once,
//! and a sheet reads back as the JSON list's `types` section reads.

use super::csv_alarm::{self, ALARM_COLUMNS};
use super::parse::{Parsed, TypeDef};
use serde_json::Value;
use std::collections::HashMap;

/// The `type` cell of a row declaring a structure type (IEC 61131-3 declares one as
/// `TYPE Axis : STRUCT ... END_STRUCT END_TYPE`).
pub const STRUCT: &str = "STRUCT";

/// The CSV columns: first those of the tooling of the framework the JSON format comes from (`name` .. `initial`), then
/// the rest of a variable's fields, so that nothing of a declaration is lost.
pub const COLUMNS: [&str; 17] = [
    "name",
    "type",
    "direction",
    "link",
    "description",
    "initial",
    "source",
    "bit",
    "max_length",
    "nonvolatile",
    "read_only",
    "at",
    "dims",
    "ux",
    "quantity",
    "unit",
    "deadband",
];

/// A CSV file read into the JSON front end's form, with the line of each row.
pub struct Table {
    /// The variables, as a JSON file would give them.
    pub parsed: Parsed,
    /// The line of each variable's row (same order as `parsed.variables`).
    pub lines: Vec<u64>,
    /// The line of each row of `parsed.duplicates`.
    pub duplicate_lines: Vec<u64>,
    /// Problems of single rows (an empty name, too many cells); the other rows are still read.
    pub row_errors: Vec<String>,
    /// The line of each type's `STRUCT` row (same order as `parsed.types`).
    pub type_lines: Vec<Option<u64>>,
    /// The lines of each type's member rows, and of its members' second uses.
    pub member_lines: Vec<(Vec<u64>, Vec<u64>)>,
}

impl Table {
    /// The line of a variable (`ty` `None`) or of a type's member: the variables first, then
    /// the second uses of a name, as the declaration holds them.
    pub fn line_of(&self, ty: Option<usize>, var: usize) -> Option<u64> {
        let (parsed, lines, duplicate_lines) = match ty {
            None => (&self.parsed, &self.lines, &self.duplicate_lines),
            Some(t) => {
                let (l, d) = self.member_lines.get(t)?;
                (&self.parsed.types.get(t)?.members, l, d)
            }
        };
        match var.checked_sub(parsed.variables.len()) {
            None => lines.get(var).copied(),
            Some(k) => duplicate_lines.get(k).copied(),
        }
    }

    /// The type a member row belongs to (by name, in any case), created at its first mention.
    fn type_of(&mut self, name: &str, index: &mut HashMap<String, usize>) -> usize {
        *index
            .entry(name.to_ascii_lowercase())
            .or_insert_with(|| self.new_type(name))
    }

    /// A type with no members and no declaring row yet; its index.
    fn new_type(&mut self, name: &str) -> usize {
        self.parsed.types.push(TypeDef {
            name: name.to_string(),
            fields: serde_json::Map::new(),
            members: Parsed::new(),
        });
        self.type_lines.push(None);
        self.member_lines.push((Vec::new(), Vec::new()));
        self.parsed.types.len() - 1
    }
}

const HEADER_HINT: &str =
    "the first line names the columns, such as name,type,direction,link,description,initial";

/// The csv crate reads any text, forgiving bad quoting (an unclosed quote swallows the rest of
/// the file; `"a"b` reads as `ab`). A variable list must not lose rows that way, so quoting is
/// checked against RFC 4180 first, with the line of the mistake.
fn check_quoting(text: &str) -> Result<(), String> {
    let bytes = text.as_bytes();
    let (mut line, mut open_line) = (1u64, 0u64);
    let (mut in_quotes, mut field_start, mut after_close) = (false, true, false);
    let mut i = 0;
    while i < bytes.len() {
        let c = bytes[i];
        if in_quotes {
            match c {
                b'"' if bytes.get(i + 1) == Some(&b'"') => i += 1,
                b'"' => (in_quotes, after_close) = (false, true),
                b'\n' => line += 1,
                _ => {}
            }
        } else {
            match c {
                b',' | b'\r' | b'\n' => {
                    line += u64::from(c == b'\n');
                    (field_start, after_close) = (true, false);
                }
                _ if after_close => {
                    return Err(format!(
                        "line {line}: text after the closing quote of a field: a quoted field ends at its closing quote; double a quote inside it (\"say \"\"hi\"\"\")"
                    ));
                }
                b'"' if field_start => (in_quotes, open_line, field_start) = (true, line, false),
                b'"' => {
                    return Err(format!(
                        "line {line}: a double quote inside an unquoted field: put the field in double quotes and double the quote (\"5\"\" pipe\")"
                    ));
                }
                _ => field_start = false,
            }
        }
        i += 1;
    }
    if in_quotes {
        return Err(format!(
            "line {open_line}: a quoted field is not closed: add the closing double quote"
        ));
    }
    Ok(())
}

/// `true`/`false` in any case (spreadsheets write `TRUE`); anything else is left as text, which
/// the checks then refuse with "expected true or false".
fn flag(cell: &str) -> Value {
    match cell.to_ascii_lowercase().as_str() {
        "true" => Value::Bool(true),
        "false" => Value::Bool(false),
        _ => Value::String(cell.to_string()),
    }
}

/// A number if the cell is one, else the text (refused by the checks with the text quoted).
fn number(cell: &str) -> Value {
    match serde_json::from_str::<Value>(cell) {
        Ok(v @ Value::Number(_)) => v,
        _ => Value::String(cell.to_string()),
    }
}

/// The value of an `initial` cell: text for a string variable (plain, or as JSON text in
/// double quotes, as the framework's own export writes it: `"abc"` is `abc`), else a bool or a
/// number as JSON writes it.
fn initial(cell: &str, ty: &str) -> Value {
    if ty.trim().eq_ignore_ascii_case("string") {
        let quoted = cell.trim();
        if quoted.len() >= 2
            && quoted.starts_with('"')
            && quoted.ends_with('"')
            && let Ok(text @ Value::String(_)) = serde_json::from_str::<Value>(quoted)
        {
            return text;
        }
        return Value::String(cell.to_string());
    }
    match flag(cell.trim()) {
        Value::String(_) => number(cell.trim()),
        b => b,
    }
}

/// `3`, `3,4`, `[3, 4]`: the list of dimensions.
fn dims(cell: &str) -> Value {
    let inner = cell
        .strip_prefix('[')
        .and_then(|c| c.strip_suffix(']'))
        .unwrap_or(cell)
        .trim();
    if inner.is_empty() {
        return Value::Array(vec![]);
    }
    Value::Array(inner.split(',').map(|d| number(d.trim())).collect())
}

/// The cell of column `col` as the JSON value of that field; `None` for an empty cell.
fn cell_value(col: &str, cell: &str, ty: &str) -> Option<Value> {
    // Text fields keep their spaces; names, numbers and flags do not need them.
    let kept = matches!(col, "description" | "initial");
    let c = if kept { cell } else { cell.trim() };
    if c.is_empty() {
        return None;
    }
    Some(match col {
        "initial" => initial(c, ty),
        "bit" | "max_length" | "deadband" => number(c),
        "nonvolatile" | "read_only" | "ux" | "alarm_latched" | "alarm_when" => flag(c),
        "alarm_severity" | "alarm_low_low" | "alarm_low" | "alarm_high" | "alarm_high_high"
        | "alarm_deadband" => number(c),
        "dims" => dims(c),
        _ => Value::String(c.to_string()),
    })
}

/// The header: the column of each field; errors for unknown, repeated and missing columns.
fn header(record: &csv::StringRecord) -> Result<Vec<&'static str>, Vec<String>> {
    let mut cols: Vec<&'static str> = Vec::new();
    let mut errors = Vec::new();
    for (i, h) in record.iter().enumerate() {
        let h = h.trim();
        let known = COLUMNS.iter().chain(&ALARM_COLUMNS);
        match known.clone().find(|c| c.eq_ignore_ascii_case(h)) {
            Some(c) if cols.contains(c) => {
                errors.push(format!("line 1: column {c:?} is named twice"));
            }
            Some(c) => cols.push(c),
            None => errors.push(format!(
                "line 1, column {}: unknown column {h:?}: use {} ({HEADER_HINT})",
                i + 1,
                known.copied().collect::<Vec<_>>().join(", ")
            )),
        }
    }
    for needed in ["name", "type"] {
        if !cols.contains(&needed) && errors.is_empty() {
            errors.push(format!("line 1: no {needed:?} column: {HEADER_HINT}"));
        }
    }
    if errors.is_empty() {
        Ok(cols)
    } else {
        Err(errors)
    }
}

/// The line a record starts on. The csv crate's own record line lags by one after a CRLF (the
/// LF is taken as the start of the next record), so lines are counted here from the record's
/// byte offset, skipping the line break it may begin with; incrementally, to stay linear.
struct LineCounter<'a> {
    text: &'a [u8],
    offset: usize,
    line: u64,
}

impl LineCounter<'_> {
    fn at(&mut self, byte: u64) -> u64 {
        let mut start = usize::try_from(byte)
            .unwrap_or(usize::MAX)
            .min(self.text.len());
        while start < self.text.len() && matches!(self.text[start], b'\r' | b'\n') {
            start += 1;
        }
        if start >= self.offset {
            let breaks = self.text[self.offset..start]
                .iter()
                .filter(|&&b| b == b'\n');
            self.line += breaks.count() as u64;
            self.offset = start;
        }
        self.line
    }
}

/// Reads a CSV variable list. A quoting or header error ends the reading (rows cannot be told
/// apart reliably then); errors of single rows are collected in [`Table::row_errors`].
pub fn parse(text: &str) -> Result<Table, Vec<String>> {
    // Spreadsheets put a byte order mark before the header.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    check_quoting(text).map_err(|e| vec![e])?;
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .flexible(true)
        .from_reader(text.as_bytes());
    let mut records = reader.records();
    let head = match records.next() {
        None => return Err(vec![format!("the file is empty: {HEADER_HINT}")]),
        Some(r) => r.map_err(|e| vec![format!("CSV error: {e}")])?,
    };
    let cols = header(&head)?;
    let mut table = Table {
        parsed: Parsed::new(),
        lines: Vec::new(),
        duplicate_lines: Vec::new(),
        row_errors: Vec::new(),
        type_lines: Vec::new(),
        member_lines: Vec::new(),
    };
    let mut type_index: HashMap<String, usize> = HashMap::new();
    let type_col = cols.iter().position(|c| *c == "type");
    let mut lines = LineCounter {
        text: text.as_bytes(),
        offset: 0,
        line: 1,
    };
    for record in records {
        let record = record.map_err(|e| vec![format!("CSV error: {e}")])?;
        let line = lines.at(record.position().map_or(0, csv::Position::byte));
        // Spreadsheets end a sheet with rows of empty cells.
        if record.iter().all(|c| c.trim().is_empty()) {
            continue;
        }
        if record.len() > cols.len() {
            table.row_errors.push(format!(
                "line {line}: {} cells but the header names {} columns: put a cell that holds a comma in double quotes",
                record.len(),
                cols.len()
            ));
            continue;
        }
        let ty = type_col.and_then(|t| record.get(t)).unwrap_or("");
        let mut name = None;
        let mut fields = serde_json::Map::new();
        for (col, cell) in cols.iter().zip(record.iter()) {
            if *col == "name" {
                name = Some(cell.trim().to_string()).filter(|n| !n.is_empty());
            } else if let Some(v) = cell_value(col, cell, ty) {
                fields.insert((*col).to_string(), v);
            }
        }
        csv_alarm::gather(&mut fields);
        let Some(name) = name else {
            table.row_errors.push(format!(
                "line {line}, column name: empty: every row needs the variable's name"
            ));
            continue;
        };
        if ty.trim().eq_ignore_ascii_case(STRUCT) {
            struct_row(&mut table, &mut type_index, name, fields, line);
        } else if let Some((type_name, member)) = name.split_once('.') {
            if type_name.is_empty() || member.is_empty() || member.contains('.') {
                table.row_errors.push(format!(
                    "line {line}, column name: {name:?} is not a member: a member row is named \
                     <type>.<member> (Axis.pos), with one dot"
                ));
                continue;
            }
            let t = table.type_of(type_name, &mut type_index);
            let (lines, duplicates) = &mut table.member_lines[t];
            let members = &mut table.parsed.types[t].members;
            if members.push(member.to_string(), Value::Object(fields)) {
                lines.push(line);
            } else {
                duplicates.push(line);
            }
        } else if table.parsed.push(name, Value::Object(fields)) {
            table.lines.push(line);
        } else {
            table.duplicate_lines.push(line);
        }
    }
    for (t, def) in table.parsed.types.iter().enumerate() {
        if table.type_lines[t].is_none() {
            let line = table.member_lines[t].0.first().copied().unwrap_or(0);
            table.row_errors.push(format!(
                "line {line}, column name: {:?} is a member of the type {:?}, which no row \
                 declares: add a row {},{STRUCT}",
                format!(
                    "{}.{}",
                    def.name,
                    def.members.variables.first().map_or("", |m| m.0.as_str())
                ),
                def.name,
                def.name
            ));
        }
    }
    Ok(table)
}

/// A `STRUCT` row: the type's description; its other cells are refused (a type has only
/// members, given by their own rows).
fn struct_row(
    table: &mut Table,
    index: &mut HashMap<String, usize>,
    name: String,
    mut fields: serde_json::Map<String, Value>,
    line: u64,
) {
    fields.remove("type");
    for col in fields.keys().filter(|c| *c != "description") {
        table.row_errors.push(format!(
            "line {line}, type {name}, column {col}: a {STRUCT} row declares a type by its \
             name and description; give the members' {col} on their rows (<type>.<member>)"
        ));
    }
    fields.retain(|c, _| c == "description");
    let key = name.to_ascii_lowercase();
    let t = match index.get(&key) {
        // A type seen only in member rows so far: this row declares it.
        Some(&t) if table.type_lines[t].is_none() => t,
        // A second declaration: a type of its own, which the checks report as a duplicate.
        Some(_) => table.new_type(&name),
        None => table.type_of(&name, index),
    };
    table.type_lines[t] = Some(line);
    // The declaring row spells the name (a member row may have used another case).
    table.parsed.types[t].name = name;
    table.parsed.types[t].fields = fields;
}
