//! One variable's fields read into the declaration model, with what the format itself refuses
//! (a field of the wrong JSON kind, a missing or unknown type) and what a variable of a
//! structure type cannot have as a whole.

use super::outcome::{ListAt, Problem};
use super::wording::{ListWording, text};
use plc_core::IecType;
use plc_rules::capacity::DEFAULT_STRING_CAPACITY;
use plc_rules::decl::{self, Direction, Initial, InitialValue, Issue, IssueKind, Located, Wording};
use serde_json::Value;
use std::borrow::Cow;
use std::collections::HashMap;

/// Reads one variable's fields into the model, reporting what the format itself refuses.
pub(super) struct Reader<'a> {
    pub(super) ty: Option<usize>,
    pub(super) var: usize,
    pub(super) obj: &'a serde_json::Map<String, Value>,
    pub(super) problems: &'a mut Vec<Problem>,
    pub(super) wording: &'a ListWording<'a>,
}

impl Reader<'_> {
    pub(super) fn at(&self, field: &'static str) -> ListAt {
        ListAt {
            ty: self.ty,
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
        self.issue_at(self.at(field), kind);
    }

    pub(super) fn string(&mut self, key: &'static str) -> Option<Located<String, ListAt>> {
        match self.obj.get(key)? {
            Value::String(s) => Some(Located::new(s.clone(), self.at(key))),
            other => {
                self.err(key, format!("expected a string, found {}", text(other)));
                None
            }
        }
    }

    /// A number field (`"deadband": 0.5`): its rules are the checker's, its JSON kind is here.
    pub(super) fn number(&mut self, key: &'static str) -> Option<Located<f64, ListAt>> {
        match self.obj.get(key)? {
            Value::Number(n) => n.as_f64().map(|v| Located::new(v, self.at(key))),
            other => {
                self.err(
                    key,
                    format!("expected a number such as 0.5, found {}", text(other)),
                );
                None
            }
        }
    }

    pub(super) fn flag(&mut self, key: &'static str) -> bool {
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
    pub(super) fn declared_type(&mut self, types: &TypeNames) -> Option<Declared> {
        if !self.obj.contains_key("type") {
            self.err(
                "type",
                "missing: every variable needs a type (bool, u8..u64, i8..i64, f32, f64, \
                 string, an IEC name, or a type of the list's \"types\")"
                    .into(),
            );
            return None;
        }
        let ty = self.string("type")?.value;
        if let Ok(t) = ty.parse() {
            return Some(Declared::Basic(t));
        }
        if let Some(&t) = types.index.get(ty.as_str()) {
            return Some(Declared::Structure(t));
        }
        let basic = [
            "bool", "u8", "u16", "u32", "u64", "i8", "i16", "i32", "i64", "f32", "f64",
        ];
        let candidates = types.names.iter().copied().chain(basic).chain(["string"]);
        let hint = plc_rules::names::nearest(&ty, candidates)
            .map_or_else(String::new, |n| format!(" (did you mean {n:?}?)"));
        self.err(
            "type",
            format!(
                "unknown type {ty:?}{hint}: use bool, u8..u64, i8..i64, f32, f64, string, \
                 BOOL..LREAL, BYTE..LWORD, STRING, LTIME, or a type of the list's \"types\" \
                 (type names are exact){}",
                if ty.eq_ignore_ascii_case("TIME") {
                    " (a duration is LTIME, 64-bit nanoseconds; there is no 32-bit TIME)"
                } else {
                    ""
                }
            ),
        );
        None
    }

    /// `max_length`: the capacity of a string (64 if not given).
    pub(super) fn capacity(&mut self, declared: Option<IecType>, structure: bool) -> Option<u64> {
        if structure && self.obj.contains_key("max_length") {
            self.err("max_length", "only strings have a max_length".into());
            return None;
        }
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
    pub(super) fn dims(&mut self) -> Vec<u64> {
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

    pub(super) fn direction(&mut self) -> Option<Located<Direction, ListAt>> {
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
    pub(super) fn initial(&self) -> Option<Located<Initial, ListAt>> {
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
    pub(super) fn source_and_bit(
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

impl Reader<'_> {
    /// An issue of a shared rule at a given place.
    pub(super) fn issue_at(&mut self, at: ListAt, kind: IssueKind) {
        let name = kind.name();
        let issue = Issue::new(kind, at);
        self.problems.push(Problem {
            message: issue.message(self.wording),
            at: issue.at,
            kind: Some(name),
        });
    }

    /// What a variable of a structure type cannot have as a whole, in the words of the
    /// derive's checks of a structured field (docs/rules.md, "Structures"); each is taken out
    /// of the model once reported, so the checker does not judge it again as if the type were
    /// basic. Inside a structure, `link` and `at` are left to the checker, whose
    /// `IoInStructure` names the rule that applies there.
    pub(super) fn structure_as_a_whole(&mut self, model: &mut decl::Var<ListAt>) {
        let name = self.wording.name(&model.name.value);
        if model.initial.take().is_some() {
            self.err(
                "initial",
                format!(
                    "{name} is a structure: give `initial` on its members, in the structure's \
                     declaration"
                ),
            );
        }
        if model.nonvolatile {
            model.nonvolatile = false;
            let key = if self.obj.get("nonvolatile") == Some(&Value::Bool(true)) {
                "nonvolatile"
            } else {
                "retain"
            };
            self.err(
                key,
                format!(
                    "{name} is a structure: it cannot be `nonvolatile` as a whole; mark the \
                     members to keep `nonvolatile` in the structure's declaration"
                ),
            );
        }
        if model.alarm.take().is_some() {
            self.err(
                "alarm",
                format!(
                    "{name} is a structure: declare alarms on its members, in the structure's \
                     declaration (each instance then has its own)"
                ),
            );
        }
        for (key, given) in [
            ("unit", model.unit.take().is_some()),
            ("deadband", model.deadband.take().is_some()),
        ] {
            if given {
                self.err(
                    key,
                    format!(
                        "{name} is a structure: `{key}` is for numbers; declare it on the \
                         structure's members"
                    ),
                );
            }
        }
        if model.source.take().is_some() | model.bit.take().is_some() {
            let key = if self.obj.contains_key("source") {
                "source"
            } else {
                "bit"
            };
            self.err(
                key,
                format!("{name} is mapped to a bit, so its type must be bool"),
            );
        }
        if self.ty.is_none() {
            if model.link.take().is_some() {
                self.err(
                    "link",
                    format!(
                        "{name} is a structure: a link connects one basic variable to one \
                         entry; link a top-level variable of a basic type"
                    ),
                );
            }
            if model.at.take().is_some() {
                self.err(
                    "at",
                    format!(
                        "{name} is a structure: `at` locates one channel; locate a top-level \
                         variable of a basic type"
                    ),
                );
            }
        }
    }
}

/// A variable's type as the list declares it.
pub(super) enum Declared {
    /// A basic type (or a bit string, stored as its unsigned integer).
    Basic(IecType),
    /// A type of the `types` section (its index).
    Structure(usize),
}

/// The types a variable may name: the first type of each name (a second one is an error).
pub(super) struct TypeNames<'a> {
    pub(super) index: HashMap<&'a str, usize>,
    pub(super) names: Vec<&'a str>,
}
