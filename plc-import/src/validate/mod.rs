//! A variable list (from JSON or CSV) read into the declaration model (`plc_rules::decl`) and
//! checked by its one checker, so a file gets every rule the derive applies, in the same
//! words, all its errors at once, each naming the variable and the field. What is checked here
//! is only the list's own format: fields of the wrong JSON kind, unknown fields, a missing or
//! unknown type. A variable whose type is missing or unknown is still declared and its other
//! fields still checked: one mistake must not hide the others or cascade into "names no
//! variable".
//!
//! The `types` section's structures are read the same way, each into a declaration of its own
//! (`Decl { structure: true }`), and the rules between types are checked here: unknown type
//! names (with the nearest one suggested), cycles, nesting depth, image size, and what a
//! variable of a structure type cannot have as a whole (`initial`, `nonvolatile`, `link`,
//! `at`, a bit mapping), in the words of the derive's own checks.

use super::parse::{Parsed, TypeDef};
use plc_core::{IecType, TypeFamily};
use plc_rules::capacity::{DEFAULT_STRING_CAPACITY, MAX_IMAGE_BYTES, MAX_STRUCT_DEPTH};
use plc_rules::decl::{
    self, ATTRIBUTE_KEYS, Decl, DeclType, Direction, Initial, InitialValue, Issue, IssueKind,
    KnownType, Located, Wording,
};
use serde_json::Value;
use std::borrow::Cow;
use std::collections::HashMap;

/// The fields a variable may have besides the attributes of every format: its type, a
/// string's capacity, an array's dimensions.
const LIST_FIELDS: [&str; 3] = ["type", "max_length", "dims"];

/// Where something is in a variable list: the structure type the variable is a member of
/// (`None` for the list's own variables), the variable (its index in that group's
/// declaration) and the field (JSON key, CSV column), `None` for the variable as a whole.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ListAt {
    /// The type (index into [`Checked::types`]), `None` for the list's variables.
    pub ty: Option<usize>,
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

/// A variable of a structure type: the type (index into [`Checked::types`]) and the array
/// dimensions, outermost first (empty for one structure).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct StructUse {
    /// The type.
    pub ty: usize,
    /// The dimensions.
    pub dims: Vec<u64>,
}

/// One declaration: the variables in file order, then the names given twice.
pub struct Group {
    pub decl: Decl<ListAt>,
    /// How many of `decl`'s variables are the list's own; the rest are the second uses of a
    /// name, declared to be reported, not generated.
    pub declared: usize,
    /// For each variable, its structure type, if it has one (its `decl` type is then
    /// [`DeclType::Unknown`]: the rules of basic types do not apply to it).
    pub structured: Vec<Option<StructUse>>,
}

/// One type of the `types` section, checked.
pub struct CheckedType {
    /// The type's name, as the list gives it and tools show it.
    pub name: String,
    /// Its description ("" if none).
    pub description: String,
    /// Its members.
    pub group: Group,
    /// Whether an earlier type has the same name (in any case): checked, not generated.
    pub duplicate: bool,
    /// For a standard function block (`TON`), the Rust type the generated code names: the
    /// list uses it without declaring it, and it is not generated.
    pub standard: Option<&'static str>,
}

/// A problem of a type as a whole (its name, its fields), by type index and field.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TypeProblem {
    /// The type (index into [`Checked::types`]).
    pub ty: usize,
    /// The field (`description`, `variables`), `None` for the type's name.
    pub field: Option<String>,
    /// What is wrong and what to do.
    pub message: String,
}

/// The outcome: the list's variables, its types, every error (type problems, then the members'
/// and variables' in file order) and warnings.
pub struct Checked {
    /// The list's own variables.
    pub top: Group,
    /// The types, in file order.
    pub types: Vec<CheckedType>,
    /// The types in dependency order (a type after every type its members use), as they are
    /// generated.
    pub order: Vec<usize>,
    /// Bytes of the whole image (saturating): below 2^32 for a valid list.
    pub image_bytes: u64,
    pub type_errors: Vec<TypeProblem>,
    pub errors: Vec<Problem>,
    pub warnings: Vec<Problem>,
}

impl Checked {
    /// The group a location is in.
    pub fn group(&self, ty: Option<usize>) -> &Group {
        match ty {
            Some(t) => &self.types[t].group,
            None => &self.top,
        }
    }

    /// The types the list declares (not the standard function blocks), with their indexes.
    pub fn listed(&self) -> impl Iterator<Item = (usize, &CheckedType)> + Clone {
        self.types
            .iter()
            .enumerate()
            .filter(|(_, t)| t.standard.is_none())
    }

    /// The name of the variable at `at`.
    pub fn var_name(&self, at: &ListAt) -> &str {
        &self.group(at.ty).decl.vars[at.var].name.value
    }
}

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
fn text(v: &Value) -> String {
    match v {
        Value::String(s) => format!("{s:?}"),
        other => other.to_string(),
    }
}

/// Reads one variable's fields into the model, reporting what the format itself refuses.
struct Reader<'a> {
    ty: Option<usize>,
    var: usize,
    obj: &'a serde_json::Map<String, Value>,
    problems: &'a mut Vec<Problem>,
    wording: &'a ListWording<'a>,
}

impl Reader<'_> {
    fn at(&self, field: &'static str) -> ListAt {
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
    fn declared_type(&mut self, types: &TypeNames) -> Option<Declared> {
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
    fn capacity(&mut self, declared: Option<IecType>, structure: bool) -> Option<u64> {
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

/// A variable's type as the list declares it.
enum Declared {
    /// A basic type (or a bit string, stored as its unsigned integer).
    Basic(IecType),
    /// A type of the `types` section (its index).
    Structure(usize),
}

/// The types a variable may name: the first type of each name (a second one is an error).
struct TypeNames<'a> {
    index: HashMap<&'a str, usize>,
    names: Vec<&'a str>,
}

/// One variable of the list, read into the model, and its structure type if it has one.
fn read_var(
    (ty, var): (Option<usize>, usize),
    name: &str,
    v: &Value,
    types: &TypeNames,
    problems: &mut Vec<Problem>,
    wording: &ListWording,
) -> (decl::Var<ListAt>, Option<StructUse>) {
    let whole = || ListAt {
        ty,
        var,
        field: None,
    };
    let type_at = ListAt {
        ty,
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
        return (model, None);
    };
    let mut r = Reader {
        ty,
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
                    ty,
                    var,
                    field: Some(Cow::Owned(key.clone())),
                },
                message: format!("unknown field: use one of {}", known.join(", ")),
                kind: None,
            });
        }
    }
    let declared = r.declared_type(types);
    let basic = match declared {
        Some(Declared::Basic(t)) => Some(t),
        _ => None,
    };
    let structure = matches!(declared, Some(Declared::Structure(_)));
    let capacity = r.capacity(basic, structure);
    let dims = r.dims();
    model.dims_at = obj.contains_key("dims").then(|| r.at("dims"));
    let mut structured = None;
    match declared {
        Some(Declared::Basic(declared)) => {
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
        }
        Some(Declared::Structure(t)) => {
            // The limits of an array of structures are those of any array: checked on a
            // stand-in element, whose type no other rule sees.
            let stand_in = KnownType {
                iec: IecType::Bool,
                capacity: None,
                dims: dims.clone(),
            };
            for kind in decl::type_rules(&stand_in) {
                let at = model.dims_at.clone().unwrap_or_else(|| r.at("type"));
                r.issue_at(at, kind);
            }
            structured = Some(StructUse { ty: t, dims });
        }
        None => {}
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
    if structured.is_some() {
        r.structure_as_a_whole(&mut model);
    }
    (model, structured)
}

impl Reader<'_> {
    /// An issue of a shared rule at a given place.
    fn issue_at(&mut self, at: ListAt, kind: IssueKind) {
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
    fn structure_as_a_whole(&mut self, model: &mut decl::Var<ListAt>) {
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

/// Reads and checks one declaration: the list's variables (`ty` `None`) or a type's members.
fn read_group(
    ty: Option<usize>,
    parsed: &Parsed,
    types: &TypeNames,
    wording: &ListWording,
    errors: &mut Vec<Problem>,
    warnings: &mut Vec<Problem>,
) -> Group {
    let all = parsed.variables.iter().chain(&parsed.duplicates);
    let (vars, structured): (Vec<_>, Vec<_>) = all
        .enumerate()
        .map(|(i, (name, v))| read_var((ty, i), name, v, types, errors, wording))
        .unzip();
    let decl = Decl {
        structure: ty.is_some(),
        vars,
        unaligned: false,
    };
    sources_of_structure_type(&decl, &structured, wording, errors);
    for issue in &decl::check(&decl).issues {
        let problem = Problem {
            at: issue.at.clone(),
            message: issue.message(wording),
            kind: Some(issue.kind.name()),
        };
        if issue.is_warning() {
            warnings.push(problem);
        } else {
            errors.push(problem);
        }
    }
    Group {
        decl,
        declared: parsed.variables.len(),
        structured,
    }
}

/// A bit-mapped bool whose source is a structure: the checker takes a source of a type it
/// cannot see as valid (the derive's compiler checks it), so the list checks it here, in the
/// derive's words.
fn sources_of_structure_type(
    decl: &Decl<ListAt>,
    structured: &[Option<StructUse>],
    wording: &ListWording,
    errors: &mut Vec<Problem>,
) {
    let structures: std::collections::HashSet<&str> = decl
        .vars
        .iter()
        .zip(structured)
        .filter(|(_, s)| s.is_some())
        .map(|(v, _)| v.field.as_str())
        .collect();
    for v in &decl.vars {
        if let Some(src) = &v.source
            && structures.contains(src.value.as_str())
        {
            errors.push(Problem {
                at: src.at.clone(),
                message: format!(
                    "the source {} must be an integer (u8, u16, u32, u64, i8, i16, i32 or i64), \
                     but its type is not",
                    wording.name(&src.value)
                ),
                kind: None,
            });
        }
    }
}

/// The fields a type may have.
const TYPE_FIELDS: [&str; 2] = ["description", "variables"];

/// The problems of one type as a whole: its name, fields and members object.
fn type_rules(t: usize, def: &TypeDef, duplicate_of: Option<&str>) -> Vec<TypeProblem> {
    let mut out = Vec::new();
    let mut problem = |field: Option<&str>, message: String| {
        out.push(TypeProblem {
            ty: t,
            field: field.map(str::to_string),
            message,
        })
    };
    if super::standard::is_standard(&def.name) {
        problem(
            None,
            format!(
                "invalid type name {:?}: it is the name of a standard function block of IEC \
                 61131-3, which a list uses without declaring it (\"type\": \"{}\"); choose \
                 another name",
                def.name,
                def.name.to_ascii_uppercase()
            ),
        );
    } else if let Err(e) = plc_rules::names::check_name(&def.name) {
        problem(None, format!("invalid type name {:?}: {e}", def.name));
    } else if def.name.parse::<IecType>().is_ok() {
        // `"type": "f64"` would name the basic type, never this one.
        problem(
            None,
            format!(
                "invalid type name {:?}: it is the name of a basic type; choose another name",
                def.name
            ),
        );
    }
    if let Some(first) = duplicate_of {
        problem(
            None,
            format!(
                "the type {:?} is declared already as {first:?} (type names are unique in any \
                 case): rename one",
                def.name
            ),
        );
    }
    for (key, value) in &def.fields {
        if key == "description" {
            if !value.is_string() {
                problem(
                    Some(key),
                    format!("expected a string, found {}", text(value)),
                );
            }
        } else {
            problem(
                Some(key),
                format!("unknown field: use one of {}", TYPE_FIELDS.join(", ")),
            );
        }
    }
    if def.members.variables.is_empty() {
        problem(
            Some("variables"),
            "a structure needs at least one member: give them as \"variables\": { \"pos\": \
             { \"type\": \"f64\" } }"
                .into(),
        );
    }
    out
}

/// The members of a standard function block as a checked group: known to be valid (their IEC
/// names include some a list may not declare, such as `R`), so not checked again.
fn standard_group(ty: usize, block: &super::standard::StandardBlock) -> Group {
    let vars = block
        .members
        .iter()
        .enumerate()
        .map(|(var, m)| {
            let at = ListAt {
                ty: Some(ty),
                var,
                field: None,
            };
            let known = KnownType {
                iec: m.iec_type,
                capacity: None,
                dims: m.dims.iter().map(|&d| d as u64).collect(),
            };
            decl::Var::new(
                Located::new(m.name.to_string(), at.clone()),
                m.name,
                Located::new(DeclType::Known(known), at),
            )
        })
        .collect();
    Group {
        decl: Decl {
            structure: true,
            vars,
            unaligned: false,
        },
        declared: block.members.len(),
        structured: vec![None; block.members.len()],
    }
}

/// What the walk over the types works out.
struct TypeGraph {
    /// Dependency order: each type after the types its members use.
    order: Vec<usize>,
    /// Levels of structures in each type (1 for a type of basic members only).
    depth: Vec<usize>,
    /// Bytes of each type's image (saturating).
    size: Vec<u64>,
}

/// Bytes of one declaration's image (saturating), given the sizes of the types so far.
fn group_size(group: &Group, size: &[u64]) -> u64 {
    let vars = group.decl.vars.iter().zip(&group.structured);
    vars.take(group.declared)
        .map(|(v, s)| match (s, v.ty.value.known()) {
            (Some(s), _) => elements(&s.dims).saturating_mul(size[s.ty]),
            (None, Some(k)) => {
                let one = k.capacity.unwrap_or(k.iec.image_size() as u64);
                elements(&k.dims).saturating_mul(one)
            }
            (None, None) => 0,
        })
        .fold(0u64, u64::saturating_add)
}

fn elements(dims: &[u64]) -> u64 {
    dims.iter().fold(1u64, |a, &d| a.saturating_mul(d))
}

/// Walks the types depth first without recursion (a hostile list may chain thousands), in
/// file order: reports every cycle at the member that closes it, naming the cycle, and works
/// out the dependency order, depths and sizes.
fn walk_types(types: &[CheckedType], errors: &mut Vec<Problem>) -> TypeGraph {
    const NEW: u8 = 0;
    const OPEN: u8 = 1;
    const DONE: u8 = 2;
    let n = types.len();
    let mut state = vec![NEW; n];
    let mut graph = TypeGraph {
        order: Vec::with_capacity(n),
        depth: vec![0; n],
        size: vec![0; n],
    };
    let uses = |t: usize, i: usize| {
        let g = &types[t].group;
        (i < g.declared).then(|| g.structured[i].as_ref().map(|s| s.ty))
    };
    for root in 0..n {
        if state[root] != NEW {
            continue;
        }
        // (type, the next member to follow)
        let mut stack = vec![(root, 0usize)];
        state[root] = OPEN;
        while let Some(top) = stack.last_mut() {
            let (t, i) = *top;
            match uses(t, i) {
                Some(used) => {
                    top.1 += 1;
                    match used.map(|u| (u, state[u])) {
                        Some((u, NEW)) => {
                            state[u] = OPEN;
                            stack.push((u, 0));
                        }
                        Some((u, OPEN)) => errors.push(cycle(types, &stack, u)),
                        _ => {}
                    }
                }
                None => {
                    stack.pop();
                    state[t] = DONE;
                    let g = &types[t].group;
                    let deepest = g.structured[..g.declared]
                        .iter()
                        .flatten()
                        .map(|s| graph.depth[s.ty])
                        .max()
                        .unwrap_or(0);
                    graph.depth[t] = deepest.saturating_add(1);
                    graph.size[t] = group_size(g, &graph.size);
                    graph.order.push(t);
                }
            }
        }
    }
    graph
}

/// The error of a cycle: `stack` is the walk's path, whose last member leads back to `to`.
fn cycle(types: &[CheckedType], stack: &[(usize, usize)], to: usize) -> Problem {
    let from = stack.iter().rposition(|&(t, _)| t == to).unwrap_or(0);
    let path: Vec<String> = stack[from..]
        .iter()
        .map(|&(t, next)| {
            let member = &types[t].group.decl.vars[next - 1].name.value;
            format!("{}.{member}", types[t].name)
        })
        .chain([types[to].name.clone()])
        .collect();
    let &(t, next) = stack.last().unwrap_or(&(to, 1));
    Problem {
        at: ListAt {
            ty: Some(t),
            var: next - 1,
            field: Some(Cow::Borrowed("type")),
        },
        message: format!(
            "the type {:?} contains itself: {}; a structure cannot hold itself, directly or \
             through its members (hold the other part in a variable of its own)",
            types[to].name,
            path.join(" -> ")
        ),
        kind: None,
    }
}

/// The nesting limit, at every member or variable whose type nests too deep, in the derive's
/// words: a program's variable may have a type of 8 levels, a member one of 7.
fn nesting(group: &Group, depth: &[usize], wording: &ListWording, errors: &mut Vec<Problem>) {
    let levels = match group.decl.structure {
        true => MAX_STRUCT_DEPTH - 1,
        false => MAX_STRUCT_DEPTH,
    };
    let vars = group.decl.vars.iter().zip(&group.structured);
    for (v, s) in vars.take(group.declared) {
        if let Some(s) = s
            && depth[s.ty] > levels
        {
            errors.push(Problem {
                at: v.ty.at.clone(),
                message: format!(
                    "the type of {} nests structures too deep: at most {MAX_STRUCT_DEPTH} \
                     levels of structures in one another",
                    wording.name(&v.name.value)
                ),
                kind: None,
            });
        }
    }
}

/// Checks the types and every variable, and the rules between them. `lines` gives a
/// variable's line where the format has lines.
pub fn check(parsed: &Parsed, lines: Lines) -> Checked {
    let wording = ListWording { lines };
    let (mut errors, mut warnings) = (Vec::new(), Vec::new());
    let mut names = TypeNames {
        index: HashMap::new(),
        names: Vec::new(),
    };
    let mut first_of: HashMap<String, usize> = HashMap::new();
    let mut type_errors = Vec::new();
    let mut duplicates = Vec::with_capacity(parsed.types.len());
    for (t, def) in parsed.types.iter().enumerate() {
        let first = *first_of.entry(def.name.to_ascii_lowercase()).or_insert(t);
        let duplicate_of = (first != t).then(|| parsed.types[first].name.as_str());
        type_errors.extend(type_rules(t, def, duplicate_of));
        if first == t {
            names.index.insert(&def.name, t);
            names.names.push(&def.name);
        }
        duplicates.push(first != t);
    }
    // The standard function blocks come after the list's types; `"type": "TON"` names the
    // standard one even where the list declares a type of that name (an error above).
    let standard = super::standard::blocks();
    for (k, b) in standard.iter().enumerate() {
        names.index.insert(b.name, parsed.types.len() + k);
        names.names.push(b.name);
    }
    let mut types: Vec<CheckedType> = parsed
        .types
        .iter()
        .zip(duplicates)
        .enumerate()
        .map(|(t, (def, duplicate))| CheckedType {
            name: def.name.clone(),
            description: def
                .fields
                .get("description")
                .and_then(Value::as_str)
                .unwrap_or("")
                .to_string(),
            group: read_group(
                Some(t),
                &def.members,
                &names,
                &wording,
                &mut errors,
                &mut warnings,
            ),
            duplicate,
            standard: None,
        })
        .collect();
    let first_standard = types.len();
    types.extend(standard.iter().enumerate().map(|(k, b)| CheckedType {
        name: b.name.to_string(),
        description: String::new(),
        group: standard_group(first_standard + k, b),
        duplicate: false,
        standard: Some(b.rust),
    }));
    let top = read_group(None, parsed, &names, &wording, &mut errors, &mut warnings);
    let graph = walk_types(&types, &mut errors);
    for (t, ty) in types.iter().enumerate() {
        nesting(&ty.group, &graph.depth, &wording, &mut errors);
        if graph.size[t] >= MAX_IMAGE_BYTES {
            type_errors.push(TypeProblem {
                ty: t,
                field: None,
                message: format!(
                    "the image of {:?} is 4 GiB or more: the members must take less than 2^32 \
                     bytes (fewer or smaller array elements)",
                    ty.name
                ),
            });
        }
    }
    nesting(&top, &graph.depth, &wording, &mut errors);
    // In the order of the file, as a user fixes them going down it: the types (usually
    // first), then the variables; the sort is stable, so a variable's errors keep the order of
    // its fields.
    errors.sort_by_key(|p| (p.at.ty.is_none(), p.at.ty, p.at.var));
    Checked {
        image_bytes: group_size(&top, &graph.size),
        top,
        types,
        order: graph.order,
        type_errors,
        errors,
        warnings,
    }
}

#[cfg(test)]
mod agreement {
    //! The importer's half of the agreement test: each row's JSON form gives the row's issue
    //! kinds (the derive's half reads the Rust form).
    include!("../../plc-rules/src/decl/agreement_table.rs");

    #[test]
    fn the_json_form_of_each_row_gives_its_issue_kinds() {
        let mut rows = 0;
        for row in ROWS {
            let Some(json) = row.json else { continue };
            // A row declaring a structure type gives its members; the list declares them in
            // its `types` section.
            let list = if row.rust.contains("derive(PlcStruct)") {
                format!("{{ \"types\": {{ \"Axis\": {{ \"variables\": {{ {json} }} }} }} }}")
            } else {
                format!("{{ \"variables\": {{ {json} }} }}")
            };
            let parsed =
                super::super::parse::parse(&list).unwrap_or_else(|e| panic!("{}: {e}", row.rule));
            let checked = super::check(&parsed, &|_, _| None);
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
