//! The runtime directory: where a program's socket (`<name>.sock`) and lock file
//! (`<name>.lock`) live while it runs.
//!
//! An owner's directory is `$PLC_VARS_RUNTIME_DIR` if set, else `/run/plc-vars` for root and
//! `$XDG_RUNTIME_DIR/plc-vars` for other users, else `/tmp/plc-vars-<uid>`. It is created
//! mode 0700 (0750 with the program's read group) and must be the owner's, not a link, and
//! closed to other users (a group may only read and enter it); anything else is refused with a
//! message naming it and the fix, as PostgreSQL and OpenSSH do with their directories.
//!
//! Owner liveness is an exclusive `flock` on the lock file: the kernel releases it when the
//! owner dies, however it dies, and unlike a pid it cannot be reused by an unrelated process.
//! Nothing here follows a symbolic link (`O_NOFOLLOW`; files are created with `O_EXCL`).
//!
//! Removal: an owner that stops cleanly unlinks its socket, then its lock file, then releases
//! the lock. An owner that starts takes the lock and then checks that the file it locked is
//! still the one at the path: if the previous owner unlinked it meanwhile, it starts over with
//! a new file, so two owners never hold locks on two files of one name. What a killed owner
//! leaves behind is removed by the next owner of this user that starts in the directory,
//! whatever its name, once it holds that name's lock (so that owner is gone).

use super::ids::Group;
use super::ids::euid;
use crate::error::Cause;
use crate::error::ShmError;
use std::fs::{File, OpenOptions};
use std::io;
use std::os::fd::AsRawFd;
use std::os::unix::fs::{DirBuilderExt, FileTypeExt, MetadataExt, OpenOptionsExt, PermissionsExt};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use crate::env::RUNTIME_DIR_ENV;

/// The program's segment name from what a user typed: `press`, `plc.press` or a path to its
/// socket (`/run/plc-vars/press.sock`) all mean `press`.
pub fn normalise(name: &str) -> Result<String, ShmError> {
    // A path is a socket's: `<dir>/<name>.sock`.
    let n = match name.rsplit_once('/') {
        Some((_, file)) if file.ends_with(".sock") => file,
        Some(_) => return Err(ShmError::BadName(name.to_string())),
        None => name,
    };
    let n = n.strip_prefix("plc.").unwrap_or(n);
    let n = n
        .strip_suffix(".sock")
        .or_else(|| n.strip_suffix(".lock"))
        .unwrap_or(n);
    let valid = !n.is_empty()
        && n.len() <= 200
        && n != "."
        && n != ".."
        && n.chars()
            .all(|c| c.is_ascii_alphanumeric() || "_-.".contains(c));
    if valid {
        Ok(n.to_string())
    } else {
        Err(ShmError::BadName(name.to_string()))
    }
}

fn env_dir() -> Option<PathBuf> {
    std::env::var_os(RUNTIME_DIR_ENV)
        .filter(|v| !v.is_empty())
        .map(PathBuf::from)
}

/// The directory this process's programs use.
pub fn owner_dir() -> PathBuf {
    if let Some(dir) = env_dir() {
        return dir;
    }
    let uid = euid();
    if uid == 0 && Path::new("/run").is_dir() {
        return PathBuf::from("/run/plc-vars");
    }
    if let Some(xdg) = std::env::var_os("XDG_RUNTIME_DIR").map(PathBuf::from)
        && xdg.is_absolute()
        && xdg.is_dir()
    {
        return xdg.join("plc-vars");
    }
    std::env::temp_dir().join(format!("plc-vars-{uid}"))
}

/// The directories a tool looks in, each with the uid that must own it: the environment's
/// only, if set (any owner: the user named it); else this user's own (this user's) and root's
/// `/run/plc-vars` (root's, for programs run as system services). A directory of the expected
/// name that another user made first is not trusted.
pub fn tool_dirs() -> Vec<(PathBuf, Option<u32>)> {
    if let Some(dir) = env_dir() {
        return vec![(dir, None)];
    }
    let mut dirs = vec![(owner_dir(), Some(euid()))];
    let root = PathBuf::from("/run/plc-vars");
    if !dirs.iter().any(|(d, _)| *d == root) {
        dirs.push((root, Some(0)));
    }
    dirs
}

/// The socket of `name` in `dir`.
pub fn socket_path(dir: &Path, name: &str) -> PathBuf {
    dir.join(format!("{name}.sock"))
}

/// The lock file of `name` in `dir`.
pub fn lock_path(dir: &Path, name: &str) -> PathBuf {
    dir.join(format!("{name}.lock"))
}

/// A refusal of a file or directory that is a link, of the wrong kind, another user's, or
/// too open.
pub fn refuse(name: &str, path: &Path, problem: String, fix: String) -> ShmError {
    ShmError::Unsafe {
        name: name.to_string(),
        path: path.to_path_buf(),
        problem,
        fix,
    }
}

/// The error of opening `path`: a link, permission denied, or another OS error.
pub fn open_error(name: &str, path: &Path, what: &str, e: io::Error) -> ShmError {
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
            error: Cause::system(e),
        },
    }
}

/// Refuses a directory that is a link or no directory.
fn refuse_kind(name: &str, dir: &Path, meta: &std::fs::Metadata) -> Result<(), ShmError> {
    if meta.file_type().is_symlink() {
        return Err(refuse(
            name,
            dir,
            "is a symbolic link".into(),
            format!(
                "remove it (`rm {}`): plc-vars never follows a link there",
                dir.display()
            ),
        ));
    }
    if !meta.is_dir() {
        return Err(refuse(
            name,
            dir,
            "is not a directory".into(),
            format!("remove it (`rm {}`)", dir.display()),
        ));
    }
    Ok(())
}

/// The owner's directory, created if missing, checked (ours, no link, closed to others), and
/// opened to `group` (mode 0750, that group) if the program shares its variables with one.
pub fn ensure_owner_dir(name: &str, group: Option<&Group>) -> Result<PathBuf, ShmError> {
    let dir = owner_dir();
    match std::fs::DirBuilder::new().mode(0o700).create(&dir) {
        Ok(()) => {}
        Err(e) if e.kind() == io::ErrorKind::AlreadyExists => {}
        Err(e) => {
            return Err(open_error(
                name,
                &dir,
                &format!("cannot create the runtime directory (set {RUNTIME_DIR_ENV} to another)"),
                e,
            ));
        }
    }
    let meta =
        std::fs::symlink_metadata(&dir).map_err(|e| open_error(name, &dir, "cannot inspect", e))?;
    refuse_kind(name, &dir, &meta)?;
    let me = euid();
    if meta.uid() != me {
        return Err(refuse(
            name,
            &dir,
            format!(
                "belongs to uid {}, not to this program's uid {me}",
                meta.uid()
            ),
            format!(
                "remove it as its owner or root (`rm -r {}`), or set {RUNTIME_DIR_ENV} to a \
                 directory of uid {me}",
                dir.display()
            ),
        ));
    }
    let mode = meta.permissions().mode() & 0o7777;
    if mode & 0o027 != 0 {
        return Err(refuse(
            name,
            &dir,
            format!("has mode {mode:04o}, open to other users"),
            format!(
                "make it private (`chmod 700 {}`; 750 for a read group)",
                dir.display()
            ),
        ));
    }
    let Some(group) = group else {
        return Ok(dir);
    };
    let shared = mode & 0o050 != 0;
    if shared && meta.gid() != group.gid {
        return Err(refuse(
            name,
            &dir,
            format!(
                "is shared with group {} already, not with this program's group {}",
                meta.gid(),
                group.name
            ),
            format!(
                "give this program the same read group, or another directory \
                 ({RUNTIME_DIR_ENV})"
            ),
        ));
    }
    if !shared || mode & 0o050 != 0o050 {
        // Through a descriptor of the directory checked above: no path lookup between the
        // check and the change.
        let d = File::open(&dir).map_err(|e| open_error(name, &dir, "cannot open", e))?;
        let same = d
            .metadata()
            .is_ok_and(|m| m.ino() == meta.ino() && m.dev() == meta.dev());
        // SAFETY: plain system calls on an open descriptor.
        let ok = same
            && unsafe { libc::fchown(d.as_raw_fd(), u32::MAX, group.gid) } == 0
            && unsafe { libc::fchmod(d.as_raw_fd(), 0o750) } == 0;
        if !ok {
            return Err(ShmError::Os {
                name: name.to_string(),
                what: format!(
                    "cannot share {} with group {} (mode 0750)",
                    dir.display(),
                    group.name
                ),
                error: Cause::system(io::Error::last_os_error()),
            });
        }
    }
    Ok(dir)
}

/// Checks a directory a tool found a socket in: not a link, of the `expected` owner if one is
/// expected, and nobody but its owner may change it (so the socket in it is the owner's).
/// Returns its owner's uid.
pub fn check_tool_dir(name: &str, dir: &Path, expected: Option<u32>) -> Result<u32, ShmError> {
    let meta =
        std::fs::symlink_metadata(dir).map_err(|e| open_error(name, dir, "cannot inspect", e))?;
    refuse_kind(name, dir, &meta)?;
    if let Some(uid) = expected
        && meta.uid() != uid
    {
        return Err(refuse(
            name,
            dir,
            format!("belongs to uid {}, not to uid {uid}", meta.uid()),
            format!(
                "remove it as its owner or root (`rm -r {}`): another user may have made it \
                 to pass as a program",
                dir.display()
            ),
        ));
    }
    let mode = meta.permissions().mode() & 0o7777;
    if mode & 0o022 != 0 {
        return Err(refuse(
            name,
            dir,
            format!("has mode {mode:04o}: other users may change it"),
            format!(
                "make it private (`chmod 700 {}`); its program refuses it too",
                dir.display()
            ),
        ));
    }
    Ok(meta.uid())
}

/// Checks `path` as a program's socket in a directory of uid `owner`.
pub fn check_socket(name: &str, path: &Path, owner: u32) -> Result<(), ShmError> {
    let meta = std::fs::symlink_metadata(path).map_err(|e| match e.kind() {
        io::ErrorKind::NotFound => ShmError::NotFound(name.to_string()),
        _ => open_error(name, path, "cannot inspect", e),
    })?;
    if meta.file_type().is_symlink() {
        return Err(open_error(
            name,
            path,
            "",
            io::Error::from_raw_os_error(libc::ELOOP),
        ));
    }
    if !meta.file_type().is_socket() {
        return Err(refuse(
            name,
            path,
            "is not a socket".into(),
            format!("remove it (`rm {}`)", path.display()),
        ));
    }
    if meta.uid() != owner {
        return Err(refuse(
            name,
            path,
            format!(
                "belongs to uid {}, not to its directory's owner uid {owner}",
                meta.uid()
            ),
            format!("remove it (`rm {}`)", path.display()),
        ));
    }
    Ok(())
}

/// Opens `path` without following a link; `create` adds `O_CREAT | O_EXCL` (mode 0600).
fn open_nofollow(path: &Path, create: bool) -> io::Result<File> {
    let mut o = OpenOptions::new();
    o.read(true).write(true).custom_flags(libc::O_NOFOLLOW);
    if create {
        o.create_new(true).mode(0o600);
    }
    o.open(path)
}

/// Checks that `file` (opened from `path`) is a regular file of this user that nobody else may
/// read or write.
fn check_private_file(name: &str, path: &Path, file: &File) -> Result<(), ShmError> {
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
    if meta.uid() != euid() {
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
    if mode & 0o077 != 0 {
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

/// Whether two files are the same file.
fn same_file(a: &File, path: &Path) -> bool {
    match (a.metadata(), std::fs::symlink_metadata(path)) {
        (Ok(a), Ok(b)) => a.dev() == b.dev() && a.ino() == b.ino(),
        _ => false,
    }
}

/// Whether a live process owns segment `name` in `dir` (holds its lock).
pub fn owner_alive(dir: &Path, name: &str) -> bool {
    let Ok(file) = OpenOptions::new()
        .read(true)
        .custom_flags(libc::O_NOFOLLOW)
        .open(lock_path(dir, name))
    else {
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
/// a shared lock on the same file for a few microseconds: a refusal is tried again for
/// `patience` before the owner is taken to be alive.
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

/// The lock of `name` in `dir`, taken: `Ok(None)` if a live process holds it.
pub fn acquire_lock(dir: &Path, name: &str, patience: Duration) -> Result<Option<File>, ShmError> {
    let path = lock_path(dir, name);
    // Each round loses only to an owner that stopped (and unlinked the file) meanwhile.
    for _ in 0..100 {
        let file = match open_nofollow(&path, true) {
            Ok(f) => f,
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists => match open_nofollow(&path, false)
            {
                Ok(f) => f,
                Err(e) if e.kind() == io::ErrorKind::NotFound => continue,
                Err(e) => return Err(open_error(name, &path, "cannot open the lock file", e)),
            },
            Err(e) => return Err(open_error(name, &path, "cannot create the lock file", e)),
        };
        check_private_file(name, &path, &file)?;
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

/// Removes a dead owner's socket of `name` (we hold its lock). A link or anything but a
/// socket at its path is refused: nothing there was made by plc-vars.
pub fn remove_old_socket(dir: &Path, name: &str) -> Result<(), ShmError> {
    let path = socket_path(dir, name);
    match std::fs::symlink_metadata(&path) {
        Err(e) if e.kind() == io::ErrorKind::NotFound => Ok(()),
        Err(e) => Err(open_error(name, &path, "cannot inspect", e)),
        Ok(meta) if meta.file_type().is_symlink() => Err(open_error(
            name,
            &path,
            "",
            io::Error::from_raw_os_error(libc::ELOOP),
        )),
        Ok(meta) if !meta.file_type().is_socket() => Err(refuse(
            name,
            &path,
            "is not a socket".into(),
            format!("remove it (`rm {}`)", path.display()),
        )),
        Ok(_) => {
            unlink(&path);
            Ok(())
        }
    }
}

/// Removes `path` (a name in our own directory: unlinking never follows a link).
pub fn unlink(path: &Path) {
    let _ = std::fs::remove_file(path);
}

/// Names of the programs in `dir`: each `<name>.sock` or `<name>.lock`.
fn entries(dir: &Path, with_locks: bool) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .into_iter()
        .flatten()
        .flatten()
        .filter_map(|e| {
            let n = e.file_name().into_string().ok()?;
            let rest = n
                .strip_suffix(".sock")
                .or_else(|| n.strip_suffix(".lock").filter(|_| with_locks))?;
            normalise(rest).ok().filter(|r| r == rest)
        })
        .collect();
    names.sort();
    names.dedup();
    names
}

/// Removes what killed owners left in `dir` under other names: for each name whose lock
/// nobody holds, the socket and the lock file. Best effort: a file that cannot be removed
/// stays, and is tried again by the next owner.
pub fn sweep(dir: &Path, except: &str) {
    for name in entries(dir, true).into_iter().filter(|n| n != except) {
        if let Ok(Some(lock)) = acquire_lock(dir, &name, Duration::ZERO) {
            if remove_old_socket(dir, &name).is_ok() {
                unlink(&lock_path(dir, &name));
            }
            drop(lock);
        }
    }
}

/// The running programs' names in the tool directories, each with the directory it is in
/// (the first directory wins for a name found twice).
pub fn names() -> Vec<(String, PathBuf)> {
    let mut out: Vec<(String, PathBuf)> = Vec::new();
    for (dir, expected) in tool_dirs() {
        if check_tool_dir("", &dir, expected).is_err() {
            continue;
        }
        for name in entries(&dir, false) {
            if !out.iter().any(|(n, _)| *n == name) {
                out.push((name, dir.clone()));
            }
        }
    }
    out.sort();
    out
}
