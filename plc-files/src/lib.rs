//! Every file plc-vars writes (generated Rust, retained values, scanned bus descriptions, the
//! OPC UA users file) is written through [`write_atomically`]: whole or not at all, never
//! through a link someone planted.
//!
//! 1. A temporary file beside the target, [`temp_path`] (`.<name>.tmp.<pid>`), created with
//!    `O_CREAT | O_EXCL | O_NOFOLLOW` and the file's mode: it is always new, so a file or a
//!    link planted at its name is never written through. One left there (by an earlier process
//!    of this pid, or planted) is removed, never followed, and the create tried once more.
//! 2. The contents written and `fsync`ed.
//! 3. Renamed over the target, then the directory `fsync`ed: a crash at any point leaves the
//!    old file or the new one, and once this returns the new one survives a power cut.
//!
//! On an error the temporary file is removed and the old file is untouched.
//!
//! ```
//! let dir = std::env::temp_dir().join(format!("plc-files-doc-{}", std::process::id()));
//! std::fs::create_dir_all(&dir)?;
//! let file = dir.join("bus.toml");
//! plc_files::write_atomically(&file, b"[[devices]]\n", 0o644)?;
//! assert_eq!(std::fs::read(&file)?, b"[[devices]]\n");
//! # std::fs::remove_dir_all(&dir)?;
//! # Ok::<(), std::io::Error>(())
//! ```
#![deny(missing_docs)]

use std::ffi::OsString;
use std::fs::{self, File, OpenOptions};
use std::io::{self, Write};
use std::os::unix::fs::OpenOptionsExt;
use std::path::{Path, PathBuf};

/// The steps of [`write_atomically_with`], each reported to its `step` hook as it is reached
/// (a test can stop the process there, as a crash or a power cut would).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Step {
    /// The temporary file is created, nothing written yet.
    Created,
    /// Written, not yet synced.
    Written,
    /// Synced, not yet renamed over the file.
    Synced,
    /// Renamed, the directory not yet synced.
    Renamed,
    /// Done.
    DirSynced,
}

/// Writes `bytes` to `path` whole or not at all, the new file with permissions `mode`
/// (as `open(2)` takes them, less the umask).
pub fn write_atomically(path: &Path, bytes: &[u8], mode: u32) -> io::Result<()> {
    write_atomically_with(path, mode, |f| f.write_all(bytes), |_| {})
}

/// [`write_atomically`] with the contents written by `write` into the temporary file, and
/// `step` called at each [`Step`].
pub fn write_atomically_with(
    path: &Path,
    mode: u32,
    write: impl FnOnce(&mut File) -> io::Result<()>,
    mut step: impl FnMut(Step),
) -> io::Result<()> {
    let tmp = temp_path(path, std::process::id())?;
    let mut file = create_new(&tmp, mode)?;
    step(Step::Created);
    let written = write(&mut file).and_then(|()| {
        step(Step::Written);
        file.sync_all()
    });
    drop(file);
    let renamed = written.and_then(|()| {
        step(Step::Synced);
        fs::rename(&tmp, path)
    });
    if let Err(e) = renamed {
        let _ = fs::remove_file(&tmp);
        return Err(e);
    }
    step(Step::Renamed);
    File::open(dir_of(path)).and_then(|d| d.sync_all())?;
    step(Step::DirSynced);
    Ok(())
}

/// The temporary file a write to `path` by process `pid` goes through: `.<name>.tmp.<pid>`
/// beside it (hidden, and apart from every other file's). An error if `path` names no file.
pub fn temp_path(path: &Path, pid: u32) -> io::Result<PathBuf> {
    let name = path.file_name().ok_or_else(|| {
        io::Error::new(
            io::ErrorKind::InvalidInput,
            format!("{} names no file to write", path.display()),
        )
    })?;
    let mut tmp = OsString::from(".");
    tmp.push(name);
    tmp.push(format!(".tmp.{pid}"));
    Ok(dir_of(path).join(tmp))
}

/// The pid of the process whose write to `path` left the temporary file named `name` (a
/// name in `path`'s directory), if `name` is one: to clean up after processes that are gone.
///
/// ```
/// use std::path::Path;
/// let file = Path::new("state/gm.retain");
/// assert_eq!(plc_files::temp_owner(file, ".gm.retain.tmp.42".as_ref()), Some(42));
/// assert_eq!(plc_files::temp_owner(file, "gm.retain".as_ref()), None);
/// ```
pub fn temp_owner(path: &Path, name: &std::ffi::OsStr) -> Option<u32> {
    let file = path.file_name()?.to_str()?;
    let pid = name
        .to_str()?
        .strip_prefix('.')?
        .strip_prefix(file)?
        .strip_prefix(".tmp.")?;
    pid.parse().ok()
}

/// The directory `path` is in (`.` for a bare file name).
pub fn dir_of(path: &Path) -> &Path {
    match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    }
}

/// Creates `path`, which must not exist (a link there is not followed), with `mode`. One that
/// exists is removed (the link itself, never what it points at) and the create tried once more.
fn create_new(path: &Path, mode: u32) -> io::Result<File> {
    let open = || {
        OpenOptions::new()
            .write(true)
            .create_new(true)
            .mode(mode)
            .custom_flags(libc::O_NOFOLLOW)
            .open(path)
    };
    match open() {
        Err(e) if e.kind() == io::ErrorKind::AlreadyExists => {
            fs::remove_file(path)?;
            open()
        }
        r => r,
    }
}

#[cfg(test)]
mod tests;
