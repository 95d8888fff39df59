//! Records the compiler and target this crate is built with: they are part of the
//! fingerprint a module and its host compare (see `src/fingerprint.rs`).

use std::process::Command;

fn main() {
    let rustc = std::env::var("RUSTC").unwrap_or_else(|_| "rustc".into());
    let version = Command::new(&rustc)
        .arg("--version")
        .output()
        .ok()
        .filter(|o| o.status.success())
        .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
        .unwrap_or_else(|| format!("{rustc} (its version unknown)"));
    let target = std::env::var("TARGET").unwrap_or_else(|_| "unknown target".into());
    println!("cargo:rustc-env=PLC_MODULE_RUSTC={version}");
    println!("cargo:rustc-env=PLC_MODULE_TARGET={target}");
    println!("cargo:rerun-if-env-changed=RUSTC");
}
