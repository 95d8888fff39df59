//! A segment as its owner holds it (the memory, the lock, the socket and its server) and as a
//! tool holds it (the memory, mapped read-only, and the connection it came through).

use super::ShmError;
use super::client::Client;
use super::error::Cause;
use super::layout::{H_MAGIC, MAGIC_CLOSED};
use super::policy::Policy;
use super::server::{Server, Setup};
use crate::sys::base::Base;
use crate::sys::memfd::Mapping;
use crate::sys::rundir;
use std::fs::File;
use std::os::fd::AsRawFd;
use std::os::unix::fs::PermissionsExt;
use std::path::PathBuf;
use std::time::Duration;

pub use crate::sys::rundir::normalise;

/// The largest descriptor a reader reads. A program with thousands of variables has a
/// descriptor of a few megabytes; a larger length is taken to be damage, not read, so another
/// process cannot make a tool allocate what it likes.
pub const MAX_DESCRIPTOR: usize = 64 << 20;
/// The largest image a reader copies, for the same reason (process images are kilobytes).
pub const MAX_IMAGE: usize = 256 << 20;
/// The largest segment a tool maps: a header, the largest image and the largest descriptor a
/// tool reads, and the words between.
const MAX_SEGMENT: usize = MAX_IMAGE + MAX_DESCRIPTOR + (1 << 20);

/// What only the owner has.
struct Owned {
    dir: PathBuf,
    /// Held for the segment's life.
    lock: File,
    server: Option<Server>,
}

/// A mapped segment.
pub struct Segment {
    /// Dropped last: the server threads and readers' answers use it until then.
    mapping: Mapping,
    base: Base,
    name: String,
    owned: Option<Owned>,
    client: Option<Client>,
}

/// A generation for a new segment: the creation time in microseconds, so that two runs of one
/// name differ and a later one is greater.
pub fn next_generation(last: u64) -> u64 {
    let now_us = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_micros() as u64);
    now_us.max(last.saturating_add(1))
}

impl Segment {
    /// Creates segment `name` of `size` bytes as its owner, in the runtime directory shared
    /// with `policy`'s group. One whose owner is alive is refused; what dead owners of this
    /// user left there is removed. Nothing is served until [`serve`](Self::serve).
    pub fn create(name: &str, size: usize, policy: &Policy) -> Result<Segment, ShmError> {
        let dir = rundir::ensure_owner_dir(name, policy.access_group())?;
        let socket = rundir::socket_path(&dir, name);
        let limit = crate::sys::unix::max_path();
        if socket.as_os_str().len() > limit {
            return Err(ShmError::Os {
                name: name.to_string(),
                what: format!("cannot make the socket {}", socket.display()),
                error: Cause::Reason(format!(
                    "a Unix socket's path has at most {limit} bytes: choose a shorter segment \
                     name, or a shorter directory ({})",
                    rundir::RUNTIME_DIR_ENV
                )),
            });
        }
        rundir::sweep(&dir, name);
        let Some(lock) = rundir::acquire_lock(&dir, name, Duration::from_millis(100))? else {
            // Asked as a tool would: the live owner's pid, to name it.
            let pid = Segment::open(name)
                .map(|s| s.base.load(super::layout::S_PID))
                .unwrap_or(0);
            return Err(ShmError::OwnerAlive {
                name: name.to_string(),
                pid,
            });
        };
        let made = rundir::remove_old_socket(&dir, name).and_then(|()| {
            Mapping::create(name, size).map_err(|e| ShmError::Os {
                name: name.to_string(),
                what: "cannot create the shared memory".into(),
                error: Cause::system(e),
            })
        });
        let mapping = match made {
            Ok(m) => m,
            Err(e) => {
                // Still holding the lock: nobody else uses the file.
                rundir::unlink(&rundir::lock_path(&dir, name));
                return Err(e);
            }
        };
        Ok(Segment {
            base: mapping.base(),
            mapping,
            name: name.to_string(),
            owned: Some(Owned {
                dir,
                lock,
                server: None,
            }),
            client: None,
        })
    }

    /// Starts serving the segment on its socket (mode 0600, or 0660 for the policy's group).
    pub fn serve(&mut self, setup: Setup) -> Result<(), ShmError> {
        let Some(owned) = self.owned.as_mut() else {
            return Err(ShmError::NotOwner(self.name.clone()));
        };
        let path = rundir::socket_path(&owned.dir, &self.name);
        let os = |what: &str, e: std::io::Error| ShmError::Os {
            name: self.name.clone(),
            what: format!("{what} {}", path.display()),
            error: Cause::system(e),
        };
        let listener =
            crate::sys::unix::listen(&path, 64).map_err(|e| os("cannot listen on", e))?;
        // The directory is ours and closed to others: nobody can have replaced the socket
        // between its creation and these calls.
        let group = setup.policy.access_group().map(|g| g.gid);
        let mode = if group.is_some() { 0o660 } else { 0o600 };
        std::fs::set_permissions(&path, std::fs::Permissions::from_mode(mode))
            .map_err(|e| os("cannot set the mode of", e))?;
        if let Some(gid) = group {
            std::os::unix::fs::lchown(&path, None, Some(gid))
                .map_err(|e| os("cannot give the group", e))?;
        }
        let memfd = self.mapping.fd().as_raw_fd();
        let server =
            Server::start(listener, setup, memfd, self.base).map_err(|e| os("cannot serve", e))?;
        owned.server = Some(server);
        Ok(())
    }

    /// Attaches to segment `name` as a tool: the first of the tool directories that has it.
    pub fn open(name: &str) -> Result<Segment, ShmError> {
        let mut first_error = None;
        for (dir, expected) in rundir::tool_dirs() {
            let path = rundir::socket_path(&dir, name);
            let attempt = rundir::check_tool_dir(name, &dir, expected).and_then(|owner| {
                rundir::check_socket(name, &path, owner)?;
                Client::connect(name, &path, owner)
            });
            match attempt {
                Ok((client, memfd)) => {
                    let mapping =
                        Mapping::receive(memfd, MAX_SEGMENT).map_err(|e| ShmError::Corrupt {
                            name: name.to_string(),
                            why: format!("the segment it sent cannot be used: {e}"),
                        })?;
                    return Ok(Segment {
                        base: mapping.base(),
                        mapping,
                        name: name.to_string(),
                        owned: None,
                        client: Some(client),
                    });
                }
                Err(ShmError::NotFound(_)) => {}
                Err(ShmError::Os { .. }) if !dir.exists() => {}
                Err(e) => {
                    first_error.get_or_insert(e);
                }
            }
        }
        Err(first_error.unwrap_or_else(|| ShmError::NotFound(name.to_string())))
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
        self.owned.is_some()
    }

    /// A tool's connection to the owner.
    pub(crate) fn client(&self) -> Option<&Client> {
        self.client.as_ref()
    }

    /// Whether the owner is alive: always for the owner; for a tool, while its connection
    /// stands.
    pub fn owner_alive(&self) -> bool {
        self.client.as_ref().is_none_or(|c| !c.hung_up())
    }

    /// The segment's descriptor.
    #[cfg(feature = "fault-injection")]
    pub fn fd(&self) -> std::os::fd::BorrowedFd<'_> {
        use std::os::fd::AsFd;
        self.mapping.fd().as_fd()
    }

    /// Whether the mapping was cut short under this process.
    pub fn damaged(&self) -> bool {
        self.mapping.damaged()
    }
}

impl Drop for Segment {
    fn drop(&mut self) {
        let Some(mut owned) = self.owned.take() else {
            return;
        };
        // Readers still mapping this segment must learn that nobody publishes into it or
        // applies writes any more, even once a new owner has created the name again.
        self.base.store(H_MAGIC, MAGIC_CLOSED);
        // Every server thread stops and every connection closes before the files go.
        drop(owned.server.take());
        // Still holding the lock: no new owner can have created either file meanwhile.
        rundir::unlink(&rundir::socket_path(&owned.dir, &self.name));
        rundir::unlink(&rundir::lock_path(&owned.dir, &self.name));
        drop(owned.lock);
    }
}

/// Names of the running programs, with the directory each is in.
pub fn names() -> Vec<(String, PathBuf)> {
    rundir::names()
}

/// Whether a live process owns segment `name` in `dir` (holds its lock).
pub fn owner_alive(dir: &std::path::Path, name: &str) -> bool {
    rundir::owner_alive(dir, name)
}
