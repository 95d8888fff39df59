//! `plc import <project.json> [-o FILE] [--struct NAME]` (or `--csv <table.csv>`): a JSON or
//! CSV variable list to the equivalent `#[derive(GlobalMemory)]` struct. Every error of the file is listed; on any error
//! nothing is written, and the output file is replaced whole or not at all.

use super::Error;
use plc_import::{Options, generate, generate_csv, is_csv, write_atomically};
use std::path::Path;

pub fn run(input: &Path, csv: bool, output: Option<&Path>, struct_name: &str) -> Result<(), Error> {
    let text = std::fs::read_to_string(input).map_err(|e| format!("{}: {e}", input.display()))?;
    let options = Options {
        struct_name: struct_name.to_string(),
        origin: input.file_name().map_or_else(
            || input.display().to_string(),
            |n| n.to_string_lossy().into_owned(),
        ),
    };
    let generated = if csv || is_csv(input) {
        generate_csv(&text, &options)
    } else {
        generate(&text, &options)
    }
    .map_err(|e| format!("{} has errors:\n{e}", input.display()))?;
    for w in &generated.warnings {
        eprintln!("warning: {w}");
    }
    match output {
        Some(path) => {
            write_atomically(path, generated.code.as_bytes())
                .map_err(|e| format!("{}: {e}", path.display()))?;
            eprintln!("plc import: wrote {}", path.display());
        }
        None => print!("{}", generated.code),
    }
    Ok(())
}
