//! The segment's memory: an anonymous file (`memfd_create`) that exists only as long as a
//! process holds it, sized once and sealed so that nobody can change its size
//! (`F_SEAL_SHRINK | F_SEAL_GROW`), nor, once its owner mapped it writable, map it writable or
//! write it (`F_SEAL_FUTURE_WRITE`), nor add or remove seals (`F_SEAL_SEAL`), and, where the
//! kernel has it, never executable (`MFD_NOEXEC_SEAL`). Tools receive
//! the descriptor over the segment's socket and map it read-only: the seals are the kernel's,
//! so they hold against any process, the owner's own user's included.

use super::base::Base;
use super::guard::Guard;
use std::io;
use std::os::fd::{AsRawFd, FromRawFd, OwnedFd};

/// The seals every segment carries once its owner mapped it.
pub const SEALS: libc::c_int =
    libc::F_SEAL_SHRINK | libc::F_SEAL_GROW | libc::F_SEAL_FUTURE_WRITE | libc::F_SEAL_SEAL;

/// A new anonymous memory file labelled `label` (the label is only what `/proc/<pid>/fd`
/// shows; it need not be unique), sealable and closed on exec, with `flag` as well
/// (`MFD_NOEXEC_SEAL`, `MFD_EXEC`) where the kernel knows it: a kernel before 6.3 refuses
/// those (EINVAL) and gets the file without, as it makes every memory file.
pub fn memory_file(label: &str, flag: libc::c_uint) -> io::Result<OwnedFd> {
    let label = std::ffi::CString::new(label.replace('\0', "_"))
        .map_err(|e| io::Error::new(io::ErrorKind::InvalidInput, e))?;
    let create = |flags: libc::c_uint| {
        // SAFETY: a valid C string; the descriptor returned is ours.
        let raw = unsafe {
            libc::memfd_create(
                label.as_ptr(),
                libc::MFD_ALLOW_SEALING | libc::MFD_CLOEXEC | flags,
            )
        };
        if raw < 0 {
            Err(io::Error::last_os_error())
        } else {
            // SAFETY: a fresh descriptor nobody else owns.
            Ok(unsafe { OwnedFd::from_raw_fd(raw) })
        }
    };
    match create(flag) {
        Err(e) if e.raw_os_error() == Some(libc::EINVAL) && flag != 0 => create(0),
        made => made,
    }
}

/// A shared mapping of a segment.
pub struct Mapping {
    ptr: *mut u8,
    len: usize,
    guard: Option<Guard>,
    fd: OwnedFd,
}

// SAFETY: the mapping is plain memory valid until drop, used only through atomics (`Base`);
// moving the handle to another thread moves nothing the thread could misuse.
unsafe impl Send for Mapping {}

fn map(fd: &OwnedFd, len: usize, prot: libc::c_int) -> io::Result<*mut u8> {
    // SAFETY: a fresh shared mapping of an open file; the kernel picks the address.
    let ptr = unsafe {
        libc::mmap(
            std::ptr::null_mut(),
            len,
            prot,
            libc::MAP_SHARED,
            fd.as_raw_fd(),
            0,
        )
    };
    if ptr == libc::MAP_FAILED {
        Err(io::Error::last_os_error())
    } else {
        Ok(ptr as *mut u8)
    }
}

fn fcntl(fd: &OwnedFd, cmd: libc::c_int, arg: libc::c_int) -> io::Result<libc::c_int> {
    // SAFETY: fcntl with an integer argument on our descriptor.
    let r = unsafe { libc::fcntl(fd.as_raw_fd(), cmd, arg) };
    if r < 0 {
        Err(io::Error::last_os_error())
    } else {
        Ok(r)
    }
}

/// The seals on `fd`.
pub fn seals(fd: &OwnedFd) -> io::Result<libc::c_int> {
    fcntl(fd, libc::F_GET_SEALS, 0)
}

impl Mapping {
    /// A new segment of `len` bytes (zeroed), mapped writable for its owner and sealed.
    pub fn create(name: &str, len: usize) -> io::Result<Mapping> {
        if len == 0 {
            return Err(io::Error::new(
                io::ErrorKind::InvalidInput,
                "an empty segment",
            ));
        }
        // Never executable (`F_SEAL_EXEC` with it), which kernels set to `vm.memfd_noexec=2`
        // require.
        let fd = memory_file(&format!("plc.{name}"), libc::MFD_NOEXEC_SEAL)?;
        // SAFETY: plain system call on our descriptor.
        if unsafe { libc::ftruncate(fd.as_raw_fd(), len as libc::off_t) } != 0 {
            return Err(io::Error::last_os_error());
        }
        fcntl(
            &fd,
            libc::F_ADD_SEALS,
            libc::F_SEAL_SHRINK | libc::F_SEAL_GROW,
        )?;
        let ptr = map(&fd, len, libc::PROT_READ | libc::PROT_WRITE)?;
        // From here on no new writable mapping and no write(2): only the owner's mapping
        // above writes the segment.
        let mapping = Mapping {
            ptr,
            len,
            guard: Some(Guard::register(ptr, len)),
            fd,
        };
        fcntl(
            &mapping.fd,
            libc::F_ADD_SEALS,
            libc::F_SEAL_FUTURE_WRITE | libc::F_SEAL_SEAL,
        )?;
        Ok(mapping)
    }

    /// Maps a segment received from its owner, read-only. Refused unless it carries every seal
    /// (so nobody but its owner can change it, and its size stays what `fstat` says) and is at
    /// most `max` bytes (so a tool maps no more than a segment can need).
    pub fn receive(fd: OwnedFd, max: usize) -> io::Result<Mapping> {
        let bad = |why: String| io::Error::new(io::ErrorKind::InvalidData, why);
        let got = seals(&fd).map_err(|e| bad(format!("it is not a sealed memory file ({e})")))?;
        if got & SEALS != SEALS {
            return Err(bad(format!(
                "its seals are {got:#x}, not {SEALS:#x}: another process could change it"
            )));
        }
        // SAFETY: stat is plain data; fstat fills it.
        let mut st: libc::stat = unsafe { std::mem::zeroed() };
        // SAFETY: a valid stat buffer and our descriptor.
        if unsafe { libc::fstat(fd.as_raw_fd(), &mut st) } != 0 {
            return Err(io::Error::last_os_error());
        }
        let len = usize::try_from(st.st_size).unwrap_or(usize::MAX);
        if len == 0 || len > max {
            return Err(bad(format!(
                "it is {len} bytes; a segment is 1 to {max} bytes"
            )));
        }
        let ptr = map(&fd, len, libc::PROT_READ)?;
        Ok(Mapping {
            ptr,
            len,
            guard: Some(Guard::register(ptr, len)),
            fd,
        })
    }

    /// The mapping as a `Base`.
    pub fn base(&self) -> Base {
        // SAFETY: page aligned, `len` bytes, mapped until `self` drops (its owner keeps both).
        unsafe { Base::new(self.ptr, self.len) }
    }

    /// The segment's descriptor, to pass to tools.
    pub fn fd(&self) -> &OwnedFd {
        &self.fd
    }

    /// Whether the mapping was cut short under this process (it now reads zeros). The seals
    /// make this impossible for a segment; the guard stays as a second line.
    pub fn damaged(&self) -> bool {
        self.guard.as_ref().is_some_and(Guard::damaged)
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_segment_is_sealed_and_never_executable_where_the_kernel_can_say_so() {
        let m = Mapping::create("memfd_test", 4096).unwrap();
        let got = seals(m.fd()).unwrap();
        assert_eq!(got & SEALS, SEALS);
        // F_SEAL_EXEC exists from Linux 6.3 on.
        let release = std::fs::read_to_string("/proc/sys/kernel/osrelease").unwrap_or_default();
        let mut parts = release
            .trim()
            .split(['.', '-'])
            .map(|p| p.parse::<u32>().unwrap_or(0));
        let (major, minor) = (parts.next().unwrap_or(0), parts.next().unwrap_or(0));
        if (major, minor) >= (6, 3) {
            assert_ne!(got & libc::F_SEAL_EXEC, 0, "seals {got:#x}");
        }
    }
}
