//! The keys of `#[plc(...)]`, for messages that list them. The darling receivers in `attr`
//! define the keys themselves (by field name); a test keeps this list and them in step.

/// The attribute's path: `#[plc(...)]`.
pub const PLC: &str = "plc";

/// Field keys: those of every declaration format, then the derive's own.
pub fn field_keys() -> impl Iterator<Item = &'static str> {
    plc_rules::decl::ATTRIBUTE_KEYS
        .iter()
        .chain(["name", "iec_type", "alarm_when"].iter())
        .copied()
}

/// Container keys.
pub const CONTAINER_KEYS: &[&str] = &["crate", "byte_order", "unaligned", "bus", "name"];

/// What a key's value looks like, for "wrong kind of value" messages.
pub fn expects(key: &str) -> Option<&'static str> {
    Some(match key {
        "link" => "a string such as \"ethercat.io_0.inputs\"",
        "source" => "the name of an integer field as a string, such as \"inputs\"",
        "bit" => "a bit number such as `3`",
        "at" => "an address string such as \"%IW4\"",
        "description" => "a string",
        "direction" => "a string: \"input\", \"output\", \"command\", \"status\" or \"internal\"",
        "name" => "a string",
        "iec_type" => "a string such as \"WORD\"",
        "quantity" => "a string such as \"force\"",
        "unit" => "a string such as \"mm\"",
        "deadband" => "a number of 0 or more, such as `0.5`",
        "alarm" => "its text, `alarm = \"Guard door open\"`, or `alarm(text = \"...\", ...)`",
        "alarm_when" => "`true` or `false`",
        "crate" => "a path as a string, such as \"::plc_core\"",
        "byte_order" => "\"little\" or \"big\"",
        "bus" => "the path of a bus description as a string, such as \"bus/machine.toml\"",
        _ => return None,
    })
}

/// `` `a`, `b` and `c` ``: all of the keys, as "the keys are ..." lists them.
pub fn list<'a>(keys: impl IntoIterator<Item = &'a str>) -> String {
    let quoted: Vec<String> = keys.into_iter().map(|k| format!("`{k}`")).collect();
    match quoted.split_last() {
        Some((last, rest)) if !rest.is_empty() => format!("{} and {last}", rest.join(", ")),
        _ => quoted.concat(),
    }
}

#[cfg(test)]
mod tests {
    use super::{CONTAINER_KEYS, field_keys};
    use crate::attr::{ContainerAttr, FieldAttr};
    use darling::{FromDeriveInput, FromField};
    use syn::parse::Parser;

    fn unknown(e: darling::Error) -> bool {
        e.flatten()
            .into_iter()
            .any(|e| e.to_string().starts_with("Unknown field"))
    }

    #[test]
    fn a_list_of_all_keys_ends_with_and() {
        assert_eq!(
            super::list(["crate", "byte_order", "unaligned"]),
            "`crate`, `byte_order` and `unaligned`"
        );
        assert_eq!(super::list(["crate"]), "`crate`");
    }

    #[test]
    fn every_listed_key_is_a_key_of_the_receivers() {
        for key in field_keys() {
            let src = format!("#[plc({key} = 1)] x: u8");
            let field = syn::Field::parse_named.parse_str(&src).unwrap();
            if let Err(e) = FieldAttr::from_field(&field) {
                assert!(!unknown(e), "field key `{key}`");
            }
        }
        for key in CONTAINER_KEYS {
            let src = format!("#[plc({key} = 1)] struct S {{ x: u8 }}");
            let input: syn::DeriveInput = syn::parse_str(&src).unwrap();
            if let Err(e) = ContainerAttr::from_derive_input(&input) {
                assert!(!unknown(e), "container key `{key}`");
            }
        }
    }
}
