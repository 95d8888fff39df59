//! Every rule the derive enforces, applied to a variable list (from JSON or CSV) before any code
//! is written, so a bad file gets all its errors at once, each naming the variable and the
//! field. A variable whose type is missing or unknown is still declared and its other fields
//! are still checked: one mistake must not hide the others or cascade into "names no variable".

use super::parse::Parsed;
use plc_core::{Direction, IecType, TypeFamily};
use plc_rules::address::{Area, IecAddress, Size};
use plc_rules::capacity::{
    DEFAULT_STRING_CAPACITY, MAX_ARRAY_DIMS, MAX_ARRAY_ITEMS, MAX_STRING_CAPACITY,
};
use plc_rules::link::Link;
use plc_rules::names;
use serde_json::Value;
use std::collections::{HashMap, HashSet};

/// The fields a variable may have (`retain` is an alias of `nonvolatile`, as in the derive).
pub const FIELDS: [&str; 13] = [
    "type",
    "link",
    "description",
    "initial",
    "nonvolatile",
    "max_length",
    "source",
    "bit",
    "direction",
    "read_only",
    "at",
    "dims",
    "retain",
];

/// One variable, checked.
#[derive(Clone, Debug, PartialEq)]
pub struct Spec {
    /// Name (the struct field).
    pub name: String,
    /// IEC type of one element as its Rust type maps it (`WORD` fields are `UINT` here).
    pub iec_type: IecType,
    /// A bit-string type declared in the file (`BYTE`..`LWORD`).
    pub bit_string: Option<IecType>,
    /// String capacity.
    pub capacity: Option<usize>,
    /// Array dimensions.
    pub dims: Vec<usize>,
    /// Hardware link.
    pub link: Option<String>,
    /// Description.
    pub description: Option<String>,
    /// Initial value.
    pub initial: Option<Value>,
    /// Nonvolatile.
    pub nonvolatile: bool,
    /// Source word and bit of a bit-mapped bool.
    pub source: Option<(String, u8)>,
    /// Direction as written.
    pub direction: Option<Direction>,
    /// Read-only.
    pub read_only: bool,
    /// IEC address.
    pub at: Option<String>,
}

impl Spec {
    /// The Rust type of one element: `u16`, `FixedString<64>`.
    pub fn element_type(&self) -> String {
        match self.capacity {
            Some(n) => format!("FixedString<{n}>"),
            None => self.iec_type.rust_name().to_string(),
        }
    }

    /// The field's Rust type, arrays included: `[[f32; 4]; 3]`.
    pub fn rust_type(&self) -> String {
        self.dims
            .iter()
            .rev()
            .fold(self.element_type(), |inner, d| format!("[{inner}; {d}]"))
    }

    /// The direction the derive gives it before bit mapping: as written, else from `at`, else
    /// internal. A contradiction with `at` is reported elsewhere; `at` wins, as in the derive.
    fn own_direction(&self) -> Direction {
        match self
            .at
            .as_deref()
            .and_then(|a| a.parse::<IecAddress>().ok())
        {
            Some(a) if a.area == Area::Input => Direction::Input,
            Some(a) if a.area == Area::Output => Direction::Output,
            _ => self.direction.unwrap_or(Direction::Internal),
        }
    }
}

/// What an issue is about; the front end (JSON or CSV) turns it into a location.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Subject {
    /// A variable, by name (names are unique once duplicates are set aside).
    Var(String),
    /// The n-th name of [`Parsed::duplicates`].
    Duplicate(usize),
}

/// One error or warning: its subject, the field (if one), and what is wrong.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Issue {
    /// The variable.
    pub subject: Subject,
    /// The field (JSON key, CSV column); `None` for the variable as a whole.
    pub field: Option<String>,
    /// What is wrong and what to do.
    pub message: String,
}

/// The outcome: checked variables (those with a known type), errors, warnings.
pub struct Checked {
    pub specs: Vec<Spec>,
    pub errors: Vec<Issue>,
    pub warnings: Vec<Issue>,
}

fn text(v: &Value) -> String {
    match v {
        Value::String(s) => format!("{s:?}"),
        other => other.to_string(),
    }
}

/// Collects the issues of one variable.
struct Report<'a> {
    name: &'a str,
    errors: &'a mut Vec<Issue>,
}

impl Report<'_> {
    fn err(&mut self, field: &str, message: String) {
        self.errors.push(Issue {
            subject: Subject::Var(self.name.to_string()),
            field: (!field.is_empty()).then(|| field.to_string()),
            message,
        });
    }
}

/// A variable as checked on its own; `typed` is false when its type is missing or unknown, so
/// that the checks between variables that need the type are skipped.
struct Var {
    spec: Spec,
    typed: bool,
}

fn str_field(obj: &serde_json::Map<String, Value>, key: &str, r: &mut Report) -> Option<String> {
    match obj.get(key)? {
        Value::String(s) => Some(s.clone()),
        other => {
            r.err(key, format!("expected a string, found {}", text(other)));
            None
        }
    }
}

fn bool_field(obj: &serde_json::Map<String, Value>, key: &str, r: &mut Report) -> bool {
    match obj.get(key) {
        None => false,
        Some(Value::Bool(b)) => *b,
        Some(other) => {
            r.err(
                key,
                format!("expected true or false, found {}", text(other)),
            );
            false
        }
    }
}

/// The declared type: `Ok(None)` when it is missing or unknown (reported).
fn declared_type(obj: &serde_json::Map<String, Value>, r: &mut Report) -> Option<IecType> {
    if !obj.contains_key("type") {
        r.err("type", "missing: every variable needs a type (bool, u8..u64, i8..i64, f32, f64, string, or an IEC name)".into());
        return None;
    }
    let ty_text = str_field(obj, "type", r)?;
    match ty_text.parse() {
        Ok(t) => Some(t),
        Err(_) => {
            r.err(
                "type",
                format!(
                    "unknown type {ty_text:?}: use bool, u8..u64, i8..i64, f32, f64, string, or BOOL..LREAL, BYTE..LWORD, STRING"
                ),
            );
            None
        }
    }
}

fn dims_field(obj: &serde_json::Map<String, Value>, r: &mut Report) -> Vec<usize> {
    match obj.get("dims") {
        None => vec![],
        Some(Value::Array(a)) => {
            let d: Vec<usize> = a
                .iter()
                .filter_map(|x| x.as_u64().and_then(|n| usize::try_from(n).ok()))
                .collect();
            let items = d.iter().try_fold(1usize, |acc, &n| acc.checked_mul(n));
            if d.len() != a.len() || d.contains(&0) {
                r.err(
                    "dims",
                    format!(
                        "{} is not a list of whole numbers of at least 1",
                        text(&Value::Array(a.clone()))
                    ),
                );
                vec![]
            } else if d.is_empty() || d.len() > MAX_ARRAY_DIMS {
                r.err(
                    "dims",
                    format!(
                        "{} dimensions given: an array has 1 to {MAX_ARRAY_DIMS} dimensions (seed 003)",
                        d.len()
                    ),
                );
                vec![]
            } else if items.is_none_or(|n| n > MAX_ARRAY_ITEMS) {
                r.err(
                    "dims",
                    format!(
                        "an array holds at most {MAX_ARRAY_ITEMS} items in all dimensions (seed 003)"
                    ),
                );
                vec![]
            } else {
                d
            }
        }
        Some(other) => {
            r.err(
                "dims",
                format!("expected a list such as [3, 4], found {}", text(other)),
            );
            vec![]
        }
    }
}

fn capacity_field(
    obj: &serde_json::Map<String, Value>,
    iec_type: Option<IecType>,
    r: &mut Report,
) -> Option<usize> {
    match (iec_type, obj.get("max_length")) {
        (Some(IecType::String), None) => Some(DEFAULT_STRING_CAPACITY),
        (Some(IecType::String), Some(v)) => match v.as_u64() {
            Some(n) if (1..=MAX_STRING_CAPACITY as u64).contains(&n) => Some(n as usize),
            _ => {
                r.err(
                    "max_length",
                    format!("{} is not a capacity of 1..=255 bytes (seed 000)", text(v)),
                );
                Some(DEFAULT_STRING_CAPACITY)
            }
        },
        (Some(_), Some(_)) => {
            r.err("max_length", "only strings have a max_length".into());
            None
        }
        // Unknown type: whether a capacity is allowed is unknown too.
        (None, _) | (Some(_), None) => None,
    }
}

/// Checks `at`: syntax, area, and (with a known type) width and alignment; a direction that
/// contradicts it.
fn at_field(
    at: &str,
    ty: Option<(IecType, IecType)>,
    dims: &[usize],
    direction: Option<Direction>,
    r: &mut Report,
) {
    let addr = match at.parse::<IecAddress>() {
        Err(e) => return r.err("at", format!("invalid address {e}")),
        Ok(addr) if addr.area == Area::Memory => {
            return r.err(
                "at",
                format!("{at:?} is in the M area: `at` locates I/O channels (%I or %Q)"),
            );
        }
        Ok(addr) => addr,
    };
    if let Some((iec_type, declared)) = ty {
        let width = if iec_type == IecType::Bool {
            1
        } else {
            iec_type.bits()
        };
        if !dims.is_empty() || iec_type == IecType::String {
            let what = if dims.is_empty() {
                "a STRING"
            } else {
                "an array"
            };
            r.err(
                "at",
                format!(
                    "{what} cannot be located: only a scalar of a basic type can (seed 003); remove `at`"
                ),
            );
        } else if Size::from_bits(width) != Some(addr.size) {
            r.err(
                "at",
                format!(
                    "{at:?} is {} bits but a {} has {width}",
                    addr.size.bits(),
                    declared
                ),
            );
        } else if !addr.is_aligned() {
            r.err(
                "at",
                format!(
                    "{at:?} is not aligned to {} bytes (seed 004)",
                    addr.size.bytes()
                ),
            );
        }
    }
    let implied = if addr.area == Area::Input {
        Direction::Input
    } else {
        Direction::Output
    };
    if direction.is_some_and(|d| d != implied) {
        r.err(
            "direction",
            format!(
                "contradicts `at` {at:?}, which makes it an {}",
                implied.name()
            ),
        );
    }
}

/// Whether `init` fits the type; the error says why not.
fn initial_fits(
    init: &Value,
    iec_type: IecType,
    declared: IecType,
    capacity: Option<usize>,
) -> Result<(), String> {
    match (init, iec_type.family()) {
        (Value::Bool(_), TypeFamily::Bool) => Ok(()),
        (Value::Number(n), _) if iec_type.is_integer() => {
            match n.as_i64().map(i128::from).or(n.as_u64().map(i128::from)) {
                Some(v) => {
                    let (lo, hi) = iec_type.int_range().unwrap_or((0, 0));
                    if (lo..=hi).contains(&v) {
                        Ok(())
                    } else {
                        Err(format!("{v} is out of range for {declared} ({lo}..={hi})"))
                    }
                }
                None => Err(format!("{n} is not a whole number ({declared})")),
            }
        }
        (Value::Number(n), TypeFamily::Real) => match n.as_f64() {
            Some(v) if iec_type == IecType::Real && v.abs() > f32::MAX as f64 => Err(format!(
                "{n} is out of range for REAL (at most {:e} either side of 0); use f64 (LREAL)",
                f32::MAX
            )),
            _ => Ok(()),
        },
        (Value::String(s), TypeFamily::String) => {
            let cap = capacity.unwrap_or(DEFAULT_STRING_CAPACITY);
            if s.len() <= cap {
                Ok(())
            } else {
                Err(format!("{} bytes do not fit max_length {cap}", s.len()))
            }
        }
        (other, _) => Err(format!("{} is not a {declared} value", text(other))),
    }
}

/// `source` and `bit`, each checked on its own so that both mistakes show.
fn source_field(obj: &serde_json::Map<String, Value>, r: &mut Report) -> Option<(String, u8)> {
    let source = obj.get("source").map(|s| match s.as_str() {
        Some(s) => Some(s.to_string()),
        None => {
            r.err(
                "source",
                format!("expected a variable name, found {}", text(s)),
            );
            None
        }
    });
    let bit = obj.get("bit").map(|b| match b.as_u64() {
        Some(n) if n <= 63 => Some(n as u8),
        _ => {
            r.err("bit", format!("{} is not a bit number 0..=63", text(b)));
            None
        }
    });
    match (source, bit) {
        (None, None) => None,
        (Some(_), None) => {
            r.err(
                "source",
                "needs `bit`, the bit of the source word (0 = least significant)".into(),
            );
            None
        }
        (None, Some(_)) => {
            r.err(
                "bit",
                "needs `source`, the integer variable that holds the bit".into(),
            );
            None
        }
        (Some(s), Some(b)) => Some((s?, b?)),
    }
}

/// Checks one variable's own fields.
fn one(name: &str, v: &Value, errors: &mut Vec<Issue>) -> Option<Var> {
    let mut r = Report { name, errors };
    if let Err(e) = names::check_name(name) {
        r.err("", format!("invalid variable name: {e} (seed 003)"));
    }
    let Some(obj) = v.as_object() else {
        r.err(
            "",
            format!(
                "expected an object such as {{ \"type\": \"u16\" }}, found {}",
                text(v)
            ),
        );
        return None;
    };
    for key in obj.keys() {
        if !FIELDS.contains(&key.as_str()) {
            r.err(
                key,
                format!("unknown field: use one of {}", FIELDS.join(", ")),
            );
        }
    }
    let declared = declared_type(obj, &mut r);
    let ty = declared.map(|declared| match declared.family() {
        TypeFamily::BitString => (
            IecType::from_rust_name(declared.rust_name()).unwrap_or(declared),
            declared,
        ),
        _ => (declared, declared),
    });
    let iec_type = ty.map(|(t, _)| t);
    let capacity = capacity_field(obj, iec_type, &mut r);
    let dims = dims_field(obj, &mut r);
    let link = str_field(obj, "link", &mut r);
    if let Some(l) = &link
        && let Err(e) = Link::parse(l)
    {
        r.err("link", format!("invalid link {l:?}: {e}"));
    }
    let direction = str_field(obj, "direction", &mut r).and_then(|d| {
        Direction::from_name(&d).or_else(|| {
            r.err(
                "direction",
                format!("unknown direction {d:?}: use input, output, command, status or internal"),
            );
            None
        })
    });
    let at = str_field(obj, "at", &mut r);
    if let Some(a) = &at {
        at_field(a, ty, &dims, direction, &mut r);
    }
    let initial = obj.get("initial").cloned();
    if let (Some(init), Some((iec_type, declared))) = (&initial, ty)
        && let Err(e) = initial_fits(init, iec_type, declared, capacity)
    {
        r.err("initial", e);
    }
    let source = source_field(obj, &mut r);
    let description = str_field(obj, "description", &mut r);
    let nonvolatile = bool_field(obj, "nonvolatile", &mut r) | bool_field(obj, "retain", &mut r);
    let read_only = bool_field(obj, "read_only", &mut r);
    Some(Var {
        spec: Spec {
            name: name.to_string(),
            // A placeholder when the type is unknown: `typed` keeps it out of every check.
            iec_type: iec_type.unwrap_or(IecType::Bool),
            bit_string: ty.and_then(|(t, d)| (t != d).then_some(d)),
            capacity,
            dims,
            link,
            description,
            initial,
            nonvolatile,
            source,
            direction,
            read_only,
            at,
        },
        typed: ty.is_some(),
    })
}

/// The checks of a bit-mapped bool against its source.
fn bit_mappings(vars: &[Var], declared: &HashSet<&str>, errors: &mut Vec<Issue>) {
    // Maps, not searches: a 10,000-variable file must not take quadratic time.
    let by_name: HashMap<&str, &Var> = vars.iter().map(|v| (v.spec.name.as_str(), v)).collect();
    let mut taken: HashMap<(&str, u8), &str> = HashMap::new();
    for v in vars {
        let s = &v.spec;
        let Some((source, bit)) = &s.source else {
            continue;
        };
        let mut r = Report {
            name: &s.name,
            errors,
        };
        if v.typed && (s.iec_type != IecType::Bool || !s.dims.is_empty()) {
            r.err(
                "type",
                format!(
                    "a bit-mapped variable must be bool (seed 000), not {}",
                    s.rust_type()
                ),
            );
        }
        if source == &s.name {
            r.err("source", "a variable cannot be its own source".into());
            continue;
        }
        let Some(src) = by_name.get(source.as_str()) else {
            if !declared.contains(&source.as_str()) {
                let hint = declared
                    .iter()
                    .find(|x| x.eq_ignore_ascii_case(source))
                    .map(|x| format!(" (did you mean {x:?}?)"))
                    .unwrap_or_default();
                r.err("source", format!("{source:?} names no variable{hint}"));
            }
            // Declared but not an object: its own error says so.
            continue;
        };
        if !src.typed {
            // Its missing or unknown type is reported on it; nothing more can be said here.
            continue;
        }
        let src = &src.spec;
        if !src.iec_type.is_integer() || !src.dims.is_empty() {
            r.err(
                "source",
                format!(
                    "{source:?} is {}, but a source must be an integer (u8..u64, i8..i64)",
                    src.rust_type()
                ),
            );
            continue;
        }
        if u32::from(*bit) >= src.iec_type.bits() {
            r.err(
                "bit",
                format!(
                    "{bit} is out of range for source {source:?} ({} has bits 0..={})",
                    src.rust_type(),
                    src.iec_type.bits() - 1
                ),
            );
            continue;
        }
        let source_dir = src.own_direction();
        if let Some(d) = s.direction
            && d != source_dir
        {
            r.err(
                "direction",
                format!(
                    "{:?} contradicts the source {source:?}, which is {}: a bit-mapped bool takes its source's direction; remove `direction`",
                    d.name(),
                    source_dir.name()
                ),
            );
        }
        if let Some(first) = taken.get(&(source.as_str(), *bit)) {
            r.err(
                "bit",
                format!("bit {bit} of {source:?} is already mapped to {first:?}"),
            );
            continue;
        }
        taken.insert((source, *bit), &s.name);
    }
}

/// Checks every variable and the rules between them.
pub fn check(parsed: &Parsed) -> Checked {
    let mut errors: Vec<Issue> = parsed
        .duplicates
        .iter()
        .enumerate()
        .map(|(i, _)| Issue {
            subject: Subject::Duplicate(i),
            field: None,
            message: "declared twice (names are case-insensitive, seed 003)".into(),
        })
        .collect();
    let vars: Vec<Var> = parsed
        .variables
        .iter()
        .filter_map(|(n, v)| one(n, v, &mut errors))
        .collect();
    let declared: HashSet<&str> = parsed.variables.iter().map(|(n, _)| n.as_str()).collect();
    bit_mappings(&vars, &declared, &mut errors);
    let mut warnings = Vec::new();
    let mut linked: HashMap<&str, &str> = HashMap::new();
    for v in &vars {
        let s = &v.spec;
        let Some(l) = &s.link else { continue };
        if let Some(first) = linked.get(l.as_str()) {
            warnings.push(Issue {
                subject: Subject::Var(s.name.clone()),
                field: Some("link".into()),
                message: format!(
                    "{l:?} is also linked by {first:?}: fine for an input; two variables writing one output entry are refused when the bus starts"
                ),
            });
        } else {
            linked.insert(l, &s.name);
        }
    }
    let located: Vec<(&Spec, IecAddress)> = vars
        .iter()
        .filter_map(|v| Some((&v.spec, v.spec.at.as_ref()?.parse().ok()?)))
        .collect();
    for (i, (s, a)) in located.iter().enumerate() {
        if let Some((first, _)) = located[..i].iter().find(|(_, b)| b.overlaps(a)) {
            errors.push(Issue {
                subject: Subject::Var(s.name.clone()),
                field: Some("at".into()),
                message: format!("{a} overlaps the address of {:?}", first.name),
            });
        }
    }
    Checked {
        specs: vars
            .into_iter()
            .filter(|v| v.typed)
            .map(|v| v.spec)
            .collect(),
        errors,
        warnings,
    }
}
