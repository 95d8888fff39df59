//! Nonvolatile (retained) variables: values that survive restarts, and edits of the
//! declaration.
//!
//! The file is one header line with a CRC-32 of the body, then the body: JSON with each
//! nonvolatile variable's name, IEC type and values. It is replaced atomically (temporary file,
//! fsync, rename, fsync of the directory), so after a crash at any point it holds the old or
//! the new content, never a mix. Saving happens on a background thread from a copy, never in
//! the cycle.
//!
//! Nonvolatile members of structures are kept one by one, by path (`axes[1].cycles`), so a
//! structure edited around them or an array of structures resized keeps what still exists.
//!
//! Loading matches variables by name (case-insensitive): new variables keep their `initial`,
//! removed or renamed ones are reported, a changed type is converted only where IEC 61131-3's
//! widening allows it (`can_widen`), otherwise reported and the initial value kept. A corrupt
//! or truncated file is an error naming it, and the file is left untouched.
//!
//! ```
//! use plc_core::GlobalMemory;
//! use plc_runtime::retain::RetainStore;
//!
//! #[derive(GlobalMemory, Debug, Clone)]
//! struct Gm {
//!     #[plc(nonvolatile, initial = 12.5)]
//!     home_offset_mm: f64,
//! }
//!
//! let dir = std::env::temp_dir().join(format!("retain-doc-{}", std::process::id()));
//! std::fs::create_dir_all(&dir).unwrap();
//! let store = RetainStore::new(dir.join("press.retain"));
//! let mut gm = Gm::default();
//! gm.home_offset_mm = 3.25;
//! store.save(&gm).unwrap();
//!
//! let mut fresh = Gm::default();
//! let report = store.load(&mut fresh).unwrap();
//! assert_eq!(fresh.home_offset_mm, 3.25);
//! assert_eq!(report.restored, ["home_offset_mm"]);
//! # std::fs::remove_dir_all(&dir).unwrap();
//! ```

use plc_core::convert::can_widen;
use plc_core::memory::Memory;
use plc_core::{IecType, Value};
use serde::{Deserialize, Serialize};
use std::fmt;
use std::fs::{self, OpenOptions};
use std::io::{Read, Write};
use std::os::unix::fs::{DirBuilderExt, OpenOptionsExt};
use std::path::{Path, PathBuf};

mod files;
mod items;
mod values;
mod writer;

pub use writer::RetainWriter;

use files::{fault_point, process_alive};
use items::items;
use plc_shm::euid;
use values::{from_json, to_json, widen};

const HEADER: &str = "plc-vars retain v1 crc32=";

/// Why the retain file could not be used.
#[derive(Debug)]
pub enum RetainError {
    /// The file is damaged (bad checksum, truncated, not JSON). It was left as it is.
    Corrupt {
        /// The file.
        path: PathBuf,
        /// What is wrong.
        why: String,
    },
    /// Reading or writing failed.
    Io {
        /// The file.
        path: PathBuf,
        /// The OS error.
        error: std::io::Error,
    },
    /// The file or its directory is a symbolic link, not a regular file or directory, belongs
    /// to another user or is open to other users: it is not used, so that nobody else can
    /// plant or change retained values, or make the program write elsewhere.
    Unsafe {
        /// The file or directory.
        path: PathBuf,
        /// What is wrong with it.
        problem: String,
        /// What to do.
        fix: String,
    },
}

impl fmt::Display for RetainError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RetainError::Corrupt { path, why } => write!(
                f,
                "retain file {} is damaged ({why}); it was left untouched: restore it from a \
                 backup, or move it away to start from the initial values",
                path.display()
            ),
            RetainError::Io { path, error } => {
                write!(f, "retain file {}: {error}", path.display())
            }
            RetainError::Unsafe { path, problem, fix } => {
                write!(
                    f,
                    "refusing retain path {}: it {problem}; {fix}",
                    path.display()
                )
            }
        }
    }
}

impl std::error::Error for RetainError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            RetainError::Io { error, .. } => Some(error),
            RetainError::Corrupt { .. } | RetainError::Unsafe { .. } => None,
        }
    }
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
struct Stored {
    name: String,
    #[serde(rename = "type")]
    iec_type: IecType,
    values: Vec<serde_json::Value>,
}

/// A retained item as loading compares it with the file.
struct Retained<'a> {
    name: &'a str,
    iec_type: IecType,
    elements: usize,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
struct Body {
    variables: Vec<Stored>,
}

/// What loading did, variable by variable.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RetainReport {
    /// Restored as saved.
    pub restored: Vec<String>,
    /// Restored with a widening conversion: name, saved type, declared type.
    pub converted: Vec<(String, IecType, IecType)>,
    /// Nonvolatile now but not in the file: kept their initial value.
    pub new: Vec<String>,
    /// In the file but no longer declared (removed or renamed): ignored.
    pub removed: Vec<String>,
    /// In the file but not restorable (type narrowed, other kind, other size): name and why;
    /// they kept their initial value.
    pub reset: Vec<(String, String)>,
    /// Temporary files of saves that a process did not finish (it died between creating and
    /// renaming one), removed. They never hold the retained values: those are in the file.
    pub stale_temps: Vec<PathBuf>,
}

impl RetainReport {
    /// Logs the report's warnings (removed and reset variables) and the temporary files it
    /// removed, through the `log` crate (target `plc_runtime::retain`).
    pub fn log(&self, path: &Path) {
        for name in &self.removed {
            log::warn!(target: "plc_io::retain",
                "retain {}: `{name}` is no longer a nonvolatile variable (removed or renamed); \
                 its saved value is ignored",
                path.display()
            );
        }
        for (name, why) in &self.reset {
            log::warn!(target: "plc_io::retain",
                "retain {}: `{name}` keeps its initial value: {why}",
                path.display()
            );
        }
        for temp in &self.stale_temps {
            log::info!(target: "plc_io::retain",
                "retain {}: removed {}, left by a save that did not finish",
                path.display(),
                temp.display()
            );
        }
    }
}
/// The retain file of a program.
#[derive(Clone, Debug)]
pub struct RetainStore {
    path: PathBuf,
}

impl RetainStore {
    /// The store at `path` (created at the first save).
    pub fn new(path: impl Into<PathBuf>) -> Self {
        RetainStore { path: path.into() }
    }

    /// The file.
    pub fn path(&self) -> &Path {
        &self.path
    }

    fn body_of<T: Memory>(gm: &T) -> Body {
        Body {
            variables: items(gm.schema().variables)
                .into_iter()
                .map(|item| Stored {
                    values: (0..item.elements)
                        .filter_map(|e| gm.try_get(item.index, item.first_leaf + e))
                        .map(|x| to_json(&x))
                        .collect(),
                    name: item.path,
                    iec_type: item.iec_type,
                })
                .collect(),
        }
    }

    /// Saves the nonvolatile variables of `gm`, atomically.
    pub fn save<T: Memory>(&self, gm: &T) -> Result<(), RetainError> {
        let body = serde_json::to_vec_pretty(&Self::body_of(gm)).map_err(|e| RetainError::Io {
            path: self.path.clone(),
            error: std::io::Error::other(e),
        })?;
        self.write_atomically(&body)
    }

    fn write_atomically(&self, body: &[u8]) -> Result<(), RetainError> {
        let crc = crc32fast::hash(body);
        self.checked_dir(false)?;
        plc_files::write_atomically_with(
            &self.path,
            0o600,
            |f| {
                f.write_all(format!("{HEADER}{crc:08x}\n").as_bytes())?;
                f.write_all(body)
            },
            fault_point,
        )
        .map_err(|error| RetainError::Io {
            path: self.path.clone(),
            error,
        })
    }

    /// The directory the file is in (`.` for a bare file name).
    fn dir(&self) -> PathBuf {
        match self.path.parent() {
            Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
            _ => PathBuf::from("."),
        }
    }

    /// The directory, checked: a directory (not a link) of this user that nobody else may
    /// write. Anyone who could write it could swap the file. `create`: created 0700 if it is
    /// missing (at load, when the program starts; a directory that disappears later is an
    /// error of the save, not silently made again).
    fn checked_dir(&self, create: bool) -> Result<PathBuf, RetainError> {
        let dir = self.dir();
        if create && !dir.exists() {
            fs::DirBuilder::new()
                .recursive(true)
                .mode(0o700)
                .create(&dir)
                .map_err(|error| RetainError::Io {
                    path: dir.clone(),
                    error,
                })?;
        }
        let meta = fs::symlink_metadata(&dir).map_err(|error| RetainError::Io {
            path: dir.clone(),
            error,
        })?;
        if let Some((problem, fix)) = crate::private_dir::problem(&dir, &meta, euid()) {
            return Err(RetainError::Unsafe {
                path: dir.clone(),
                problem,
                fix,
            });
        }
        Ok(dir)
    }

    /// The temporary file a save by process `pid` writes before renaming it over the file.
    fn temp_path(&self, pid: u32) -> PathBuf {
        plc_files::temp_path(&self.path, pid).unwrap_or_default()
    }

    /// Removes the temporary files of saves by processes that are gone, and returns them. A
    /// live process's file is left alone: it may be saving right now.
    fn remove_stale_temps(&self) -> Vec<PathBuf> {
        let dir = self.dir();
        let Ok(entries) = fs::read_dir(&dir) else {
            return Vec::new();
        };
        let mut removed = Vec::new();
        for entry in entries.flatten() {
            let pid = plc_files::temp_owner(&self.path, &entry.file_name());
            if let Some(pid) = pid.filter(|&pid| !process_alive(pid)) {
                let temp = self.temp_path(pid);
                if fs::remove_file(&temp).is_ok() {
                    removed.push(temp);
                }
            }
        }
        removed
    }

    fn read_body(&self) -> Result<Option<Body>, RetainError> {
        self.checked_dir(true)?;
        let io = |error| RetainError::Io {
            path: self.path.clone(),
            error,
        };
        let mut file = match OpenOptions::new()
            .read(true)
            .custom_flags(libc::O_NOFOLLOW)
            .open(&self.path)
        {
            Ok(f) => f,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
            Err(e) if e.raw_os_error() == Some(libc::ELOOP) => {
                let (problem, fix) = crate::private_dir::link_problem(&self.path);
                return Err(RetainError::Unsafe {
                    path: self.path.clone(),
                    problem,
                    fix,
                });
            }
            Err(error) => return Err(io(error)),
        };
        let meta = file.metadata().map_err(io)?;
        if let Some((problem, fix)) = crate::private_dir::file_problem(&self.path, &meta, euid()) {
            return Err(RetainError::Unsafe {
                path: self.path.clone(),
                problem,
                fix,
            });
        }
        let mut data = Vec::new();
        file.read_to_end(&mut data).map_err(io)?;
        let corrupt = |why: &str| RetainError::Corrupt {
            path: self.path.clone(),
            why: why.to_string(),
        };
        let newline = data
            .iter()
            .position(|&b| b == b'\n')
            .ok_or_else(|| corrupt("no header line"))?;
        let header = std::str::from_utf8(&data[..newline]).map_err(|_| corrupt("bad header"))?;
        let crc = header
            .strip_prefix(HEADER)
            .and_then(|h| u32::from_str_radix(h, 16).ok())
            .ok_or_else(|| corrupt("not a plc-vars retain file"))?;
        let body = &data[newline + 1..];
        if crc32fast::hash(body) != crc {
            return Err(corrupt("checksum mismatch: truncated or modified"));
        }
        serde_json::from_slice(body)
            .map(Some)
            .map_err(|e| corrupt(&e.to_string()))
    }

    /// Loads saved values into `gm`'s nonvolatile variables (others are untouched). A missing
    /// file is not an error: every nonvolatile variable is then reported new, and a missing
    /// directory is created (mode 0700).
    pub fn load<T: Memory>(&self, gm: &mut T) -> Result<RetainReport, RetainError> {
        let body = self.read_body()?.unwrap_or(Body { variables: vec![] });
        let mut report = RetainReport {
            stale_temps: self.remove_stale_temps(),
            ..RetainReport::default()
        };
        let retained = items(gm.schema().variables);
        for stored in &body.variables {
            if !retained
                .iter()
                .any(|v| v.path.eq_ignore_ascii_case(&stored.name))
            {
                report.removed.push(stored.name.clone());
            }
        }
        for item in &retained {
            let (i, first) = (item.index, item.first_leaf);
            let v = Retained {
                name: &item.path,
                iec_type: item.iec_type,
                elements: item.elements,
            };
            let Some(stored) = body
                .variables
                .iter()
                .find(|s| s.name.eq_ignore_ascii_case(v.name))
            else {
                report.new.push(v.name.to_string());
                continue;
            };
            if stored.values.len() != v.elements {
                report.reset.push((
                    v.name.to_string(),
                    format!(
                        "it had {} elements, now {}",
                        stored.values.len(),
                        v.elements
                    ),
                ));
                continue;
            }
            if stored.iec_type != v.iec_type && !can_widen(stored.iec_type, v.iec_type) {
                report.reset.push((
                    v.name.to_string(),
                    format!(
                        "its type changed from {} to {}, which is no implicit widening",
                        stored.iec_type, v.iec_type
                    ),
                ));
                continue;
            }
            let values: Option<Vec<Value>> = stored
                .values
                .iter()
                .map(|j| {
                    from_json(j, stored.iec_type)
                        .and_then(|x| widen(x, stored.iec_type, v.iec_type))
                })
                .collect();
            let Some(values) = values else {
                report.reset.push((
                    v.name.to_string(),
                    format!("a saved value is not a {} value", stored.iec_type),
                ));
                continue;
            };
            // Check every element first: a variable is restored whole or not at all.
            let mut trial = (0..v.elements).filter_map(|e| gm.try_get(i, first + e));
            let before: Vec<Value> = trial.by_ref().collect();
            let mut failed = None;
            for (e, x) in values.iter().enumerate() {
                if let Err(err) = gm.set(i, first + e, *x) {
                    failed = Some(err.to_string());
                    break;
                }
            }
            if let Some(why) = failed {
                for (e, x) in before.iter().enumerate() {
                    let _ = gm.set(i, first + e, *x);
                }
                report.reset.push((v.name.to_string(), why));
            } else if stored.iec_type != v.iec_type {
                report
                    .converted
                    .push((v.name.to_string(), stored.iec_type, v.iec_type));
            } else {
                report.restored.push(v.name.to_string());
            }
        }
        Ok(report)
    }
}
