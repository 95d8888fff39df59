//! One declaration (the list's variables or a type's members) read and checked: each variable
//! read into the model, then the declaration's rules, worded for the list.

use super::fields::{Declared, Reader, TypeNames};
use super::outcome::{Group, ListAt, Problem, StructUse};
use super::wording::{ListWording, text};
use crate::parse::Parsed;
use plc_core::{IecType, TypeFamily};
use plc_rules::decl::{self, ATTRIBUTE_KEYS, Decl, DeclType, KnownType, Located, Wording};
use serde_json::Value;
use std::borrow::Cow;

/// The fields a variable may have besides the attributes of every format: its type, a
/// string's capacity, an array's dimensions.
const LIST_FIELDS: [&str; 3] = ["type", "max_length", "dims"];

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
    model.unit = r.string("unit");
    model.deadband = r.number("deadband");
    model.alarm = r.alarm();
    if structured.is_some() {
        r.structure_as_a_whole(&mut model);
    }
    (model, structured)
}

/// Reads and checks one declaration: the list's variables (`ty` `None`) or a type's members.
pub(super) fn read_group(
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
