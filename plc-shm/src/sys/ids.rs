//! Who this process is, as the kernel checks files and sockets (one answer for the segment's
//! directory, its policy and the retained values' files), and the system's groups by name and
//! by id.

use crate::error::Cause;
use crate::error::ShmError;
use std::ffi::{CStr, CString};

/// This process's effective uid.
pub fn euid() -> u32 {
    // SAFETY: geteuid has no preconditions and cannot fail.
    unsafe { libc::geteuid() }
}

/// A group resolved to its id.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Group {
    /// Its name.
    pub name: String,
    /// Its id.
    pub gid: u32,
}

/// The id of group `name`, from the system's group database.
pub fn group(segment: &str, name: &str, role: &str) -> Result<Group, ShmError> {
    let unknown = |why: Cause| ShmError::Os {
        name: segment.to_string(),
        what: format!("cannot use group `{name}` as the {role} group"),
        error: why,
    };
    let c = CString::new(name).map_err(|_| unknown("the name holds a NUL byte".into()))?;
    // SAFETY: group is plain data; getgrnam_r fills it, with its strings in `buf`.
    let mut group: libc::group = unsafe { std::mem::zeroed() };
    let mut result: *mut libc::group = std::ptr::null_mut();
    let mut buf = vec![0 as libc::c_char; 1 << 16];
    // SAFETY: valid pointers and the buffer's true length.
    let r = unsafe {
        libc::getgrnam_r(
            c.as_ptr(),
            &mut group,
            buf.as_mut_ptr(),
            buf.len(),
            &mut result,
        )
    };
    if r != 0 {
        return Err(unknown(Cause::system(std::io::Error::from_raw_os_error(r))));
    }
    if result.is_null() {
        return Err(unknown(Cause::Reason(format!(
            "there is no such group on this machine (`getent group {name}`); create it \
             (`groupadd {name}`) or name another"
        ))));
    }
    Ok(Group {
        name: name.to_string(),
        gid: group.gr_gid,
    })
}

/// The name of group `gid`, or its number.
pub fn group_name(gid: u32) -> String {
    // SAFETY: as in `group`.
    let mut group: libc::group = unsafe { std::mem::zeroed() };
    let mut result: *mut libc::group = std::ptr::null_mut();
    let mut buf = vec![0 as libc::c_char; 1 << 16];
    // SAFETY: valid pointers and the buffer's true length.
    let r = unsafe { libc::getgrgid_r(gid, &mut group, buf.as_mut_ptr(), buf.len(), &mut result) };
    if r == 0 && !result.is_null() {
        // SAFETY: getgrgid_r set gr_name to a NUL-terminated string inside `buf`.
        return unsafe { CStr::from_ptr(group.gr_name) }
            .to_string_lossy()
            .into_owned();
    }
    gid.to_string()
}

/// The name of user `uid` from the system's user database, if it has one (the name is as the
/// database holds it: a tool shows it escaped).
pub fn user_name(uid: u32) -> Option<String> {
    // SAFETY: passwd is plain data; getpwuid_r fills it, with its strings in `buf`.
    let mut pwd: libc::passwd = unsafe { std::mem::zeroed() };
    let mut result: *mut libc::passwd = std::ptr::null_mut();
    let mut buf = vec![0 as libc::c_char; 1 << 14];
    // SAFETY: valid pointers and the buffer's true length.
    let r = unsafe { libc::getpwuid_r(uid, &mut pwd, buf.as_mut_ptr(), buf.len(), &mut result) };
    if r != 0 || result.is_null() || pwd.pw_name.is_null() {
        return None;
    }
    // SAFETY: getpwuid_r set pw_name to a NUL-terminated string inside `buf`.
    Some(
        unsafe { CStr::from_ptr(pwd.pw_name) }
            .to_string_lossy()
            .into_owned(),
    )
}
