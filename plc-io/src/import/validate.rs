//! Every rule the derive enforces, applied to a JSON variable list before any code is written,
//! so a bad file gets all its errors at once, each naming the variable and the field.

use super::parse::Parsed;
use plc_core::{Direction, IecType, TypeFamily};
use plc_rules::address::{Area, IecAddress, Size};
use plc_rules::capacity::{
    DEFAULT_STRING_CAPACITY, MAX_ARRAY_DIMS, MAX_ARRAY_ITEMS, MAX_STRING_CAPACITY,
};
use plc_rules::link::Link;
use plc_rules::names;
use serde_json::Value;

const FIELDS: [&str; 13] = [
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
}

/// The outcome: checked variables, errors, warnings.
pub struct Checked {
    pub specs: Vec<Spec>,
    pub errors: Vec<String>,
    pub warnings: Vec<String>,
}

fn text(v: &Value) -> String {
    match v {
        Value::String(s) => format!("{s:?}"),
        other => other.to_string(),
    }
}

/// Checks one variable's own fields.
fn one(name: &str, v: &Value, errors: &mut Vec<String>) -> Option<Spec> {
    let mut err = |field: &str, msg: String| {
        errors.push(if field.is_empty() {
            format!("variables.{name}: {msg}")
        } else {
            format!("variables.{name}.{field}: {msg}")
        })
    };
    if let Err(e) = names::check_name(name) {
        err("", format!("invalid variable name: {e} (seed 003)"));
    }
    let Some(obj) = v.as_object() else {
        err(
            "",
            "expected an object such as { \"type\": \"u16\" }".into(),
        );
        return None;
    };
    for key in obj.keys() {
        if !FIELDS.contains(&key.as_str()) {
            err(
                key,
                format!("unknown field: use one of {}", FIELDS.join(", ")),
            );
        }
    }
    let str_field = |key: &str, errs: &mut dyn FnMut(&str, String)| -> Option<String> {
        match obj.get(key)? {
            Value::String(s) => Some(s.clone()),
            other => {
                errs(key, format!("expected a string, found {}", text(other)));
                None
            }
        }
    };
    let bool_field = |key: &str, errs: &mut dyn FnMut(&str, String)| -> bool {
        match obj.get(key) {
            None => false,
            Some(Value::Bool(b)) => *b,
            Some(other) => {
                errs(
                    key,
                    format!("expected true or false, found {}", text(other)),
                );
                false
            }
        }
    };
    let Some(ty_text) = str_field("type", &mut err) else {
        if !obj.contains_key("type") {
            err("type", "missing: every variable needs a type (bool, u8..u64, i8..i64, f32, f64, string, or an IEC name)".into());
        }
        return None;
    };
    let declared: IecType = match ty_text.parse() {
        Ok(t) => t,
        Err(_) => {
            err(
                "type",
                format!(
                    "unknown type {ty_text:?}: use bool, u8..u64, i8..i64, f32, f64, string, or BOOL..LREAL, BYTE..LWORD, STRING"
                ),
            );
            return None;
        }
    };
    let (iec_type, bit_string) = match declared.family() {
        TypeFamily::BitString => (
            IecType::from_rust_name(declared.rust_name()).unwrap_or(declared),
            Some(declared),
        ),
        _ => (declared, None),
    };
    let capacity = match (iec_type, obj.get("max_length")) {
        (IecType::String, None) => Some(DEFAULT_STRING_CAPACITY),
        (IecType::String, Some(v)) => match v.as_u64() {
            Some(n) if (1..=MAX_STRING_CAPACITY as u64).contains(&n) => Some(n as usize),
            _ => {
                err(
                    "max_length",
                    format!("{} is not a capacity of 1..=255 bytes (seed 000)", text(v)),
                );
                Some(DEFAULT_STRING_CAPACITY)
            }
        },
        (_, Some(_)) => {
            err("max_length", "only strings have a max_length".into());
            None
        }
        (_, None) => None,
    };
    let dims: Vec<usize> = match obj.get("dims") {
        None => vec![],
        Some(Value::Array(a)) => {
            let d: Vec<usize> = a
                .iter()
                .filter_map(|x| x.as_u64().map(|n| n as usize))
                .collect();
            let items = d.iter().try_fold(1usize, |acc, &n| acc.checked_mul(n));
            if d.len() != a.len() || d.contains(&0) {
                err("dims", "dimensions are whole numbers of at least 1".into());
                vec![]
            } else if d.is_empty() || d.len() > MAX_ARRAY_DIMS {
                err(
                    "dims",
                    format!("an array has 1 to {MAX_ARRAY_DIMS} dimensions (seed 003)"),
                );
                vec![]
            } else if items.is_none_or(|n| n > MAX_ARRAY_ITEMS) {
                err(
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
            err(
                "dims",
                format!("expected a list such as [3, 4], found {}", text(other)),
            );
            vec![]
        }
    };
    let link = str_field("link", &mut err);
    if let Some(l) = &link
        && let Err(e) = Link::parse(l)
    {
        err("link", format!("invalid link {l:?}: {e}"));
    }
    let direction = str_field("direction", &mut err).and_then(|d| {
        Direction::from_name(&d).or_else(|| {
            err(
                "direction",
                format!("unknown direction {d:?}: use input, output, command, status or internal"),
            );
            None
        })
    });
    let at = str_field("at", &mut err);
    if let Some(a) = &at {
        match a.parse::<IecAddress>() {
            Err(e) => err("at", format!("invalid address {e}")),
            Ok(addr) if addr.area == Area::Memory => err(
                "at",
                format!("{a:?} is in the M area: `at` locates I/O channels (%I or %Q)"),
            ),
            Ok(addr) => {
                let width = if iec_type == IecType::Bool {
                    1
                } else {
                    iec_type.bits()
                };
                if !dims.is_empty() || iec_type == IecType::String {
                    err(
                        "at",
                        "only a scalar of a basic type can be located (seed 003)".into(),
                    );
                } else if Size::from_bits(width) != Some(addr.size) {
                    err(
                        "at",
                        format!(
                            "{a:?} is {} bits but a {} has {width}",
                            addr.size.bits(),
                            declared
                        ),
                    );
                } else if !addr.is_aligned() {
                    err(
                        "at",
                        format!(
                            "{a:?} is not aligned to {} bytes (seed 004)",
                            addr.size.bytes()
                        ),
                    );
                }
                let implied = if addr.area == Area::Input {
                    Direction::Input
                } else {
                    Direction::Output
                };
                if direction.is_some_and(|d| d != implied) {
                    err(
                        "direction",
                        format!(
                            "contradicts `at` {a:?}, which makes it an {}",
                            implied.name()
                        ),
                    );
                }
            }
        }
    }
    let initial = obj.get("initial").cloned();
    if let Some(init) = &initial {
        let fits = match (init, iec_type.family()) {
            (Value::Bool(_), TypeFamily::Bool) => Ok(()),
            (Value::Number(n), f) if iec_type.is_integer() => {
                match n.as_i64().map(i128::from).or(n.as_u64().map(i128::from)) {
                    Some(v) => {
                        let (lo, hi) = iec_type.int_range().unwrap_or((0, 0));
                        if (lo..=hi).contains(&v) {
                            Ok(())
                        } else {
                            Err(format!(
                                "{v} is out of range for {} ({lo}..={hi})",
                                declared
                            ))
                        }
                    }
                    None => {
                        let _ = f;
                        Err(format!("{n} is not a whole number ({declared})"))
                    }
                }
            }
            (Value::Number(n), TypeFamily::Real) => match n.as_f64() {
                Some(v) if iec_type == IecType::Real && v.abs() > f32::MAX as f64 => {
                    Err(format!("{n} is out of range for REAL"))
                }
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
        };
        if let Err(e) = fits {
            err("initial", e);
        }
    }
    let source = match (obj.get("source"), obj.get("bit")) {
        (None, None) => None,
        (Some(_), None) => {
            err(
                "source",
                "needs `bit`, the bit of the source word (0 = least significant)".into(),
            );
            None
        }
        (None, Some(_)) => {
            err(
                "bit",
                "needs `source`, the integer variable that holds the bit".into(),
            );
            None
        }
        (Some(s), Some(b)) => match (s.as_str(), b.as_u64()) {
            (Some(s), Some(b)) if b <= 63 => Some((s.to_string(), b as u8)),
            (None, _) => {
                err(
                    "source",
                    format!("expected a variable name, found {}", text(s)),
                );
                None
            }
            _ => {
                err("bit", format!("{} is not a bit number 0..=63", text(b)));
                None
            }
        },
    };
    let description = str_field("description", &mut err);
    let nonvolatile = bool_field("nonvolatile", &mut err) || bool_field("retain", &mut err);
    let read_only = bool_field("read_only", &mut err);
    Some(Spec {
        name: name.to_string(),
        iec_type,
        bit_string,
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
    })
}

/// Checks every variable and the rules between them.
pub fn check(parsed: &Parsed) -> Checked {
    let mut errors: Vec<String> = parsed
        .duplicates
        .iter()
        .map(|n| format!("variables.{n}: declared twice (names are case-insensitive, seed 003)"))
        .collect();
    let specs: Vec<Spec> = parsed
        .variables
        .iter()
        .filter_map(|(n, v)| one(n, v, &mut errors))
        .collect();
    let mut warnings = Vec::new();
    let mut taken: Vec<(&str, u8, &str)> = Vec::new();
    for s in &specs {
        let Some((source, bit)) = &s.source else {
            continue;
        };
        let e = |m: String| format!("variables.{}.{m}", s.name);
        if s.iec_type != IecType::Bool || !s.dims.is_empty() {
            errors.push(e(format!(
                "type: a bit-mapped variable must be bool (seed 000), not {}",
                s.rust_type()
            )));
        }
        let Some(src) = specs.iter().find(|x| &x.name == source) else {
            let hint = specs
                .iter()
                .find(|x| x.name.eq_ignore_ascii_case(source))
                .map(|x| format!(" (did you mean {:?}?)", x.name))
                .unwrap_or_default();
            errors.push(e(format!("source: {source:?} names no variable{hint}")));
            continue;
        };
        if src.name == s.name {
            errors.push(e("source: a variable cannot be its own source".into()));
            continue;
        }
        if !src.iec_type.is_integer() || !src.dims.is_empty() {
            errors.push(e(format!(
                "source: {source:?} is {}, but a source must be an integer (u8..u64, i8..i64)",
                src.rust_type()
            )));
            continue;
        }
        if u32::from(*bit) >= src.iec_type.bits() {
            errors.push(e(format!(
                "bit: {bit} is out of range for source {source:?} ({} has bits 0..={})",
                src.rust_type(),
                src.iec_type.bits() - 1
            )));
            continue;
        }
        if let Some((_, _, first)) = taken.iter().find(|(n, b, _)| *n == source && b == bit) {
            errors.push(e(format!(
                "bit: bit {bit} of {source:?} is already mapped to {first:?}"
            )));
            continue;
        }
        taken.push((source, *bit, &s.name));
    }
    for (i, s) in specs.iter().enumerate() {
        if let Some(l) = &s.link
            && let Some(first) = specs[..i].iter().find(|x| x.link.as_ref() == Some(l))
        {
            warnings.push(format!(
                "variables.{}.link: {l:?} is also linked by {:?}: fine for an input; two variables writing one output entry are refused when the bus starts",
                s.name, first.name
            ));
        }
    }
    let located: Vec<(&Spec, IecAddress)> = specs
        .iter()
        .filter_map(|s| Some((s, s.at.as_ref()?.parse().ok()?)))
        .collect();
    for (i, (s, a)) in located.iter().enumerate() {
        if let Some((first, _)) = located[..i].iter().find(|(_, b)| b.overlaps(a)) {
            errors.push(format!(
                "variables.{}.at: {a} overlaps the address of {:?}",
                s.name, first.name
            ));
        }
    }
    Checked {
        specs,
        errors,
        warnings,
    }
}
