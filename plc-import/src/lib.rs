//! Variable lists (JSON project files, and CSV tables with the same columns) to Rust,
//! and back.
//!
//! ```
//! let json = r#"{ "variables": {
//!     "impact67_0_digital_inputs": { "type": "u16", "link": "ethercat.impact67_0.digital_inputs" },
//!     "ls_centering_neg": { "type": "bool", "source": "impact67_0_digital_inputs", "bit": 0 },
//!     "info_test_id": { "type": "string", "description": "Test identifier" }
//! } }"#;
//! let generated = plc_import::generate(json, &plc_import::Options::default()).unwrap();
//! assert!(generated.code.contains("pub info_test_id: FixedString<64>,"));
//! assert!(generated.code.contains("#[plc(source = \"impact67_0_digital_inputs\", bit = 0"));
//! ```
//!
//! The same variables as CSV ([`COLUMNS`], and [`ALARM_COLUMNS`] for alarms; RFC 4180 quoting,
//! a header line naming the columns in any order, empty cells for what a variable does not
//! declare):
//!
//! ```
//! let csv = "name,type,link,source,bit,description\r\n\
//!            impact67_0_digital_inputs,u16,ethercat.impact67_0.digital_inputs,,,\r\n\
//!            ls_centering_neg,bool,,impact67_0_digital_inputs,0,\r\n\
//!            info_test_id,string,,,,\"Test identifier, as printed\"\r\n";
//! let generated = plc_import::generate_csv(csv, &plc_import::Options::default()).unwrap();
//! assert!(generated.code.contains("/// Test identifier, as printed"));
//! ```
//!
//! Structure types come in the list's `types` section, each becoming a `#[derive(PlcStruct)]`
//! struct (docs/variable-lists.md describes both formats):
//!
//! ```
//! let json = r#"{
//!     "types": { "Axis": { "variables": { "pos": { "type": "f64" }, "homed": { "type": "bool" } } } },
//!     "variables": { "lift": { "type": "Axis" }, "axes": { "type": "Axis", "dims": [3] } }
//! }"#;
//! let generated = plc_import::generate(json, &plc_import::Options::default()).unwrap();
//! assert!(generated.code.contains("pub struct Axis {"));
//! assert!(generated.code.contains("pub axes: [Axis; 3],"));
//! ```

// The importer is feature `import`, the export feature `export`. The export writes the CSV
// reader's columns, so the reader (and the parsed form it reads into) compile with either.
#[cfg(feature = "import")]
mod alarm_attr;
#[cfg_attr(not(feature = "import"), allow(dead_code))]
mod csv_alarm;
#[cfg_attr(not(feature = "import"), allow(dead_code))]
mod csv_read;
#[cfg(feature = "export")]
mod csv_write;
#[cfg(feature = "import")]
mod emit;
#[cfg(feature = "export")]
mod export;
#[cfg(feature = "export")]
mod export_alarms;
#[cfg_attr(not(feature = "import"), allow(dead_code))]
mod parse;
#[cfg_attr(not(feature = "import"), allow(dead_code))]
mod standard;
#[cfg(feature = "import")]
mod validate;

pub use csv_alarm::ALARM_COLUMNS;
pub use csv_read::COLUMNS;
#[cfg(feature = "export")]
pub use export::{descriptor_to_csv, descriptor_to_json, export_csv, export_json};

#[cfg(feature = "import")]
use validate::{ListAt, Problem};

#[cfg(feature = "import")]
use std::fmt;
#[cfg(feature = "import")]
use std::path::Path;

#[cfg(feature = "import")]
/// Import settings.
#[derive(Clone, Debug)]
pub struct Options {
    /// Name of the generated struct (default `Gm`: `GlobalMemory` would clash with the trait).
    pub struct_name: String,
    /// What the generated module says it was made from (a file name).
    pub origin: String,
}

#[cfg(feature = "import")]
impl Default for Options {
    fn default() -> Self {
        Options {
            struct_name: "Gm".into(),
            origin: "a variable list".into(),
        }
    }
}

#[cfg(feature = "import")]
/// The generated module and the warnings about suspicious but legal input.
#[derive(Clone, Debug)]
pub struct Generated {
    /// Rust source of a module that compiles on its own.
    pub code: String,
    /// Warnings, one per line, each naming the variable and field.
    pub warnings: Vec<String>,
}

#[cfg(feature = "import")]
/// Every error of the file, each naming the variable and field.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ImportErrors(pub Vec<String>);

#[cfg(feature = "import")]
impl fmt::Display for ImportErrors {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0.join("\n"))
    }
}

#[cfg(feature = "import")]
impl std::error::Error for ImportErrors {}

#[cfg(feature = "import")]
/// Checks a JSON variable list and generates the equivalent `#[derive(GlobalMemory)]` struct,
/// with a `#[derive(PlcStruct)]` struct for each type of its `types` section.
///
/// Errors and warnings read `variables.<name>.<field>: <what is wrong>`, or
/// `types.<type>.variables.<member>.<field>: ...` for a member of a type.
pub fn generate(json: &str, options: &Options) -> Result<Generated, ImportErrors> {
    let parsed = parse::parse(json).map_err(|e| ImportErrors(vec![e]))?;
    let checked = validate::check(&parsed, &|_, _| None);
    let place = |p: &Problem| {
        let name = checked.var_name(&p.at);
        let group = match p.at.ty {
            Some(t) => format!("types.{}.variables", checked.types[t].name),
            None => "variables".into(),
        };
        match &p.at.field {
            Some(f) => format!("{group}.{name}.{f}: {}", p.message),
            None => format!("{group}.{name}: {}", p.message),
        }
    };
    let place_type = |t: usize, field: Option<&str>, message: &str| {
        let name = &checked.types[t].name;
        match field {
            Some(f) => format!("types.{name}.{f}: {message}"),
            None => format!("types.{name}: {message}"),
        }
    };
    let mut generated = finish(&checked, options, Vec::new(), place, place_type)?;
    if !parsed.has_variables {
        generated.warnings.insert(
            0,
            "the file has no \"variables\" object, so the struct declares no variable: add \
             { \"variables\": { \"name\": { \"type\": \"u16\" } } } to declare some"
                .into(),
        );
    }
    Ok(generated)
}

#[cfg(feature = "import")]
/// Checks a CSV variable list ([`COLUMNS`]) and generates the equivalent struct, with the same
/// rules as [`generate`]. A structure type is declared by a row of type `STRUCT` (its
/// description in the description column) and its members by rows named `<type>.<member>`
/// (docs/variable-lists.md, "CSV").
///
/// Errors and warnings read `line <n>, variable <name>, column <column>: <what is wrong>`
/// (`variable Axis.pos` for a member, `type Axis` for a type's own row).
pub fn generate_csv(csv: &str, options: &Options) -> Result<Generated, ImportErrors> {
    let table = csv_read::parse(csv).map_err(ImportErrors)?;
    let lines = |ty: Option<usize>, var: usize| table.line_of(ty, var);
    let checked = validate::check(&table.parsed, &lines);
    let place = |p: &Problem| {
        let name = checked.var_name(&p.at);
        let name = match p.at.ty {
            Some(t) => format!("{}.{name}", checked.types[t].name),
            None => name.to_string(),
        };
        let line = lines(p.at.ty, p.at.var).map_or_else(String::new, |l| format!("line {l}, "));
        match &p.at.field {
            Some(f) => format!(
                "{line}variable {name}, column {}: {}",
                csv_alarm::column_of(f),
                p.message
            ),
            None => format!("{line}variable {name}: {}", p.message),
        }
    };
    let place_type = |t: usize, field: Option<&str>, message: &str| {
        let name = &checked.types[t].name;
        let line = table
            .type_lines
            .get(t)
            .copied()
            .flatten()
            .map_or_else(String::new, |l| format!("line {l}, "));
        match field {
            Some(f) => format!("{line}type {name}, column {f}: {message}"),
            None => format!("{line}type {name}: {message}"),
        }
    };
    finish(
        &checked,
        options,
        table.row_errors.clone(),
        place,
        place_type,
    )
    .map_err(|mut e| {
        // In the order of the file, as a user fixes them going down the sheet (the sort is
        // stable: one row's errors keep their column order).
        e.0.sort_by_key(|m| line_of(m));
        e
    })
}

#[cfg(feature = "import")]
/// The line a CSV message starts with (`line 4, ...`); messages about no line go last.
fn line_of(message: &str) -> u64 {
    message
        .strip_prefix("line ")
        .and_then(|m| m.split([',', ':']).next())
        .and_then(|n| n.parse().ok())
        .unwrap_or(u64::MAX)
}

#[cfg(feature = "import")]
/// The checks of the generated code itself, and emission, shared by the JSON and CSV front
/// ends; `place` words a problem for the input's format, `place_type` one of a type as a whole.
fn finish(
    checked: &validate::Checked,
    options: &Options,
    mut errors: Vec<String>,
    place: impl Fn(&Problem) -> String,
    place_type: impl Fn(usize, Option<&str>, &str) -> String,
) -> Result<Generated, ImportErrors> {
    for p in &checked.type_errors {
        errors.push(place_type(p.ty, p.field.as_deref(), &p.message));
    }
    for (t, message) in emit::check_type_names(checked, &options.struct_name) {
        errors.push(place_type(t, None, &message));
    }
    errors.extend(checked.errors.iter().map(&place));
    if let Err(e) = emit::check_struct_name(&options.struct_name) {
        errors.push(e);
    }
    let groups = checked
        .listed()
        .map(|(t, ty)| (Some(t), &ty.group))
        .chain([(None, &checked.top)]);
    for (ty, group) in groups {
        for (i, v) in group.decl.vars[..group.declared].iter().enumerate() {
            if emit::UNUSABLE.contains(&v.name.value.as_str()) {
                errors.push(place(&Problem {
                    at: ListAt {
                        ty,
                        var: i,
                        field: None,
                    },
                    message: "this name cannot be a Rust field; rename it".into(),
                    kind: None,
                }));
            }
        }
    }
    if checked.image_bytes >= plc_rules::capacity::MAX_IMAGE_BYTES {
        errors.push(format!(
            "the image of `{}` is 4 GiB or more: the variables must take less than 2^32 bytes \
             (fewer or smaller array elements)",
            options.struct_name
        ));
    }
    if !errors.is_empty() {
        return Err(ImportErrors(errors));
    }
    let code = emit::emit(checked, &options.struct_name, &options.origin)
        .map_err(|e| ImportErrors(vec![e]))?;
    Ok(Generated {
        code,
        warnings: checked.warnings.iter().map(place).collect(),
    })
}

#[cfg(feature = "import")]
/// For `build.rs`: generates `out` from the JSON file `path` (a CSV file if its name ends in
/// `.csv`), written atomically and only when it changed; prints the warnings as cargo warnings
/// and `cargo:rerun-if-changed`.
pub fn generate_from_file(path: &Path, out: &Path) -> Result<(), Box<dyn std::error::Error>> {
    println!("cargo:rerun-if-changed={}", path.display());
    let json = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let origin = path.file_name().map_or_else(
        || path.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    );
    let options = Options {
        origin,
        ..Options::default()
    };
    let generated = if is_csv(path) {
        generate_csv(&json, &options)
    } else {
        generate(&json, &options)
    }
    .map_err(|e| format!("{}:\n{e}", path.display()))?;
    for w in &generated.warnings {
        println!("cargo:warning={w}");
    }
    write_atomically(out, generated.code.as_bytes())?;
    Ok(())
}

#[cfg(feature = "import")]
/// Whether a file is a CSV variable list, by its name (`.csv`, any case).
pub fn is_csv(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("csv"))
}

#[cfg(feature = "import")]
/// Writes a file whole or not at all ([`plc_files::write_atomically`]: a new private temporary
/// file beside it, never a link followed, synced, renamed over it, the directory synced), so
/// that a crash leaves the old file or the new one. An unchanged file is not rewritten (cargo
/// would otherwise rebuild what includes it).
pub fn write_atomically(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    if std::fs::read(path).is_ok_and(|old| old == bytes) {
        return Ok(());
    }
    plc_files::write_atomically(path, bytes, 0o644)
}
