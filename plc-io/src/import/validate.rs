//! A variable list (from JSON or CSV) read into the declaration model (`plc_rules::decl`) and
//! checked by its one checker, so a file gets every rule the derive applies, in the same
//! words, all its errors at once, each naming the variable and the field. What is checked here
//! is only the list's own format: fields of the wrong JSON kind, unknown fields, a missing or
//! unknown type. A variable whose type is missing or unknown is still declared and its other
//! fields still checked: one mistake must not hide the others or cascade into "names no
//! variable".

use super::parse::Parsed;
use plc_core::{IecType, TypeFamily};
use plc_rules::capacity::DEFAULT_STRING_CAPACITY;
use plc_rules::decl::{
    self, ATTRIBUTE_KEYS, Decl, DeclType, Direction, Initial, InitialValue, Issue, IssueKind,
    KnownType, Located, Wording,
};
use serde_json::Value;
use std::borrow::Cow;

/// The fields a variable may have besides the attributes of every format: its type, a
/// string's capacity, an array's dimensions.
const LIST_FIELDS: [&str; 3] = ["type", "max_length", "dims"];

/// Where something is in a variable list: the variable (its index in [`Checked::decl`]) and
/// the field (JSON key, CSV column), `None` for the variable as a whole.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ListAt {
    /// The variable.
    pub var: usize,
    /// The field (owned only for a field the format does not know).
    pub field: Option<Cow<'static, str>>,
}

/// One worded problem and where it is.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Problem {
    /// Where.
    pub at: ListAt,
    /// What is wrong and what to do.
    pub message: String,
    /// The declaration rule broken (`IssueKind::name`), `None` for the format's own.
    pub kind: Option<&'static str>,
}

/// The outcome: the declaration (the list's variables in file order, then the names given
/// twice), its errors in file order, and warnings.
pub struct Checked {
    pub decl: Decl<ListAt>,
    /// How many of `decl`'s variables are the list's own; the rest are the second uses of a
    /// name, declared to be reported, not generated.
    pub declared: usize,
    pub errors: Vec<Problem>,
    pub warnings: Vec<Problem>,
}

/// How a variable list words the checker's messages: names in double quotes, as JSON writes
/// them; `lines` gives the line of a variable where the format has lines (CSV).
pub struct ListWording<'a> {
    pub lines: &'a dyn Fn(usize) -> Option<u64>,
}

impl Wording<ListAt> for ListWording<'_> {
    fn name(&self, name: &str) -> String {
        format!("{name:?}")
    }

    fn place(&self, at: &ListAt) -> String {
        (self.lines)(at.var).map_or_else(String::new, |l| format!(" (line {l})"))
    }
}

/// JSON text of a value, as messages quote it.
fn text(v: &Value) -> String {
    match v {
        Value::String(s) => format!("{s:?}"),
        other => other.to_string(),
    }
}

/// Reads one variable's fields into the model, reporting what the format itself refuses.
struct Reader<'a> {
    var: usize,
    obj: &'a serde_json::Map<String, Value>,
    problems: &'a mut Vec<Problem>,
    wording: &'a ListWording<'a>,
}

impl Reader<'_> {
    fn at(&self, field: &'static str) -> ListAt {
        ListAt {
            var: self.var,
            field: Some(Cow::Borrowed(field)),
        }
    }

    fn err(&mut self, field: &'static str, message: String) {
        let at = self.at(field);
        self.problems.push(Problem {
            at,
            message,
            kind: None,
        });
    }

    /// An issue of a shared rule found while reading, worded as the checker words it.
    fn issue(&mut self, field: &'static str, kind: IssueKind) {
        let name = kind.name();
        let issue = Issue::new(kind, self.at(field));
        self.problems.push(Problem {
            message: issue.message(self.wording),
            at: issue.at,
            kind: Some(name),
        });
    }

    fn string(&mut self, key: &'static str) -> Option<Located<String, ListAt>> {
        match self.obj.get(key)? {
            Value::String(s) => Some(Located::new(s.clone(), self.at(key))),
            other => {
                self.err(key, format!("expected a string, found {}", text(other)));
                None
            }
        }
    }

    fn flag(&mut self, key: &'static str) -> bool {
        match self.obj.get(key) {
            None => false,
            Some(Value::Bool(b)) => *b,
            Some(other) => {
                self.err(
                    key,
                    format!("expected true or false, found {}", text(other)),
                );
                false
            }
        }
    }

    /// The declared type; `None` when it is missing or unknown (reported).
    fn declared_type(&mut self) -> Option<IecType> {
        if !self.obj.contains_key("type") {
            self.err(
                "type",
                "missing: every variable needs a type (bool, u8..u64, i8..i64, f32, f64, \
                 string, or an IEC name)"
                    .into(),
            );
            return None;
        }
        let ty = self.string("type")?.value;
        match ty.parse() {
            Ok(t) => Some(t),
            Err(_) => {
                self.err(
                    "type",
                    format!(
                        "unknown type {ty:?}: use bool, u8..u64, i8..i64, f32, f64, string, or \
                         BOOL..LREAL, BYTE..LWORD, STRING, LTIME{}",
                        if ty.eq_ignore_ascii_case("TIME") {
                            " (a duration is LTIME, 64-bit nanoseconds; there is no 32-bit TIME)"
                        } else {
                            ""
                        }
                    ),
                );
                None
            }
        }
    }

    /// `max_length`: the capacity of a string (64 if not given).
    fn capacity(&mut self, declared: Option<IecType>) -> Option<u64> {
        match (declared, self.obj.get("max_length")) {
            (Some(IecType::String), None) => Some(DEFAULT_STRING_CAPACITY as u64),
            (Some(IecType::String), Some(v)) => match v.as_u64() {
                Some(n) => Some(n),
                None => {
                    self.issue("max_length", IssueKind::BadCapacity { text: text(v) });
                    Some(DEFAULT_STRING_CAPACITY as u64)
                }
            },
            (Some(_), Some(_)) => {
                self.err("max_length", "only strings have a max_length".into());
                None
            }
            // Unknown type: whether a capacity is allowed is unknown too.
            (None, _) | (Some(_), None) => None,
        }
    }

    /// `dims`: a list of whole numbers (their limits are the checker's).
    fn dims(&mut self) -> Vec<u64> {
        match self.obj.get("dims") {
            None => vec![],
            Some(Value::Array(a)) => {
                let d: Vec<u64> = a.iter().filter_map(Value::as_u64).collect();
                if d.len() != a.len() {
                    self.err(
                        "dims",
                        format!(
                            "{} is not a list of whole numbers of at least 1",
                            text(&Value::Array(a.clone()))
                        ),
                    );
                    vec![]
                } else if d.is_empty() {
                    self.issue("dims", IssueKind::DimensionCount { count: 0 });
                    vec![]
                } else {
                    d
                }
            }
            Some(other) => {
                self.err(
                    "dims",
                    format!("expected a list such as [3, 4], found {}", text(other)),
                );
                vec![]
            }
        }
    }

    fn direction(&mut self) -> Option<Located<Direction, ListAt>> {
        let d = self.string("direction")?;
        match Direction::from_name(&d.value) {
            Some(dir) => Some(Located::new(dir, d.at)),
            None => {
                self.issue("direction", IssueKind::UnknownDirection { text: d.value });
                None
            }
        }
    }

    /// `initial`; `null` is no initial value, as the framework that writes these files treats
    /// it.
    fn initial(&self) -> Option<Located<Initial, ListAt>> {
        let v = self.obj.get("initial").filter(|v| !v.is_null())?;
        let value = match v {
            Value::Bool(b) => InitialValue::Bool(*b),
            Value::Number(n) => match n.as_i64().map(i128::from).or(n.as_u64().map(i128::from)) {
                Some(i) => InitialValue::Int(i),
                None => InitialValue::Float(n.as_f64().unwrap_or(f64::NAN)),
            },
            Value::String(s) => InitialValue::Text(s.clone()),
            _ => InitialValue::Other,
        };
        let initial = Initial {
            value,
            text: text(v),
        };
        Some(Located::new(initial, self.at("initial")))
    }

    /// `source` and `bit`, each checked on its own so that both mistakes show. A malformed one
    /// (reported here) still counts as given: its partner is not told it lacks it, and alone
    /// it is still told it lacks its partner (through a stand-in the checker takes as valid).
    #[allow(clippy::type_complexity)]
    fn source_and_bit(
        &mut self,
    ) -> (
        Option<Located<String, ListAt>>,
        Option<Located<i64, ListAt>>,
    ) {
        let source = self.obj.get("source").map(|s| match s.as_str() {
            Some(name) => Some(Located::new(name.to_string(), self.at("source"))),
            None => {
                self.err(
                    "source",
                    format!("expected a variable name, found {}", text(s)),
                );
                None
            }
        });
        let bit = self.obj.get("bit").map(|b| match b.as_i64() {
            Some(n) => Some(Located::new(n, self.at("bit"))),
            None => {
                self.issue("bit", IssueKind::BadBit { text: text(b) });
                None
            }
        });
        match (source, bit) {
            (Some(_), Some(None)) | (Some(None), Some(_)) => (None, None),
            (Some(None), None) => (Some(Located::new(String::new(), self.at("source"))), None),
            (None, Some(None)) => (None, Some(Located::new(0, self.at("bit")))),
            (s, b) => (s.flatten(), b.flatten()),
        }
    }
}

/// One variable of the list, read into the model.
fn read_var(
    var: usize,
    name: &str,
    v: &Value,
    problems: &mut Vec<Problem>,
    wording: &ListWording,
) -> decl::Var<ListAt> {
    let whole = || ListAt { var, field: None };
    let type_at = ListAt {
        var,
        field: Some(Cow::Borrowed("type")),
    };
    let mut model = decl::Var::new(
        Located::new(name.to_string(), whole()),
        name,
        Located::new(DeclType::Unknown, type_at.clone()),
    );
    let Some(obj) = v.as_object() else {
        problems.push(Problem {
            at: whole(),
            message: format!(
                "expected an object such as {{ \"type\": \"u16\" }}, found {}",
                text(v)
            ),
            kind: None,
        });
        return model;
    };
    let mut r = Reader {
        var,
        obj,
        problems,
        wording,
    };
    for key in obj.keys() {
        if !LIST_FIELDS.contains(&key.as_str()) && !ATTRIBUTE_KEYS.contains(&key.as_str()) {
            let known: Vec<&str> = LIST_FIELDS.iter().chain(ATTRIBUTE_KEYS).copied().collect();
            r.problems.push(Problem {
                at: ListAt {
                    var,
                    field: Some(Cow::Owned(key.clone())),
                },
                message: format!("unknown field: use one of {}", known.join(", ")),
                kind: None,
            });
        }
    }
    let declared = r.declared_type();
    let capacity = r.capacity(declared);
    let dims = r.dims();
    if let Some(declared) = declared {
        // A bit-string type is stored as the unsigned integer of its width.
        let iec = match declared.family() {
            TypeFamily::BitString => {
                model.iec_type = Some(Located::new(declared, type_at));
                IecType::from_rust_name(declared.rust_name()).unwrap_or(declared)
            }
            _ => declared,
        };
        model.ty.value = DeclType::Known(KnownType {
            iec,
            capacity,
            dims,
        });
        model.capacity_at = obj.contains_key("max_length").then(|| r.at("max_length"));
        model.dims_at = obj.contains_key("dims").then(|| r.at("dims"));
    }
    model.link = r.string("link");
    model.direction = r.direction();
    model.at = r.string("at");
    model.initial = r.initial();
    (model.source, model.bit) = r.source_and_bit();
    model.description = r
        .string("description")
        .map_or_else(String::new, |d| d.value);
    model.nonvolatile = r.flag("nonvolatile") | r.flag("retain");
    model.read_only = r.flag("read_only");
    model.ux = r.flag("ux");
    model.quantity = r.string("quantity");
    model
}

/// Checks every variable and the rules between them. `lines` gives a variable's line where
/// the format has lines.
pub fn check(parsed: &Parsed, lines: &dyn Fn(usize) -> Option<u64>) -> Checked {
    let wording = ListWording { lines };
    let mut errors = Vec::new();
    let all = parsed.variables.iter().chain(&parsed.duplicates);
    let vars = all
        .enumerate()
        .map(|(i, (name, v))| read_var(i, name, v, &mut errors, &wording))
        .collect();
    let decl = Decl {
        structure: false,
        vars,
        unaligned: false,
    };
    let checked = decl::check(&decl);
    let mut warnings = Vec::new();
    for issue in &checked.issues {
        let problem = Problem {
            at: issue.at.clone(),
            message: issue.message(&wording),
            kind: Some(issue.kind.name()),
        };
        if issue.is_warning() {
            warnings.push(problem);
        } else {
            errors.push(problem);
        }
    }
    // In the order of the file, as a user fixes them going down it; the sort is stable, so a
    // variable's errors keep the order of its fields.
    errors.sort_by_key(|p| p.at.var);
    Checked {
        decl,
        declared: parsed.variables.len(),
        errors,
        warnings,
    }
}

#[cfg(test)]
mod agreement {
    //! The importer's half of the agreement test: each row's JSON form gives the row's issue
    //! kinds (the derive's half reads the Rust form).
    include!("../../../plc-rules/src/decl/agreement_table.rs");

    #[test]
    fn the_json_form_of_each_row_gives_its_issue_kinds() {
        let mut rows = 0;
        for row in ROWS {
            let Some(json) = row.json else { continue };
            let parsed = super::super::parse::parse(&format!("{{ \"variables\": {{ {json} }} }}"))
                .unwrap_or_else(|e| panic!("{}: {e}", row.rule));
            let checked = super::check(&parsed, &|_| None);
            let problems = checked.errors.iter().chain(&checked.warnings);
            let format: Vec<&String> = problems
                .clone()
                .filter(|p| p.kind.is_none())
                .map(|p| &p.message)
                .collect();
            assert!(format.is_empty(), "{}: {format:?}", row.rule);
            assert_eq!(
                sorted(problems.filter_map(|p| p.kind)),
                sorted(row.kinds.iter().copied()),
                "{}",
                row.rule
            );
            rows += 1;
        }
        assert!(rows >= 40, "{rows} rows with a JSON form");
    }
}
