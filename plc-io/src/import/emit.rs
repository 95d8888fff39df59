//! Writing the checked variables as a Rust module: one `#[derive(GlobalMemory)]` struct, doc
//! comments from descriptions, every declared property as a `#[plc(...)]` key, formatted as
//! prettyplease formats it (short lines written directly, long ones by prettyplease).

use super::validate::Spec;
use serde_json::Value;

/// Rust's keywords: a variable of one of these names becomes a raw identifier (`r#type`).
const KEYWORDS: &[&str] = &[
    "as", "async", "await", "break", "const", "continue", "dyn", "else", "enum", "extern", "false",
    "fn", "for", "gen", "if", "impl", "in", "let", "loop", "match", "mod", "move", "mut", "pub",
    "ref", "return", "static", "struct", "trait", "true", "try", "type", "unsafe", "use", "where",
    "while", "abstract", "become", "box", "do", "final", "macro", "override", "priv", "typeof",
    "unsized", "virtual", "yield",
];

/// Names that cannot be fields at all, not even raw.
pub const UNUSABLE: &[&str] = &["self", "Self", "super", "crate", "_"];

fn ident(name: &str) -> String {
    if KEYWORDS.contains(&name) {
        format!("r#{name}")
    } else {
        name.to_string()
    }
}

fn literal(v: &Value) -> String {
    match v {
        Value::String(s) => format!("{s:?}"),
        other => other.to_string(),
    }
}

/// The origin goes into comments: one line, whatever the file name holds.
fn one_line(text: &str) -> String {
    text.chars()
        .map(|c| if c.is_control() { ' ' } else { c })
        .collect()
}

/// The `use` line, the struct's doc and attributes and its opening line, formatted.
fn head(specs: &[Spec], struct_name: &str, origin: &str) -> String {
    let strings = specs.iter().any(|s| s.capacity.is_some());
    let mut out = format!(
        "use plc_core::{};\n\
         /// The variables of {}.\n\
         #[derive(GlobalMemory, Debug, Clone)]\n",
        if strings {
            "{FixedString, GlobalMemory}"
        } else {
            "GlobalMemory"
        },
        origin.trim_end()
    );
    if specs
        .iter()
        .any(|s| s.name.chars().any(|c| c.is_ascii_uppercase()))
    {
        out.push_str("#[allow(non_snake_case)]\n");
    }
    out.push_str(&format!("pub struct {struct_name} {{\n"));
    out
}

/// One field: doc comment, `#[plc(...)]`, declaration; formatted as prettyplease formats it
/// when each line is short (longer lines are left to prettyplease, see [`emit`]).
fn field(s: &Spec, origin: &str) -> String {
    let mut out = String::new();
    let described = s.description.as_deref().filter(|d| !d.trim().is_empty());
    match described {
        // A bare CR ends a line too: Rust refuses one inside a doc comment.
        Some(d) => {
            for line in d.split(['\r', '\n']).filter(|l| !l.trim().is_empty()) {
                out.push_str(&format!("    /// {}\n", line.trim()));
            }
        }
        // Every public field gets a doc comment (so the module passes `missing_docs`);
        // `description = ""` keeps this one out of `VARIABLES`, as the file has none.
        None => out.push_str(&format!(
            "    /// No description in {}.\n",
            origin.trim_end()
        )),
    }
    let mut keys: Vec<String> = Vec::new();
    if let Some(l) = &s.link {
        keys.push(format!("link = {l:?}"));
    }
    if let Some((src, bit)) = &s.source {
        keys.push(format!("source = {src:?}, bit = {bit}"));
    }
    if let Some(a) = &s.at {
        keys.push(format!("at = {a:?}"));
    }
    if let Some(d) = s.direction {
        keys.push(format!("direction = {:?}", d.name()));
    }
    if let Some(t) = s.bit_string {
        keys.push(format!("iec_type = {:?}", t.name()));
    }
    if let Some(i) = &s.initial {
        keys.push(format!("initial = {}", literal(i)));
    }
    if s.nonvolatile {
        keys.push("nonvolatile".into());
    }
    if s.read_only {
        keys.push("read_only".into());
    }
    if described.is_none() {
        keys.push("description = \"\"".into());
    }
    if !keys.is_empty() {
        out.push_str(&format!("    #[plc({})]\n", keys.join(", ")));
    }
    out.push_str(&format!("    pub {}: {},\n", ident(&s.name), s.rust_type()));
    out
}

/// Lines up to this many bytes are printed by prettyplease as they are written here (its
/// margin is 89 columns); a field with a longer line goes through prettyplease, which breaks
/// it.
const SHORT_LINE: usize = 80;

/// A field with a long line, formatted by prettyplease inside a struct of its own: the lines
/// between the struct's braces are what the whole struct would hold.
fn field_by_prettyplease(text: &str) -> Result<String, String> {
    let file = syn::parse_file(&format!("struct S {{\n{text}}}\n"))
        .map_err(|e| format!("generated code does not parse ({e}); please report this"))?;
    let printed = prettyplease::unparse(&file);
    let inner = printed
        .strip_prefix("struct S {\n")
        .and_then(|p| p.strip_suffix("}\n"))
        .ok_or_else(|| format!("prettyplease printed {printed:?}; please report this"))?;
    Ok(inner.to_string())
}

/// The module, formatted as prettyplease formats it. Writing it directly is ten times faster
/// than parsing and printing 10,000 fields (issue 9); the fields that prettyplease would break
/// across lines are still printed by it, and a test checks the whole against prettyplease.
pub fn emit(specs: &[Spec], struct_name: &str, origin: &str) -> Result<String, String> {
    let origin = one_line(origin);
    // A plain comment (not `//!`), so the module can also be `include!`d.
    let mut out = format!(
        "// Generated by `plc import` from {origin}: edit that file and import again.\n\n{}",
        head(specs, struct_name, &origin)
    );
    if specs.is_empty() {
        // prettyplease closes an empty struct on its opening line.
        out.truncate(out.len() - 1);
        out.push_str("}\n");
        return Ok(out);
    }
    for s in specs {
        let text = field(s, &origin);
        let long = text
            .lines()
            .any(|l| l.len() > SHORT_LINE && !l.trim_start().starts_with("///"));
        if long {
            out.push_str(&field_by_prettyplease(&text)?);
        } else {
            out.push_str(&text);
        }
    }
    out.push_str("}\n");
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use plc_core::{Direction, IecType};
    use proptest::prelude::*;

    /// The whole module through syn and prettyplease, as the importer made it before: what
    /// [`emit`] must equal.
    fn by_prettyplease(specs: &[Spec], struct_name: &str, origin: &str) -> String {
        let origin = one_line(origin);
        let mut text = head(specs, struct_name, &origin);
        for s in specs {
            text.push_str(&field(s, &origin));
        }
        text.push_str("}\n");
        let file = syn::parse_file(&text).unwrap();
        format!(
            "// Generated by `plc import` from {origin}: edit that file and import again.\n\n{}",
            prettyplease::unparse(&file)
        )
    }

    fn spec() -> impl Strategy<Value = Spec> {
        let name = "[a-zA-Z][a-zA-Z0-9_]{0,40}";
        let text = prop_oneof![
            Just(None),
            "\\PC{0,60}".prop_map(Some),
            "[ a-z\r\n]{0,90}".prop_map(Some)
        ];
        let initial = prop_oneof![
            Just(None),
            any::<i64>().prop_map(|n| Some(Value::from(n))),
            any::<f64>().prop_map(|n| Some(Value::from(n))),
            any::<bool>().prop_map(|b| Some(Value::from(b))),
            "\\PC{0,40}".prop_map(|s| Some(Value::from(s))),
        ];
        let ty = prop::sample::select(vec![
            IecType::Bool,
            IecType::Uint,
            IecType::Lreal,
            IecType::String,
            IecType::Ulint,
        ]);
        let dims = prop::collection::vec(1usize..70000, 0..4);
        let direction =
            prop::sample::select(vec![None, Some(Direction::Input), Some(Direction::Status)]);
        (
            name,
            text,
            initial,
            ty,
            dims,
            direction,
            "[a-z_]{1,30}",
            any::<[bool; 6]>(),
        )
            .prop_map(
                |(name, description, initial, iec_type, dims, direction, word, flags)| Spec {
                    capacity: (iec_type == IecType::String).then_some(255),
                    bit_string: flags[0].then_some(IecType::Lword),
                    link: flags[1].then(|| format!("ethercat.{word}.{word}")),
                    source: flags[2].then(|| (word.clone(), 63)),
                    at: flags[3].then(|| "%QL8".to_string()),
                    nonvolatile: flags[4],
                    read_only: flags[5],
                    name,
                    iec_type,
                    dims,
                    description,
                    initial,
                    direction,
                },
            )
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(500))]

        #[test]
        fn direct_output_is_what_prettyplease_prints(
            specs in prop::collection::vec(spec(), 0..6),
            origin in "\\PC{0,100}",
        ) {
            prop_assert_eq!(emit(&specs, "Gm", &origin).unwrap(), by_prettyplease(&specs, "Gm", &origin));
        }
    }
}
