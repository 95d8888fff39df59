//! JSON variable lists (seed 000's project files) to Rust, and back.
//!
//! ```
//! let json = r#"{ "variables": {
//!     "impact67_0_digital_inputs": { "type": "u16", "link": "ethercat.impact67_0.digital_inputs" },
//!     "ls_centering_neg": { "type": "bool", "source": "impact67_0_digital_inputs", "bit": 0 },
//!     "info_test_id": { "type": "string", "description": "Test identifier" }
//! } }"#;
//! let generated = plc_io::import::generate(json, &plc_io::import::Options::default()).unwrap();
//! assert!(generated.code.contains("pub info_test_id: FixedString<64>,"));
//! assert!(generated.code.contains("#[plc(source = \"impact67_0_digital_inputs\", bit = 0)]"));
//! ```

mod emit;
mod export;
mod parse;
mod validate;

pub use export::{descriptor_to_json, export_json};
pub use validate::Spec;

use std::fmt;
use std::path::Path;

/// Import settings.
#[derive(Clone, Debug)]
pub struct Options {
    /// Name of the generated struct (default `Gm`: `GlobalMemory` would clash with the trait).
    pub struct_name: String,
    /// What the generated module says it was made from (a file name).
    pub origin: String,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            struct_name: "Gm".into(),
            origin: "a JSON variable list".into(),
        }
    }
}

/// The generated module and the warnings about suspicious but legal input.
#[derive(Clone, Debug)]
pub struct Generated {
    /// Rust source of a module that compiles on its own.
    pub code: String,
    /// Warnings, one per line, each naming the variable and field.
    pub warnings: Vec<String>,
}

/// Every error of the file, each naming the variable and field.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ImportErrors(pub Vec<String>);

impl fmt::Display for ImportErrors {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0.join("\n"))
    }
}

impl std::error::Error for ImportErrors {}

/// Checks a JSON variable list and generates the equivalent `#[derive(GlobalMemory)]` struct.
pub fn generate(json: &str, options: &Options) -> Result<Generated, ImportErrors> {
    let parsed = parse::parse(json).map_err(|e| ImportErrors(vec![e]))?;
    let checked = validate::check(&parsed);
    let mut errors = checked.errors;
    if !plc_rules::link::is_identifier(&options.struct_name) {
        errors.push(format!(
            "struct name {:?} is not a Rust identifier",
            options.struct_name
        ));
    }
    for s in &checked.specs {
        if emit::UNUSABLE.contains(&s.name.as_str()) {
            errors.push(format!(
                "variables.{}: this name cannot be a Rust field; rename it",
                s.name
            ));
        }
    }
    if !errors.is_empty() {
        return Err(ImportErrors(errors));
    }
    let code = emit::emit(&checked.specs, &options.struct_name, &options.origin)
        .map_err(|e| ImportErrors(vec![e]))?;
    Ok(Generated {
        code,
        warnings: checked.warnings,
    })
}

/// For `build.rs`: generates `out` from the JSON file `path` (written atomically, and only when
/// it changed), prints the warnings as cargo warnings and `cargo:rerun-if-changed`.
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
    let generated = generate(&json, &options).map_err(|e| format!("{}:\n{e}", path.display()))?;
    for w in &generated.warnings {
        println!("cargo:warning={w}");
    }
    write_atomically(out, generated.code.as_bytes())?;
    Ok(())
}

/// Writes a file whole or not at all (temporary file, then rename).
pub fn write_atomically(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    if std::fs::read(path).is_ok_and(|old| old == bytes) {
        return Ok(());
    }
    let tmp = path.with_extension(format!("tmp.{}", std::process::id()));
    std::fs::write(&tmp, bytes)?;
    std::fs::rename(&tmp, path)
}
