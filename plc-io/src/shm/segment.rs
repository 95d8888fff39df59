//! The one place that touches the `shared_memory` crate and the owner's lock file.
//!
//! `shared_memory::Shmem` is neither `Send` nor `Sync`, and a crashed owner leaves its mapping
//! behind; both facts are handled here. Owner liveness is an exclusive `flock` on a lock file
//! beside the segment: the kernel releases it when the owner dies, however it dies, and unlike
//! a pid it cannot be reused by an unrelated process.
//!
//! The lock file is never deleted. Deleting it while holding the lock would let a second owner
//! create and lock a new file at the same path while the first still holds the old one: two
//! live owners. It also keeps the last generation of the name, so generations increase across
//! clean restarts as they do across takeovers.

use super::ShmError;
use super::layout::{Base, H_GENERATION, H_MAGIC, MAGIC, MAGIC_CLOSED, MAGIC_REPLACED, S_PID};
use shared_memory::{Shmem, ShmemConf, ShmemError};
use std::fs::{File, OpenOptions};
use std::io::Read;
use std::os::fd::AsRawFd;
use std::os::unix::fs::{FileExt, OpenOptionsExt};
use std::path::PathBuf;
use std::time::{Duration, Instant};

/// Prefix of every segment under /dev/shm, so `plc list` finds ours and nothing else.
pub const PREFIX: &str = "plc.";

/// The program's segment name from what a user typed: `press`, `plc.press` or
/// `/dev/shm/plc.press` all mean `press`.
pub fn normalise(name: &str) -> Result<String, ShmError> {
    let n = name.strip_prefix("/dev/shm/").unwrap_or(name);
    let n = n.strip_prefix(PREFIX).unwrap_or(n);
    let n = n.strip_suffix(".lock").unwrap_or(n);
    let valid = !n.is_empty()
        && n.len() <= 200
        && n.chars()
            .all(|c| c.is_ascii_alphanumeric() || "_-.".contains(c));
    if valid {
        Ok(n.to_string())
    } else {
        Err(ShmError::BadName(name.to_string()))
    }
}

fn os_id(name: &str) -> String {
    format!("/{PREFIX}{name}")
}

/// The lock file the owner holds.
pub fn lock_path(name: &str) -> PathBuf {
    PathBuf::from(format!("/dev/shm/{PREFIX}{name}.lock"))
}

/// Whether a live process owns segment `name` (holds its lock).
pub fn owner_alive(name: &str) -> bool {
    let Ok(file) = File::open(lock_path(name)) else {
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
/// a shared lock on the same file for a few microseconds, and `plc watch` probes at every
/// refresh: a refusal is tried again for a moment before the owner is taken to be alive, so a
/// dead owner's segment is not refused to its successor because a reader looked at it.
fn lock_exclusive(file: &File) -> bool {
    let deadline = Instant::now() + Duration::from_millis(100);
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

/// A mapped segment.
pub struct Segment {
    /// Held for its drop, which unmaps (and, for the owner, unlinks) the segment. Fields drop
    /// in declaration order: the mapping before the lock, so no new owner can create the name
    /// while ours is still linked.
    _shmem: Shmem,
    base: Base,
    name: String,
    /// The owner's lock, held for the segment's life (`None` for readers).
    lock: Option<File>,
}

impl Segment {
    /// Creates segment `name` of `size` bytes as its owner. A segment left behind by a dead
    /// owner is replaced (its readers are told so); one whose owner is alive is refused.
    /// Returns the new segment and its generation: one more than the last owner's of this
    /// name, whether it stopped cleanly or died.
    pub fn create(name: &str, size: usize) -> Result<(Segment, u64), ShmError> {
        let mut lock = OpenOptions::new()
            .read(true)
            .write(true)
            .create(true)
            .truncate(false)
            .mode(0o600)
            .open(lock_path(name))
            .map_err(|e| ShmError::Os {
                name: name.to_string(),
                what: format!("cannot open the lock file {}", lock_path(name).display()),
                error: e.to_string(),
            })?;
        if !lock_exclusive(&lock) {
            let pid = Segment::open(name).map(|s| s.base.load(S_PID)).unwrap_or(0);
            return Err(ShmError::OwnerAlive {
                name: name.to_string(),
                pid,
            });
        }
        let mut text = String::new();
        let mut last = match lock.read_to_string(&mut text) {
            Ok(_) => text.trim().parse::<u64>().unwrap_or(0),
            Err(_) => 0,
        };
        let shmem = match ShmemConf::new().size(size).os_id(os_id(name)).create() {
            Ok(s) => s,
            Err(ShmemError::MappingIdExists) => {
                // We hold the lock, so whoever created this mapping is dead.
                if let Ok(mut old) = ShmemConf::new().os_id(os_id(name)).open() {
                    if old.len() >= 64 {
                        // SAFETY: the mapping is at least 64 bytes and page aligned.
                        let base = unsafe { Base::new(old.as_ptr(), old.len()) };
                        if matches!(base.load(H_MAGIC), MAGIC | MAGIC_CLOSED) {
                            last = last.max(base.load(H_GENERATION));
                        }
                        base.store(H_MAGIC, MAGIC_REPLACED);
                    }
                    old.set_owner(true); // unlinked when dropped
                }
                ShmemConf::new()
                    .size(size)
                    .os_id(os_id(name))
                    .create()
                    .map_err(|e| os_error(name, "cannot create the shared memory", e))?
            }
            Err(e) => return Err(os_error(name, "cannot create the shared memory", e)),
        };
        let generation = last + 1;
        // Best effort: if the lock file cannot be written, only the monotonicity of
        // generations across clean restarts is lost (takeovers still read the old segment's).
        let _ = lock
            .set_len(0)
            .and_then(|()| lock.write_all_at(format!("{generation}\n").as_bytes(), 0));
        // SAFETY: the mapping is page aligned, `len` bytes long, and lives in `shmem`, which
        // the returned Segment owns together with `base`.
        let base = unsafe { Base::new(shmem.as_ptr(), shmem.len()) };
        Ok((
            Segment {
                _shmem: shmem,
                base,
                name: name.to_string(),
                lock: Some(lock),
            },
            generation,
        ))
    }

    /// Maps an existing segment as a reader.
    pub fn open(name: &str) -> Result<Segment, ShmError> {
        let shmem = ShmemConf::new()
            .os_id(os_id(name))
            .open()
            .map_err(|e| match e {
                ShmemError::MapOpenFailed(_) => ShmError::NotFound(name.to_string()),
                e => os_error(name, "cannot open the shared memory", e),
            })?;
        // SAFETY: as in `create`.
        let base = unsafe { Base::new(shmem.as_ptr(), shmem.len()) };
        Ok(Segment {
            _shmem: shmem,
            base,
            name: name.to_string(),
            lock: None,
        })
    }

    /// The mapping.
    pub fn base(&self) -> Base {
        self.base
    }

    /// The segment's name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Whether this process owns the segment.
    pub fn is_owner(&self) -> bool {
        self.lock.is_some()
    }
}

impl Drop for Segment {
    fn drop(&mut self) {
        if self.lock.is_some() {
            // Readers still mapping this segment must learn that nobody publishes into it or
            // drains its mailbox any more, even once a new owner has created the name again.
            // Then the fields drop: the mapping is unlinked, then the lock is released.
            self.base.store(H_MAGIC, MAGIC_CLOSED);
        }
    }
}

fn os_error(name: &str, what: &str, e: ShmemError) -> ShmError {
    ShmError::Os {
        name: name.to_string(),
        what: what.to_string(),
        error: e.to_string(),
    }
}

/// Names of the segments under /dev/shm.
pub fn names() -> Vec<String> {
    let mut out: Vec<String> = std::fs::read_dir("/dev/shm")
        .into_iter()
        .flatten()
        .flatten()
        .filter_map(|e| {
            let n = e.file_name().into_string().ok()?;
            let rest = n.strip_prefix(PREFIX)?;
            (!rest.ends_with(".lock")).then(|| rest.to_string())
        })
        .collect();
    out.sort();
    out
}
