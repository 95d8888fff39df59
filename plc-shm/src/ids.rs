//! Who this process is, as the kernel checks files and sockets: one answer for the segment's
//! directory, its policy and the retained values' files.

/// This process's effective uid.
pub fn euid() -> u32 {
    // SAFETY: geteuid has no preconditions and cannot fail.
    unsafe { libc::geteuid() }
}
