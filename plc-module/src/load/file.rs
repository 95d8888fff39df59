//! Reads a module file the way a hostile directory cannot subvert: the last path component
//! is never followed if it is a link, the checks are made on the open file (`fstat`), and the
//! bytes the later checks see are the bytes that get loaded, never the path again.

use super::error::ModuleError;
use std::fs::{File, OpenOptions};
use std::io::Read;
use std::os::unix::fs::{MetadataExt, OpenOptionsExt};
use std::path::Path;

/// The largest module accepted: far above a release build of a large program (a few MB) and
/// a debug build (tens of MB), and a bound on what a refused file can cost.
pub const MAX_MODULE_BYTES: u64 = 512 << 20;

/// The file's bytes, if it is a regular file of the host's user that nobody else may write.
pub fn read_checked(path: &Path) -> Result<Vec<u8>, ModuleError> {
    let io = |doing, error| ModuleError::Io {
        path: path.into(),
        doing,
        error,
    };
    let file: File = OpenOptions::new()
        .read(true)
        .custom_flags(libc::O_NOFOLLOW | libc::O_NOCTTY | libc::O_NONBLOCK)
        .open(path)
        .map_err(|e| match e.raw_os_error() {
            Some(libc::ELOOP) => ModuleError::Link { path: path.into() },
            _ => io("open it", e),
        })?;
    let meta = file.metadata().map_err(|e| io("read its status", e))?;
    if !meta.file_type().is_file() {
        return Err(ModuleError::NotAFile { path: path.into() });
    }
    let host = plc_shm::euid();
    if meta.uid() != host {
        return Err(ModuleError::Owner {
            path: path.into(),
            owner: meta.uid(),
            host,
        });
    }
    let mode = meta.mode();
    if mode & 0o020 != 0 {
        return Err(ModuleError::Writable {
            path: path.into(),
            who: "its group",
        });
    }
    if mode & 0o002 != 0 {
        return Err(ModuleError::Writable {
            path: path.into(),
            who: "every user",
        });
    }
    if meta.len() > MAX_MODULE_BYTES {
        return Err(ModuleError::TooLarge {
            path: path.into(),
            size: meta.len(),
            max: MAX_MODULE_BYTES,
        });
    }
    let mut bytes = Vec::with_capacity(meta.len() as usize);
    file.take(MAX_MODULE_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| io("read it", e))?;
    if bytes.len() as u64 > MAX_MODULE_BYTES {
        return Err(ModuleError::TooLarge {
            path: path.into(),
            size: bytes.len() as u64,
            max: MAX_MODULE_BYTES,
        });
    }
    Ok(bytes)
}
