//! The rules of one type of the `types` section as a whole: its name, its fields and its
//! members object.

use super::outcome::TypeProblem;
use super::wording::text;
use crate::parse::TypeDef;
use plc_core::IecType;

/// The fields a type may have.
const TYPE_FIELDS: [&str; 2] = ["description", "variables"];

/// The problems of one type as a whole: its name, fields and members object.
pub(super) fn type_rules(t: usize, def: &TypeDef, duplicate_of: Option<&str>) -> Vec<TypeProblem> {
    let mut out = Vec::new();
    let mut problem = |field: Option<&str>, message: String| {
        out.push(TypeProblem {
            ty: t,
            field: field.map(str::to_string),
            message,
        })
    };
    if crate::standard::is_standard(&def.name) {
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
