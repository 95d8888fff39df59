//! The store directory: the last birth/death sequence number (bdSeq) used, so a restarted edge
//! node goes on with the next and a host never takes a new session's death for an old one's.

use std::fs::{self, OpenOptions};
use std::io::Read;
use std::os::unix::fs::{OpenOptionsExt, PermissionsExt};
use std::path::{Path, PathBuf};

const FILE: &str = "bdseq";
/// More than any valid file holds ("255\n"): a larger one is not ours.
const MAX_LEN: u64 = 16;

/// The store directory of one edge node.
#[derive(Debug)]
pub struct Store {
    dir: PathBuf,
}

impl Store {
    /// Opens (creating it, owner-only, when missing) the store directory `dir`; a symbolic
    /// link or a file there is refused.
    pub fn open(dir: &Path) -> Result<Store, String> {
        match fs::symlink_metadata(dir) {
            Ok(m) if m.is_dir() => {}
            Ok(_) => {
                return Err(format!(
                    "the store {} is not a directory (a link or a file): name a directory with \
                     --store",
                    dir.display()
                ));
            }
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
                fs::create_dir_all(dir).map_err(|e| {
                    format!("cannot create the store directory {}: {e}", dir.display())
                })?;
                let _ = fs::set_permissions(dir, fs::Permissions::from_mode(0o700));
            }
            Err(e) => return Err(format!("cannot read the store {}: {e}", dir.display())),
        }
        Ok(Store {
            dir: dir.to_path_buf(),
        })
    }

    /// The bdSeq last stored, `None` if none was; an unreadable or damaged file is an error
    /// that says which file and what to do.
    pub fn last_bd_seq(&self) -> Result<Option<u8>, String> {
        let path = self.dir.join(FILE);
        let bad = |why: String| {
            format!(
                "the store's bdSeq file {} {why}: remove it (the next birth then uses bdSeq 0)",
                path.display()
            )
        };
        let file = match OpenOptions::new()
            .read(true)
            .custom_flags(libc::O_NOFOLLOW)
            .open(&path)
        {
            Ok(f) => f,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
            Err(e) => return Err(bad(format!("cannot be opened ({e}; a link is refused)"))),
        };
        let meta = file.metadata().map_err(|e| bad(e.to_string()))?;
        if !meta.is_file() || meta.len() > MAX_LEN {
            return Err(bad("is not a small regular file".into()));
        }
        let mut text = String::new();
        file.take(MAX_LEN)
            .read_to_string(&mut text)
            .map_err(|e| bad(format!("cannot be read ({e})")))?;
        text.trim()
            .parse::<u8>()
            .map(Some)
            .map_err(|_| bad(format!("holds `{}`, not a number 0..255", text.trim())))
    }

    /// Stores `bd_seq` whole or not at all (plc-files: a new private temporary file, never
    /// through a link, synced, renamed over the old one, the directory synced), so a crash
    /// leaves the old number or the new, never half of one.
    pub fn save_bd_seq(&self, bd_seq: u8) -> Result<(), String> {
        plc_files::write_atomically(
            &self.dir.join(FILE),
            format!("{bd_seq}\n").as_bytes(),
            0o600,
        )
        .map_err(|e| {
            format!(
                "cannot store bdSeq in {}: {e}; check the store directory's permissions",
                self.dir.display()
            )
        })
    }

    /// The bdSeq for the next session: one after the last stored (255 wraps to 0), stored
    /// before it is used.
    pub fn next_bd_seq(&self) -> Result<u8, String> {
        let next = self.last_bd_seq()?.map_or(0, |b| b.wrapping_add(1));
        self.save_bd_seq(next)?;
        Ok(next)
    }
}

/// The default store directory of node `node` of group `group`: under `$XDG_STATE_HOME`, else
/// `~/.local/state`, else the temporary directory.
pub fn default_dir(group: &str, node: &str) -> PathBuf {
    let base = std::env::var_os("XDG_STATE_HOME")
        .filter(|s| !s.is_empty())
        .map(PathBuf::from)
        .or_else(|| {
            std::env::var_os("HOME")
                .filter(|s| !s.is_empty())
                .map(|h| PathBuf::from(h).join(".local/state"))
        })
        .unwrap_or_else(std::env::temp_dir);
    base.join("plc-vars/sparkplug").join(group).join(node)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn temp_dir(what: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("plc-sparkplug-{what}-{}", std::process::id()));
        let _ = fs::remove_dir_all(&d);
        d
    }

    #[test]
    fn each_session_takes_the_next_bd_seq_and_a_restart_goes_on_from_it() {
        let dir = temp_dir("next");
        let store = Store::open(&dir).unwrap();
        assert_eq!(store.last_bd_seq(), Ok(None));
        assert_eq!(store.next_bd_seq(), Ok(0));
        assert_eq!(store.next_bd_seq(), Ok(1));
        let again = Store::open(&dir).unwrap();
        assert_eq!(again.next_bd_seq(), Ok(2));
        again.save_bd_seq(255).unwrap();
        assert_eq!(again.next_bd_seq(), Ok(0));
        let names: Vec<_> = fs::read_dir(&dir)
            .unwrap()
            .flatten()
            .map(|e| e.file_name())
            .collect();
        assert_eq!(names, ["bdseq"], "no temporary file left");
        fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_damaged_or_linked_file_is_an_error_that_says_what_to_do() {
        let dir = temp_dir("damaged");
        let store = Store::open(&dir).unwrap();
        fs::write(dir.join(FILE), "banana").unwrap();
        let e = store.last_bd_seq().unwrap_err();
        assert!(e.contains("remove it") && e.contains("banana"), "{e}");
        fs::write(dir.join(FILE), "x".repeat(100)).unwrap();
        assert!(
            store
                .last_bd_seq()
                .unwrap_err()
                .contains("small regular file")
        );
        fs::remove_file(dir.join(FILE)).unwrap();
        let target = dir.join("elsewhere");
        fs::write(&target, "7\n").unwrap();
        std::os::unix::fs::symlink(&target, dir.join(FILE)).unwrap();
        assert!(
            store
                .last_bd_seq()
                .unwrap_err()
                .contains("a link is refused")
        );
        // Writing replaces the link, never writes through it.
        store.save_bd_seq(9).unwrap();
        assert_eq!(fs::read_to_string(&target).unwrap(), "7\n");
        assert_eq!(store.last_bd_seq(), Ok(Some(9)));
        fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_store_that_is_a_link_or_a_file_is_refused() {
        let dir = temp_dir("notdir");
        fs::create_dir_all(&dir).unwrap();
        let file = dir.join("file");
        fs::write(&file, "").unwrap();
        assert!(Store::open(&file).unwrap_err().contains("not a directory"));
        let link = dir.join("link");
        std::os::unix::fs::symlink(&dir, &link).unwrap();
        assert!(Store::open(&link).unwrap_err().contains("not a directory"));
        fs::remove_dir_all(&dir).unwrap();
    }
}
