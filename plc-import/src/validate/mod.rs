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

mod alarm;
mod blocks;
mod fields;
mod graph;
mod outcome;
mod read;
mod types;
mod wording;

pub use outcome::{Checked, CheckedType, Group, ListAt, Problem, TypeProblem};
pub use wording::{Lines, ListWording};

use crate::parse::Parsed;
use blocks::standard_group;
use fields::TypeNames;
use graph::{group_size, nesting, walk_types};
use plc_rules::capacity::MAX_IMAGE_BYTES;
use read::read_group;
use serde_json::Value;
use std::collections::HashMap;
use types::type_rules;

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
    let standard = crate::standard::blocks();
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
mod agreement;
