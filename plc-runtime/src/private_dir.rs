//! What makes a directory unfit to hold a program's own files (retained values, the alarm
//! journal): a link in its place, another user's, or one others may write; and what makes
//! such a file unfit to be read: a link, not a regular file, another user's, or one others
//! may read or write. Each problem comes with what to do, for the caller's error.

use std::fs::Metadata;
use std::os::unix::fs::{MetadataExt, PermissionsExt};
use std::path::Path;

/// The problem with directory `dir` (whose `symlink_metadata` is `meta`) and its fix, if the
/// program's user `uid` should not keep its files there.
pub(crate) fn problem(dir: &Path, meta: &Metadata, uid: u32) -> Option<(String, String)> {
    if !meta.is_dir() {
        return Some((
            "is not a directory (a symbolic link is not followed)".into(),
            format!(
                "give the real directory instead, or remove the link (`rm {}`)",
                dir.display()
            ),
        ));
    }
    if meta.uid() != uid {
        return Some((
            format!(
                "belongs to uid {}, not to this program's uid {uid}",
                meta.uid()
            ),
            "use a directory of the program's own user".into(),
        ));
    }
    let mode = meta.permissions().mode() & 0o7777;
    if mode & 0o022 != 0 {
        return Some((
            format!("has mode {mode:04o}: other users may write it"),
            format!("make it private (`chmod 700 {}`)", dir.display()),
        ));
    }
    None
}

/// The problem and fix of a program's file at `path` that turned out to be a symbolic link
/// (opened with `O_NOFOLLOW`).
pub(crate) fn link_problem(path: &Path) -> (String, String) {
    (
        "is a symbolic link".into(),
        format!(
            "remove the link (`rm {}`) and give the real file's path",
            path.display()
        ),
    )
}

/// The problem with the program's file at `path` (opened, its metadata `meta`) and its fix,
/// if the program's user `uid` should not trust what it holds.
pub(crate) fn file_problem(path: &Path, meta: &Metadata, uid: u32) -> Option<(String, String)> {
    let mode = meta.permissions().mode() & 0o7777;
    let problem = if !meta.is_file() {
        "is not a regular file".to_string()
    } else if meta.uid() != uid {
        format!(
            "belongs to uid {}, not to this program's uid {uid}",
            meta.uid()
        )
    } else if mode & 0o077 != 0 {
        format!("has mode {mode:04o}, open to other users")
    } else {
        return None;
    };
    let fix = format!(
        "check its content, then make it the program's own and private \
         (`chown {uid} {p}; chmod 600 {p}`)",
        p = path.display()
    );
    Some((problem, fix))
}
