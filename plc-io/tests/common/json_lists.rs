//! What the JSON importer's tests share: a variable list around some variables, and the
//! errors an import gives.
// Each test binary uses a different subset of these helpers.
#![allow(dead_code)]

use plc_io::import::{ImportErrors, Options, generate};

/// The errors importing `json` gives (the test fails if it imports).
pub fn errors(json: &str) -> Vec<String> {
    match generate(json, &Options::default()) {
        Err(ImportErrors(e)) => e,
        Ok(g) => panic!("expected errors, got:\n{}", g.code),
    }
}

/// A variable list with `body` as its variables.
pub fn vars(body: &str) -> String {
    format!("{{ \"variables\": {{ {body} }} }}")
}
