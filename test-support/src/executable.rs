//! A copy of an executable that can be run at once.

use std::io;
use std::path::{Path, PathBuf};
use std::process::Command;

use crate::SpawnGuarded;

/// Copies the executable `source` into `dir` (mode 0755) and returns the copy's path.
///
/// Why not `std::fs::copy`: while this process holds the copy open for writing, any child
/// another test thread forks inherits that descriptor until its `exec`, and running the copy
/// in that window fails with `Text file busy` (ETXTBSY). `install`, a process of its own,
/// writes the copy instead: no descriptor of it ever exists in this process.
pub fn install_executable(source: &Path, dir: &Path) -> io::Result<PathBuf> {
    let name = source
        .file_name()
        .ok_or_else(|| io::Error::other(format!("{} names no file", source.display())))?;
    let copy = dir.join(name);
    let out = Command::new("install")
        .args(["-m", "0755"])
        .arg(source)
        .arg(&copy)
        .output_guarded()?;
    if !out.status.success() {
        return Err(io::Error::other(format!(
            "install {} {}: {}",
            source.display(),
            copy.display(),
            String::from_utf8_lossy(&out.stderr).trim()
        )));
    }
    Ok(copy)
}
