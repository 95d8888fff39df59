//! The one place that touches the segment's files: the shared memory under /dev/shm and the
//! owner's lock file beside it.
//!
//! Owner liveness is an exclusive `flock` on the lock file: the kernel releases it when the
//! owner dies, however it dies, and unlike a pid it cannot be reused by an unrelated process.
//!
//! Nothing here follows a symbolic link (`O_NOFOLLOW`; files are created with `O_EXCL`), and a
//! file that is not a regular file of this user with mode 0600 is refused with a message
//! naming it and the fix: a root-run owner must not truncate or write through a link another
//! user planted, nor trust a segment anyone may have written.
//!
//! Removal: an owner that stops cleanly unlinks its segment, then its lock file, then releases
//! the lock. An owner that starts takes the lock and then checks that the file it locked is
//! still the one at the path: if the previous owner unlinked it meanwhile, it starts over with
//! a new file, so two owners never hold locks on two files of one name. What a killed owner
//! leaves behind is removed by the next owner of this user that starts, whatever its name,
//! once it holds that name's lock (so that owner is gone).

use super::ShmError;
use super::guard::Guard;
use super::layout::{Base, H_GENERATION, H_MAGIC, IMAGE, MAGIC, MAGIC_CLOSED, MAGIC_REPLACED};
use std::fs::{File, OpenOptions};
use std::io;
use std::os::fd::{AsRawFd, OwnedFd};
use std::os::unix::fs::{MetadataExt, OpenOptionsExt, PermissionsExt};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// Prefix of every segment under /dev/shm, so `plc list` finds ours and nothing else.
pub const PREFIX: &str = "plc.";
/// Where POSIX shared memory lives on Linux.
const SHM_DIR: &str = "/dev/shm";

/// The program's segment name from what a user typed: `press`, `plc.press` or
/// `/dev/shm/plc.press` all mean `press`.
pub fn normalise(name: &str) -> Result<String, ShmError> {
    let n = name.strip_prefix("/dev/shm/").unwrap_or(name);
    let n = n.strip_prefix(PREFIX).unwrap_or(n);
    let n = n.strip_suffix(".lock").unwrap_or(n);
    let valid = !n.is_empty()
        && n.len() <= 200
        && n.chars()
            .all(|c| c.is_ascii_alphanumeric() || "_-.".contains(c));
    if valid {
        Ok(n.to_string())
    } else {
        Err(ShmError::BadName(name.to_string()))
    }
}

/// The segment's file.
pub fn shm_path(name: &str) -> PathBuf {
    PathBuf::from(format!("{SHM_DIR}/{PREFIX}{name}"))
}

/// The lock file the owner holds.
pub fn lock_path(name: &str) -> PathBuf {
    PathBuf::from(format!("{SHM_DIR}/{PREFIX}{name}.lock"))
}

fn euid() -> u32 {
    // SAFETY: geteuid has no preconditions and cannot fail.
    unsafe { libc::geteuid() }
}

/// Opens `path` without following a link; `create` adds `O_CREAT | O_EXCL` (mode 0600).
fn open_nofollow(path: &Path, write: bool, create: bool) -> io::Result<File> {
    let mut o = OpenOptions::new();
    o.read(true).write(write).custom_flags(libc::O_NOFOLLOW);
    if create {
        o.create_new(true).mode(0o600);
    }
    o.open(path)
}

/// A refusal of a file that is a link, not a regular file, another user's, or too open.
fn refuse(name: &str, path: &Path, problem: String, fix: String) -> ShmError {
    ShmError::Unsafe {
        name: name.to_string(),
        path: path.to_path_buf(),
        problem,
        fix,
    }
}

/// The error of opening `path`: a link, permission denied, or another OS error.
fn open_error(name: &str, path: &Path, what: &str, e: io::Error) -> ShmError {
    match e.raw_os_error() {
        Some(libc::ELOOP) => refuse(
            name,
            path,
            "is a symbolic link".into(),
            format!(
                "remove it (`rm {}`): plc-vars never follows a link there",
                path.display()
            ),
        ),
        Some(libc::EACCES | libc::EPERM) => ShmError::PermissionDenied {
            name: name.to_string(),
            path: path.to_path_buf(),
        },
        _ => ShmError::Os {
            name: name.to_string(),
            what: format!("{what} {}", path.display()),
            error: e.to_string(),
        },
    }
}

/// Checks that `file` (opened from `path`) is a regular file of this user that nobody else may
/// write (`private`: nor read).
fn check_file(name: &str, path: &Path, file: &File, private: bool) -> Result<(), ShmError> {
    let meta = file
        .metadata()
        .map_err(|e| open_error(name, path, "cannot inspect", e))?;
    if !meta.file_type().is_file() {
        return Err(refuse(
            name,
            path,
            "is not a regular file".into(),
            format!("remove it (`rm {}`)", path.display()),
        ));
    }
    if private && meta.uid() != euid() {
        return Err(refuse(
            name,
            path,
            format!(
                "belongs to uid {}, not to this program's uid {}",
                meta.uid(),
                euid()
            ),
            format!(
                "remove it as its owner or root (`rm {}`), or run the program as uid {}",
                path.display(),
                meta.uid()
            ),
        ));
    }
    let mode = meta.permissions().mode() & 0o777;
    let too_open = if private { 0o077 } else { 0o022 };
    if mode & too_open != 0 {
        return Err(refuse(
            name,
            path,
            format!("has mode {mode:04o}, open to other users"),
            format!(
                "remove it (`rm {}`) or make it private (`chmod 600 {}`)",
                path.display(),
                path.display()
            ),
        ));
    }
    Ok(())
}

/// Checks the directory the files are in: root's or ours, and sticky if others may write it
/// (so nobody can replace our files there).
fn check_dir(name: &str) -> Result<(), ShmError> {
    let path = Path::new(SHM_DIR);
    let meta = std::fs::symlink_metadata(path).map_err(|e| ShmError::Os {
        name: name.to_string(),
        what: format!("cannot inspect {SHM_DIR}"),
        error: e.to_string(),
    })?;
    let mode = meta.permissions().mode();
    let owner_ok = meta.uid() == 0 || meta.uid() == euid();
    let others_write = mode & 0o022 != 0;
    if !meta.is_dir() || !owner_ok || (others_write && mode & 0o1000 == 0) {
        return Err(refuse(
            name,
            path,
            format!(
                "is not a directory of root or uid {} that only its owner may change (uid {}, \
                 mode {:04o})",
                euid(),
                meta.uid(),
                mode & 0o7777
            ),
            format!("restore it: `chown root {SHM_DIR}; chmod 1777 {SHM_DIR}`"),
        ));
    }
    Ok(())
}

/// Whether two open files are the same file.
fn same_file(a: &File, path: &Path) -> bool {
    match (a.metadata(), std::fs::symlink_metadata(path)) {
        (Ok(a), Ok(b)) => a.dev() == b.dev() && a.ino() == b.ino(),
        _ => false,
    }
}

/// Whether a live process owns segment `name` (holds its lock).
pub fn owner_alive(name: &str) -> bool {
    let Ok(file) = open_nofollow(&lock_path(name), false, false) else {
        return false;
    };
    // SAFETY: flock on a valid descriptor we own; no memory is involved.
    let got = unsafe { libc::flock(file.as_raw_fd(), libc::LOCK_SH | libc::LOCK_NB) } == 0;
    if got {
        // SAFETY: as above; we release the shared lock we just took.
        unsafe { libc::flock(file.as_raw_fd(), libc::LOCK_UN) };
    }
    !got
}

/// Takes the owner's exclusive lock on `file`. A tool probing liveness ([`owner_alive`]) holds
/// a shared lock on the same file for a few microseconds, and `plc watch` probes at every
/// refresh: a refusal is tried again for `patience` before the owner is taken to be alive, so
/// a dead owner's segment is not refused to its successor because a reader looked at it.
fn lock_exclusive(file: &File, patience: Duration) -> bool {
    let deadline = Instant::now() + patience;
    loop {
        // SAFETY: flock on a valid descriptor we own; no memory is involved.
        if unsafe { libc::flock(file.as_raw_fd(), libc::LOCK_EX | libc::LOCK_NB) } == 0 {
            return true;
        }
        if Instant::now() >= deadline {
            return false;
        }
        std::thread::sleep(Duration::from_millis(1));
    }
}

/// The lock of `name`, taken: `Ok(None)` if a live process holds it.
fn acquire_lock(name: &str, patience: Duration) -> Result<Option<File>, ShmError> {
    let path = lock_path(name);
    // Each round loses only to an owner that stopped (and unlinked the file) meanwhile.
    for _ in 0..100 {
        let file = match open_nofollow(&path, true, true) {
            Ok(f) => f,
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists => {
                match open_nofollow(&path, true, false) {
                    Ok(f) => f,
                    Err(e) if e.kind() == io::ErrorKind::NotFound => continue,
                    Err(e) => return Err(open_error(name, &path, "cannot open the lock file", e)),
                }
            }
            Err(e) => return Err(open_error(name, &path, "cannot create the lock file", e)),
        };
        check_file(name, &path, &file, true)?;
        if !lock_exclusive(&file, patience) {
            return Ok(None);
        }
        if same_file(&file, &path) {
            return Ok(Some(file));
        }
    }
    Err(ShmError::Os {
        name: name.to_string(),
        what: format!("cannot hold the lock file {}", path.display()),
        error: "it was removed and created again a hundred times in a row".into(),
    })
}

/// A shared mapping of a segment file.
struct Mapping {
    ptr: *mut u8,
    len: usize,
    guard: Option<Guard>,
    _fd: OwnedFd,
}

impl Mapping {
    fn new(file: File, len: usize) -> io::Result<Mapping> {
        if len == 0 {
            return Err(io::Error::new(io::ErrorKind::InvalidData, "it is empty"));
        }
        // SAFETY: a fresh shared mapping of an open file; the kernel picks the address.
        let ptr = unsafe {
            libc::mmap(
                std::ptr::null_mut(),
                len,
                libc::PROT_READ | libc::PROT_WRITE,
                libc::MAP_SHARED,
                file.as_raw_fd(),
                0,
            )
        };
        if ptr == libc::MAP_FAILED {
            return Err(io::Error::last_os_error());
        }
        let ptr = ptr as *mut u8;
        Ok(Mapping {
            ptr,
            len,
            guard: Some(Guard::register(ptr, len)),
            _fd: file.into(),
        })
    }

    /// The mapping as a `Base`.
    fn base(&self) -> Base {
        // SAFETY: page aligned, `len` bytes, mapped until `self` drops (its owner keeps both).
        unsafe { Base::new(self.ptr, self.len) }
    }
}

impl Drop for Mapping {
    fn drop(&mut self) {
        // Unguard first: once unmapped, the range may be reused by anything else.
        drop(self.guard.take());
        // SAFETY: our own mapping, unmapped once; nothing uses it after this.
        unsafe { libc::munmap(self.ptr as *mut libc::c_void, self.len) };
    }
}

fn unlink(path: &Path) {
    let _ = std::fs::remove_file(path);
}

/// Marks a dead owner's segment replaced (readers still mapping it learn to attach again) and
/// unlinks it; returns its generation. We hold the name's lock.
fn remove_leftover(name: &str) -> Result<u64, ShmError> {
    let path = shm_path(name);
    let file = match open_nofollow(&path, true, false) {
        Ok(f) => f,
        Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(0),
        Err(e) => return Err(open_error(name, &path, "cannot open the old segment", e)),
    };
    check_file(name, &path, &file, true)?;
    let len = file.metadata().map(|m| m.len()).unwrap_or(0);
    let mut last = 0;
    // A truncated or empty leftover is only removed: there is nothing to mark.
    if let Ok(len) = usize::try_from(len)
        && len >= IMAGE
        && let Ok(old) = Mapping::new(file, len)
    {
        let base = old.base();
        if matches!(base.load(H_MAGIC), MAGIC | MAGIC_CLOSED) {
            last = base.load(H_GENERATION);
        }
        base.store(H_MAGIC, MAGIC_REPLACED);
    }
    unlink(&path);
    Ok(last)
}

/// Removes what killed owners of this user left under other names: for each name whose lock
/// nobody holds, the segment and the lock file. Best effort: a file that cannot be removed
/// stays, and is tried again by the next owner.
fn sweep(except: &str) {
    let Ok(entries) = std::fs::read_dir(SHM_DIR) else {
        return;
    };
    let me = euid();
    let mut names: Vec<String> = entries
        .flatten()
        .filter(|e| e.metadata().is_ok_and(|m| m.is_file() && m.uid() == me))
        .filter_map(|e| {
            let n = e.file_name().into_string().ok()?;
            let rest = n.strip_prefix(PREFIX)?;
            let rest = rest.strip_suffix(".lock").unwrap_or(rest);
            normalise(rest).ok().filter(|r| r != except)
        })
        .collect();
    names.sort();
    names.dedup();
    for name in names {
        if let Ok(Some(lock)) = acquire_lock(&name, Duration::ZERO) {
            if remove_leftover(&name).is_ok() {
                unlink(&lock_path(&name));
            }
            drop(lock);
        }
    }
}

/// Creates the segment file of `name` (nothing may be at its path), `size` bytes, mapped.
fn create_mapping(name: &str, size: usize) -> Result<Mapping, ShmError> {
    let path = shm_path(name);
    let file = open_nofollow(&path, true, true)
        .map_err(|e| open_error(name, &path, "cannot create", e))?;
    file.set_len(size as u64)
        .and_then(|()| Mapping::new(file, size))
        .map_err(|e| {
            unlink(&path);
            open_error(name, &path, "cannot size and map", e)
        })
}

/// A generation for a new segment after one of generation `last` (0: none): the creation time
/// in microseconds, and above `last` whatever the clock says.
pub fn next_generation(last: u64) -> u64 {
    let now_us = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_micros() as u64);
    now_us.max(last.saturating_add(1))
}

/// A mapped segment.
pub struct Segment {
    mapping: Option<Mapping>,
    base: Base,
    name: String,
    /// The owner's lock, held for the segment's life (`None` for readers).
    lock: Option<File>,
}

impl Segment {
    /// Creates segment `name` of `size` bytes as its owner. A segment left behind by a dead
    /// owner is replaced (its readers are told so); one whose owner is alive is refused.
    /// Returns the new segment and its generation: above the replaced segment's, and the
    /// creation time in microseconds otherwise, so that two runs of one name differ.
    pub fn create(name: &str, size: usize) -> Result<(Segment, u64), ShmError> {
        check_dir(name)?;
        sweep(name);
        let Some(lock) = acquire_lock(name, Duration::from_millis(100))? else {
            let pid = Segment::open(name)
                .map(|s| s.base.load(super::layout::S_PID))
                .unwrap_or(0);
            return Err(ShmError::OwnerAlive {
                name: name.to_string(),
                pid,
            });
        };
        let made = remove_leftover(name).and_then(|last| Ok((last, create_mapping(name, size)?)));
        let (last, mapping) = match made {
            Ok(m) => m,
            Err(e) => {
                // Still holding the lock: nobody else uses the file.
                unlink(&lock_path(name));
                return Err(e);
            }
        };
        let generation = next_generation(last);
        let base = mapping.base();
        Ok((
            Segment {
                mapping: Some(mapping),
                base,
                name: name.to_string(),
                lock: Some(lock),
            },
            generation,
        ))
    }

    /// Maps an existing segment as a reader.
    pub fn open(name: &str) -> Result<Segment, ShmError> {
        let path = shm_path(name);
        let file = open_nofollow(&path, true, false).map_err(|e| match e.kind() {
            io::ErrorKind::NotFound => ShmError::NotFound(name.to_string()),
            _ => open_error(name, &path, "cannot open", e),
        })?;
        check_file(name, &path, &file, false)?;
        let len = file
            .metadata()
            .map_err(|e| open_error(name, &path, "cannot inspect", e))?
            .len();
        let len = usize::try_from(len).unwrap_or(usize::MAX);
        if len < IMAGE {
            return Err(ShmError::TooSmall {
                name: name.to_string(),
                len,
                needed: IMAGE,
            });
        }
        let mapping =
            Mapping::new(file, len).map_err(|e| open_error(name, &path, "cannot map", e))?;
        let base = mapping.base();
        Ok(Segment {
            mapping: Some(mapping),
            base,
            name: name.to_string(),
            lock: None,
        })
    }

    /// The mapping.
    pub fn base(&self) -> Base {
        self.base
    }

    /// The segment's name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Whether this process owns the segment.
    pub fn is_owner(&self) -> bool {
        self.lock.is_some()
    }

    /// Replaces the owner's segment file by a new one of `size` bytes (the old one was
    /// truncated by another process), under the lock it holds, and returns the new mapping.
    /// Readers still mapping the old file see it gone and attach again.
    pub fn renew(&mut self, size: usize) -> Result<Base, ShmError> {
        if self.lock.is_none() {
            return Err(ShmError::NotOwner(self.name.clone()));
        }
        let path = shm_path(&self.name);
        // Whatever is at the path now (the truncated file, or anything put there since) goes:
        // nobody else may create the name while we hold its lock.
        unlink(&path);
        let mapping = create_mapping(&self.name, size)?;
        self.base = mapping.base();
        self.mapping = Some(mapping);
        Ok(self.base)
    }

    /// Whether another process truncated the segment under this mapping: it now reads zeros,
    /// and what is written into it reaches nobody.
    pub fn damaged(&self) -> bool {
        self.mapping
            .as_ref()
            .and_then(|m| m.guard.as_ref())
            .is_some_and(Guard::damaged)
    }
}

impl Drop for Segment {
    fn drop(&mut self) {
        let Some(lock) = self.lock.take() else {
            return;
        };
        // Readers still mapping this segment must learn that nobody publishes into it or
        // drains its mailbox any more, even once a new owner has created the name again.
        self.base.store(H_MAGIC, MAGIC_CLOSED);
        drop(self.mapping.take());
        // Still holding the lock: no new owner can have created either file meanwhile.
        unlink(&shm_path(&self.name));
        unlink(&lock_path(&self.name));
        drop(lock);
    }
}

/// Names of the segments under /dev/shm.
pub fn names() -> Vec<String> {
    let mut out: Vec<String> = std::fs::read_dir(SHM_DIR)
        .into_iter()
        .flatten()
        .flatten()
        .filter_map(|e| {
            let n = e.file_name().into_string().ok()?;
            let rest = n.strip_prefix(PREFIX)?;
            (!rest.ends_with(".lock")).then(|| rest.to_string())
        })
        .collect();
    out.sort();
    out
}
