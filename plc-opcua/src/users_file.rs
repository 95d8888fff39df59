//! The users file as a running server follows it: read again when it changes, so a user added
//! with `plc opcua user add` may sign in, and a user removed from the file may no longer sign in
//! or write, without a restart. A file that becomes unreadable or invalid lets nobody write
//! until it is fixed (it fails closed), and says why in the log.

use crate::users::Users;
use std::os::unix::fs::MetadataExt;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// How often the file is looked at, at most: a look is one `lstat`, but the server asks at
/// every write and for every node's UserAccessLevel.
const LOOK_EVERY: Duration = Duration::from_secs(1);

/// The server's users: from its users file if it has one, followed as the file changes.
pub struct UsersFile {
    path: Option<PathBuf>,
    state: Mutex<State>,
}

struct State {
    users: Arc<Users>,
    /// What the file was when `users` was read from it (`None`: it could not be looked at).
    stamp: Option<Stamp>,
    looked: Instant,
}

/// What tells a changed file: its inode (a save renames a new file over it), size and
/// modification time.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
struct Stamp {
    inode: u64,
    size: u64,
    modified_ns: i128,
}

fn stamp(path: &Path) -> Option<Stamp> {
    // `symlink_metadata`: a link is never followed (reading one is refused too).
    let meta = std::fs::symlink_metadata(path).ok()?;
    Some(Stamp {
        inode: meta.ino(),
        size: meta.size(),
        modified_ns: i128::from(meta.mtime()) * 1_000_000_000 + i128::from(meta.mtime_nsec()),
    })
}

impl UsersFile {
    /// The users of `path`, read now (an error if the file cannot be read: the server does not
    /// start with a broken users file); without a path, nobody may write.
    pub fn open(path: Option<&Path>) -> Result<UsersFile, crate::users::UsersError> {
        let (users, stamp) = match path {
            Some(p) => {
                let stamp = stamp(p);
                (Users::load(p)?, stamp)
            }
            None => (Users::default(), None),
        };
        Ok(UsersFile {
            path: path.map(Path::to_path_buf),
            state: Mutex::new(State {
                users: Arc::new(users),
                stamp,
                looked: Instant::now(),
            }),
        })
    }

    /// The users now: the file read again first if it changed since it was last read.
    pub fn current(&self) -> Arc<Users> {
        let mut state = self.state.lock().unwrap_or_else(|e| e.into_inner());
        let Some(path) = &self.path else {
            return state.users.clone();
        };
        if state.looked.elapsed() < LOOK_EVERY {
            return state.users.clone();
        }
        state.looked = Instant::now();
        let now = stamp(path);
        if now == state.stamp {
            return state.users.clone();
        }
        state.stamp = now;
        state.users = Arc::new(match Users::load(path) {
            Ok(users) => {
                log::info!(
                    "users file {} changed: {} users may write",
                    path.display(),
                    users.len()
                );
                users
            }
            Err(e) => {
                log::error!("{e}; until it is fixed, nobody may write");
                Users::default()
            }
        });
        state.users.clone()
    }

    /// Test hook: looks at the file at the next [`current`](Self::current), however recently
    /// it looked.
    #[cfg(test)]
    fn look_now(&self) {
        let mut state = self.state.lock().unwrap_or_else(|e| e.into_inner());
        state.looked = Instant::now() - LOOK_EVERY;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::users::add_user;

    #[test]
    fn a_user_added_or_removed_counts_without_a_restart_and_a_broken_file_lets_nobody_write() {
        let dir = std::env::temp_dir().join(format!("plc-opcua-follow-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("users");
        add_user(&path, "operator", "pw").unwrap();
        let file = UsersFile::open(Some(&path)).unwrap();
        assert!(file.current().contains("operator"));

        add_user(&path, "setter", "pw2").unwrap();
        file.look_now();
        let users = file.current();
        assert!(users.contains("operator") && users.verify("setter", "pw2"));

        let mut fewer = Users::load(&path).unwrap();
        fewer = Users::parse(&fewer.to_text().replace("operator:", "# operator:")).unwrap();
        fewer.save(&path).unwrap();
        file.look_now();
        assert!(!file.current().contains("operator"), "removed at once");

        std::fs::write(&path, "not a users file\n").unwrap();
        file.look_now();
        assert!(file.current().is_empty(), "a broken file lets nobody write");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn without_a_file_nobody_may_write() {
        assert!(UsersFile::open(None).unwrap().current().is_empty());
    }
}
