//! The module's bytes in an anonymous memory file that nobody can change any more
//! (`F_SEAL_WRITE`, `F_SEAL_SHRINK`, `F_SEAL_GROW`, `F_SEAL_SEAL`), which the dynamic loader
//! opens as `/proc/self/fd/N`. Why not the file itself: glibc returns the library it already
//! has for a path it loaded before (so a rebuilt module at the same path would run the old
//! code), a file can change after its checks, and `/run`, where a copy could go, may be
//! mounted `noexec`. The memory file stays open while the module is loaded, so its number,
//! and the path, is never reused for another module meanwhile.

use std::fs::File;
use std::io::{self, Write};
use std::os::fd::{AsRawFd, OwnedFd};

/// The seals of a module's memory file.
const SEALS: libc::c_int =
    libc::F_SEAL_WRITE | libc::F_SEAL_SHRINK | libc::F_SEAL_GROW | libc::F_SEAL_SEAL;

/// A sealed memory file holding a module's bytes.
#[derive(Debug)]
pub struct SealedCopy {
    fd: OwnedFd,
}

impl SealedCopy {
    /// Copies `bytes` into a new memory file labelled `label` and seals it.
    pub fn new(label: &str, bytes: &[u8]) -> io::Result<SealedCopy> {
        // Executable on purpose (`MFD_EXEC`), as kernels since 6.3 want it said.
        let fd =
            plc_shm::memory_file(&format!("plc-module.{label}"), libc::MFD_EXEC).map_err(|e| {
                match e.raw_os_error() {
                    Some(libc::EACCES) => io::Error::new(
                        e.kind(),
                        format!(
                            "{e}: this system forbids executable memory files \
                         (sysctl vm.memfd_noexec = 2), which loading a module needs"
                        ),
                    ),
                    _ => e,
                }
            })?;
        let mut file = File::from(fd);
        file.write_all(bytes)?;
        // SAFETY: fcntl with an integer argument on our descriptor.
        if unsafe { libc::fcntl(file.as_raw_fd(), libc::F_ADD_SEALS, SEALS) } != 0 {
            return Err(io::Error::last_os_error());
        }
        Ok(SealedCopy { fd: file.into() })
    }

    /// The path the loader opens it by, in this process.
    pub fn proc_path(&self) -> String {
        format!("/proc/self/fd/{}", self.fd.as_raw_fd())
    }

    /// The descriptor, for a trial child to receive.
    pub fn fd(&self) -> &OwnedFd {
        &self.fd
    }
}
