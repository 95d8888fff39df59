//! What the retain files rely on from the system: who we are, a temporary file that is always
//! new and private, whether the process that left one is gone, and the test hooks that stop a
//! save at each of its steps.

use std::fs::{self, File, OpenOptions};
use std::os::unix::fs::OpenOptionsExt;
use std::path::Path;

pub(super) fn euid() -> u32 {
    // SAFETY: geteuid has no preconditions and cannot fail.
    unsafe { libc::geteuid() }
}

/// Creates `path` for writing, mode 0600, failing if anything (a file, a link) is there: a
/// temporary file is always new. One left by an earlier process of this pid (a pid is reused)
/// in the checked directory is ours, and removed once.
pub(super) fn create_private(path: &Path) -> std::io::Result<File> {
    let open = || {
        OpenOptions::new()
            .write(true)
            .create_new(true)
            .mode(0o600)
            .custom_flags(libc::O_NOFOLLOW)
            .open(path)
    };
    match open() {
        Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => {
            fs::remove_file(path)?;
            open()
        }
        r => r,
    }
}

/// Whether process `pid` exists (a signal 0 reaches it, or exists but is not ours to signal).
pub(super) fn process_alive(pid: u32) -> bool {
    let Ok(pid) = i32::try_from(pid) else {
        return false;
    };
    // SAFETY: signal 0 only checks that the process exists; nothing is delivered.
    let reached = unsafe { libc::kill(pid, 0) } == 0;
    reached || std::io::Error::last_os_error().raw_os_error() == Some(libc::EPERM)
}
/// The steps of a save, where the `fault-injection` test hook can stop the process.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(not(feature = "fault-injection"), allow(dead_code))]
pub(super) enum FaultPoint {
    /// The temporary file is created, nothing written yet.
    BeforeWrite = 1,
    /// Written, not yet fsynced.
    BeforeFsync = 2,
    /// Fsynced, not yet renamed over the file.
    BeforeRename = 3,
    /// Renamed, the directory not yet fsynced.
    BeforeDirFsync = 4,
    /// Done.
    AfterDirFsync = 5,
}

/// Test hook (feature `fault-injection`, which only this crate's tests enable): when the
/// environment variable `PLC_RETAIN_FAULT` holds a step's number, the process aborts there, as
/// a crash would stop it. Without the feature it is nothing: a production program never aborts
/// because of its environment.
#[cfg(feature = "fault-injection")]
pub(super) fn fault_point(step: FaultPoint) {
    if std::env::var("PLC_RETAIN_FAULT").is_ok_and(|s| s == (step as u8).to_string()) {
        std::process::abort();
    }
}

#[cfg(not(feature = "fault-injection"))]
#[inline(always)]
pub(super) fn fault_point(_: FaultPoint) {}
