//! Writing the checked variables as a Rust module: one `#[derive(PlcStruct)]` struct per type
//! of the list's `types`, in dependency order, then one `#[derive(GlobalMemory)]` struct; doc
//! comments from descriptions, every declared property as a `#[plc(...)]` key, formatted as
//! prettyplease formats it (short lines written directly, long ones by prettyplease).

use super::validate::{Checked, CheckedType, Group, ListAt};
use plc_rules::IecType;
use plc_rules::decl::Var;

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

/// Names the generated module defines or imports: a struct of one of these names would not
/// compile (or would shadow what the module needs).
const TAKEN: &[&str] = &[
    "GlobalMemory",
    "FixedString",
    "PlcStruct",
    "Time",
    "Self",
    "_",
];

/// The Rust name of a structure type: its name made an upper camel case identifier (`axis_t`
/// is `AxisT`, `AXIS` is `Axis`), as Rust names types; a part in capitals keeps only its first
/// one, so the name passes clippy's acronym lint.
pub fn rust_type_name(type_name: &str) -> String {
    let mut out = String::with_capacity(type_name.len());
    for part in type_name.split('_').filter(|p| !p.is_empty()) {
        let all_caps = !part.chars().any(|c| c.is_ascii_lowercase());
        for (i, c) in part.chars().enumerate() {
            match (i, all_caps) {
                (0, _) => out.push(c.to_ascii_uppercase()),
                (_, true) => out.push(c.to_ascii_lowercase()),
                (_, false) => out.push(c),
            }
        }
    }
    out
}

/// Whether the types' Rust names give code that compiles: each a name the module does not use
/// itself (the program's struct, an import), and no two the same. Errors read `types.<name>:
/// ...`, the placing of the caller's format.
pub fn check_type_names(checked: &Checked, struct_name: &str) -> Vec<(usize, String)> {
    let mut errors = Vec::new();
    let mut seen: std::collections::HashMap<String, usize> = std::collections::HashMap::new();
    for (t, ty) in checked.listed().filter(|(_, t)| !t.duplicate) {
        let rust = rust_type_name(&ty.name);
        if rust == struct_name || TAKEN.contains(&rust.as_str()) || rust.is_empty() {
            errors.push((
                t,
                format!(
                    "the type's Rust name {rust:?} is a name the generated module uses \
                     ({struct_name}, {}): rename the type",
                    TAKEN[..4].join(", ")
                ),
            ));
        } else if let Some(&first) = seen.get(&rust) {
            errors.push((
                t,
                format!(
                    "the type's Rust name {rust:?} is that of the type {:?} too: rename one",
                    checked.types[first].name
                ),
            ));
        } else {
            seen.insert(rust, t);
        }
    }
    errors
}

/// Whether the struct name gives code that compiles: an identifier, not a keyword, not a name
/// the module imports.
pub fn check_struct_name(name: &str) -> Result<(), String> {
    if !plc_rules::link::is_identifier(name) {
        return Err(format!(
            "struct name {name:?} is not a Rust identifier: use letters, digits and \
             underscores, not starting with a digit (such as Gm)"
        ));
    }
    if KEYWORDS.contains(&name) || UNUSABLE.contains(&name) || TAKEN.contains(&name) {
        return Err(format!(
            "struct name {name:?} is a Rust keyword or a name the generated module uses \
             ({}): choose another, such as Gm",
            TAKEN[..2].join(", ")
        ));
    }
    Ok(())
}

/// Characters that do not belong in a comment line: the bidirectional text controls, which
/// rustc refuses (they can make code read differently from what it does), and control
/// characters other than the line ends (which split a description into lines); a tab too,
/// which clippy refuses in doc comments.
fn breaks_comment(c: char) -> bool {
    matches!(c, '\u{202A}'..='\u{202E}' | '\u{2066}'..='\u{2069}')
        || (c.is_control() && !matches!(c, '\n' | '\r'))
}

/// One line of a doc comment, with what does not belong there made a space.
fn comment_line(text: &str) -> String {
    text.chars()
        .map(|c| if breaks_comment(c) { ' ' } else { c })
        .collect()
}

/// The origin goes into comments: one line, whatever the file name holds.
fn one_line(text: &str) -> String {
    comment_line(text).replace(['\r', '\n'], " ")
}

/// The `use` line of the module: what its structs need.
fn use_line(checked: &Checked) -> String {
    let groups = checked
        .listed()
        .map(|(_, t)| &t.group)
        .chain([&checked.top]);
    let uses = |test: fn(&plc_rules::decl::KnownType) -> bool| {
        groups
            .clone()
            .flat_map(|g| &g.decl.vars[..g.declared])
            .any(|v| v.ty.value.known().is_some_and(test))
    };
    let mut names = Vec::new();
    if uses(|k| k.capacity.is_some()) {
        names.push("FixedString");
    }
    names.push("GlobalMemory");
    if checked.listed().next().is_some() {
        names.push("PlcStruct");
    }
    if uses(|k| k.iec == IecType::Ltime) {
        names.push("Time");
    }
    match names.as_slice() {
        [one] => format!("use plc_core::{one};\n"),
        more => format!("use plc_core::{{{}}};\n", more.join(", ")),
    }
}

/// What a struct is: the program's variables or a structure type.
enum Kind<'a> {
    /// The `GlobalMemory`, with the module's origin.
    Program { origin: &'a str },
    /// A `PlcStruct`: its type name and description.
    Structure { name: &'a str, description: &'a str },
}

/// A struct's doc and attributes and its opening line, formatted.
fn head(vars: &[Var<ListAt>], struct_name: &str, kind: &Kind) -> String {
    let mut out = match kind {
        Kind::Program { origin } => format!(
            "/// The variables of {}.\n#[derive(GlobalMemory, Debug, Clone)]\n",
            origin.trim_end()
        ),
        Kind::Structure { name, description } => {
            let mut doc = String::new();
            for line in description
                .split(['\r', '\n'])
                .map(comment_line)
                .filter(|l| !l.trim().is_empty())
            {
                doc.push_str(&format!("/// {}\n", line.trim()));
            }
            if doc.is_empty() {
                doc = format!("/// The structure {name}.\n");
            }
            doc.push_str("#[derive(PlcStruct, Debug, Clone, Copy, PartialEq)]\n");
            if *name != struct_name {
                doc.push_str(&format!("#[plc(name = {name:?})]\n"));
            }
            doc
        }
    };
    if vars
        .iter()
        .any(|v| v.name.value.chars().any(|c| c.is_ascii_uppercase()))
    {
        out.push_str("#[allow(non_snake_case)]\n");
    }
    out.push_str(&format!("pub struct {struct_name} {{\n"));
    out
}

/// One field: doc comment, `#[plc(...)]`, declaration; formatted as prettyplease formats it
/// when each line is short (longer lines are left to prettyplease, see [`emit`]).
fn field(v: &Var<ListAt>, rust_type: &str, origin: &str) -> String {
    let mut out = String::new();
    let description = v.description.trim();
    // A description rustc would refuse in a comment keeps its exact text in `description`,
    // as an escaped string; the doc comment gets it with those characters made spaces.
    let as_key = description.chars().any(breaks_comment);
    match description.is_empty() {
        // A bare CR ends a line too: Rust refuses one inside a doc comment.
        false => {
            for line in description
                .split(['\r', '\n'])
                .map(comment_line)
                .filter(|l| !l.trim().is_empty())
            {
                out.push_str(&format!("    /// {}\n", line.trim()));
            }
        }
        // Every public field gets a doc comment (so the module passes `missing_docs`);
        // `description = ""` keeps this one out of `VARIABLES`, as the file has none.
        true => out.push_str(&format!(
            "    /// No description in {}.\n",
            origin.trim_end()
        )),
    }
    let mut keys: Vec<String> = Vec::new();
    if let Some(l) = &v.link {
        keys.push(format!("link = {:?}", l.value));
    }
    if let (Some(src), Some(bit)) = (&v.source, &v.bit) {
        keys.push(format!("source = {:?}, bit = {}", src.value, bit.value));
    }
    if let Some(a) = &v.at {
        keys.push(format!("at = {:?}", a.value));
    }
    if let Some(d) = &v.direction {
        keys.push(format!("direction = {:?}", d.value.name()));
    }
    if let Some(t) = &v.iec_type {
        keys.push(format!("iec_type = {:?}", t.value.name()));
    }
    if let Some(i) = &v.initial {
        keys.push(format!("initial = {}", i.value.text));
    }
    if v.nonvolatile {
        keys.push("nonvolatile".into());
    }
    if v.read_only {
        keys.push("read_only".into());
    }
    if v.ux {
        keys.push("ux".into());
    }
    if let Some(q) = &v.quantity {
        keys.push(format!("quantity = {:?}", q.value));
    }
    if let Some(u) = &v.unit {
        keys.push(format!("unit = {:?}", u.value));
    }
    if let Some(d) = &v.deadband {
        keys.push(format!("deadband = {}", d.value));
    }
    if let Some(a) = &v.alarm {
        keys.push(crate::alarm_attr::attribute(a));
    }
    if description.is_empty() {
        keys.push("description = \"\"".into());
    } else if as_key {
        keys.push(format!("description = {description:?}"));
    }
    if !keys.is_empty() {
        out.push_str(&format!("    #[plc({})]\n", keys.join(", ")));
    }
    out.push_str(&format!("    pub {}: {rust_type},\n", ident(&v.name.value)));
    out
}

/// The Rust name of a type: a standard function block by its path in plc-core.
fn rust_name_of(ty: &CheckedType) -> String {
    ty.standard
        .map_or_else(|| rust_type_name(&ty.name), str::to_string)
}

/// The Rust type of each variable of a group: a basic type as the model writes it, a
/// structure by its type's Rust name, in arrays as dimensioned.
fn rust_types(group: &Group, checked: &Checked) -> Result<Vec<String>, String> {
    let vars = group.decl.vars.iter().zip(&group.structured);
    vars.take(group.declared)
        .map(|(v, s)| match (s, v.ty.value.known()) {
            (Some(s), _) => Ok(s
                .dims
                .iter()
                .rev()
                .fold(rust_name_of(&checked.types[s.ty]), |inner, d| {
                    format!("[{inner}; {d}]")
                })),
            (None, Some(k)) => Ok(k.rust_type()),
            // Every generated variable has a type: one without is an error before emission.
            (None, None) => Err(format!(
                "variable {:?} has no type but reached the code generator; please report this",
                v.name.value
            )),
        })
        .collect()
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

/// One struct, formatted as prettyplease formats it. Writing it directly is ten times faster
/// than parsing and printing 10,000 fields (the repository's BENCHMARKS.md, `import_10k_ms`); the fields that
/// prettyplease would break across lines are still printed by it, and a test checks the whole
/// against prettyplease.
fn emit_struct(
    vars: &[Var<ListAt>],
    types: &[String],
    struct_name: &str,
    kind: &Kind,
    origin: &str,
) -> Result<String, String> {
    let mut out = head(vars, struct_name, kind);
    if vars.is_empty() {
        // prettyplease closes an empty struct on its opening line.
        out.truncate(out.len() - 1);
        out.push_str("}\n");
        return Ok(out);
    }
    for (v, ty) in vars.iter().zip(types) {
        let text = field(v, ty, origin);
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

/// The module: the `use` line, the structure types in dependency order, the program's struct.
pub fn emit(checked: &Checked, struct_name: &str, origin: &str) -> Result<String, String> {
    let origin = one_line(origin);
    // A plain comment (not `//!`), so the module can also be `include!`d.
    let mut out = format!(
        "// Generated by `plc import` from {origin}: edit that file and import again.\n\n{}",
        use_line(checked)
    );
    for &t in &checked.order {
        let ty = &checked.types[t];
        if ty.standard.is_some() {
            continue;
        }
        let kind = Kind::Structure {
            name: &ty.name,
            description: ty.description.trim(),
        };
        let g = &ty.group;
        let types = rust_types(g, checked)?;
        let rust = rust_type_name(&ty.name);
        out.push_str(&emit_struct(
            &g.decl.vars[..g.declared],
            &types,
            &rust,
            &kind,
            &origin,
        )?);
    }
    let g = &checked.top;
    let types = rust_types(g, checked)?;
    let kind = Kind::Program { origin: &origin };
    out.push_str(&emit_struct(
        &g.decl.vars[..g.declared],
        &types,
        struct_name,
        &kind,
        &origin,
    )?);
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use plc_core::{Direction, IecType};
    use plc_rules::decl::{Initial, InitialValue, KnownType, Located};
    use proptest::prelude::*;

    /// The whole struct through syn and prettyplease, as the importer made it before: what
    /// [`emit_struct`] must equal.
    fn by_prettyplease(
        vars: &[Var<ListAt>],
        types: &[String],
        kind: &Kind,
        origin: &str,
    ) -> String {
        let mut text = head(vars, "Gm", kind);
        for (v, ty) in vars.iter().zip(types) {
            text.push_str(&field(v, ty, origin));
        }
        text.push_str("}\n");
        prettyplease::unparse(&syn::parse_file(&text).unwrap())
    }

    #[test]
    fn type_names_become_upper_camel_case() {
        for (name, rust) in [
            ("Axis", "Axis"),
            ("axis_t", "AxisT"),
            ("AXIS", "Axis"),
            ("TON", "Ton"),
            ("myAxis_2", "MyAxis2"),
            ("_station", "Station"),
        ] {
            assert_eq!(rust_type_name(name), rust, "{name}");
        }
    }

    fn at() -> ListAt {
        ListAt {
            ty: None,
            var: 0,
            field: None,
        }
    }

    fn initial(value: InitialValue, text: String) -> Option<Located<Initial, ListAt>> {
        Some(Located::new(Initial { value, text }, at()))
    }

    fn var() -> impl Strategy<Value = Var<ListAt>> {
        let name = "[a-zA-Z][a-zA-Z0-9_]{0,40}";
        let text = prop_oneof![
            Just(String::new()),
            "\\PC{0,60}",
            "[ a-z\r\n]{0,90}",
            "[a\u{202e}\u{2066}\u{7} ]{0,10}",
        ];
        let initial = prop_oneof![
            Just(None),
            any::<i64>().prop_map(|n| initial(InitialValue::Int(n.into()), n.to_string())),
            any::<f64>().prop_map(|n| initial(
                InitialValue::Float(n),
                serde_json::Value::from(n).to_string()
            )),
            any::<bool>().prop_map(|b| initial(InitialValue::Bool(b), b.to_string())),
            "\\PC{0,40}".prop_map(|s| initial(InitialValue::Text(s.clone()), format!("{s:?}"))),
        ];
        let ty = prop::sample::select(vec![
            IecType::Bool,
            IecType::Uint,
            IecType::Lreal,
            IecType::String,
            IecType::Ulint,
            IecType::Ltime,
        ]);
        let dims = prop::collection::vec(1u64..70000, 0..4);
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
                |(name, description, initial, iec, dims, direction, word, flags)| {
                    let known = KnownType {
                        iec,
                        capacity: (iec == IecType::String).then_some(255),
                        dims,
                    };
                    let mut v = Var::new(
                        Located::new(name.clone(), at()),
                        &name,
                        Located::new(known.into(), at()),
                    );
                    let located = |s: String| Some(Located::new(s, at()));
                    v.iec_type = flags[0].then(|| Located::new(IecType::Lword, at()));
                    v.link = flags[1]
                        .then(|| format!("ethercat.{word}.{word}"))
                        .and_then(located);
                    if flags[2] {
                        v.source = located(word.clone());
                        v.bit = Some(Located::new(63, at()));
                    }
                    v.at = flags[3].then(|| "%QL8".to_string()).and_then(located);
                    v.nonvolatile = flags[4];
                    v.read_only = flags[5];
                    v.description = description;
                    v.initial = initial;
                    v.direction = direction.map(|d| Located::new(d, at()));
                    v
                },
            )
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(500))]

        #[test]
        fn direct_output_is_what_prettyplease_prints(
            vars in prop::collection::vec(var(), 0..6),
            origin in "\\PC{0,100}",
            description in prop_oneof![Just(String::new()), "\\PC{0,60}", "[ a-z\r\n]{0,90}"],
            structure in any::<bool>(),
        ) {
            let origin = one_line(&origin);
            let types: Vec<String> = vars.iter().map(|v| v.ty.value.known().unwrap().rust_type()).collect();
            let kind = match structure {
                true => Kind::Structure { name: "axis_t", description: description.trim() },
                false => Kind::Program { origin: &origin },
            };
            prop_assert_eq!(
                emit_struct(&vars, &types, "Gm", &kind, &origin).unwrap(),
                by_prettyplease(&vars, &types, &kind, &origin)
            );
        }
    }
}
