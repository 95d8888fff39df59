//! What the retain files rely on from the system: whether the process that left a temporary
//! file is gone, and the test hook that stops a save at each of its steps.

use plc_files::Step;

/// Whether process `pid` exists (a signal 0 reaches it, or exists but is not ours to signal).
pub(super) fn process_alive(pid: u32) -> bool {
    let Ok(pid) = i32::try_from(pid) else {
        return false;
    };
    // SAFETY: signal 0 only checks that the process exists; nothing is delivered.
    let reached = unsafe { libc::kill(pid, 0) } == 0;
    reached || std::io::Error::last_os_error().raw_os_error() == Some(libc::EPERM)
}

/// Test hook (feature `fault-injection`, which only this crate's tests enable): when the
/// environment variable `PLC_RETAIN_FAULT` holds a step's number, the process aborts there, as
/// a crash would stop it. Without the feature it is nothing: a production program never aborts
/// because of its environment.
#[cfg(feature = "fault-injection")]
pub(super) fn fault_point(step: Step) {
    // The numbers the tests set: 1 created, nothing written; 2 written, not synced; 3 synced,
    // not renamed; 4 renamed, the directory not synced; 5 done.
    let number = match step {
        Step::Created => 1,
        Step::Written => 2,
        Step::Synced => 3,
        Step::Renamed => 4,
        Step::DirSynced => 5,
    };
    if std::env::var("PLC_RETAIN_FAULT").is_ok_and(|s| s == number.to_string()) {
        std::process::abort();
    }
}

#[cfg(not(feature = "fault-injection"))]
#[inline(always)]
pub(super) fn fault_point(_: Step) {}
