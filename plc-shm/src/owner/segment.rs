//! A segment as its owner holds it: the memory, the lock held for its life, the socket and
//! the server behind it. Dropped, it marks the memory closed for the readers still mapping it
//! and removes its files.

use super::policy::Policy;
use super::server::{Server, Setup};
use crate::error::Cause;
use crate::error::ShmError;
use crate::format::layout::{H_MAGIC, MAGIC_CLOSED};
use crate::limits::LISTEN_BACKLOG;
use crate::sys::base::Base;
use crate::sys::memfd::Mapping;
use crate::sys::{rundir, unix};
use std::fs::File;
use std::os::fd::AsRawFd;
use std::os::unix::fs::PermissionsExt;
use std::path::PathBuf;
use std::time::Duration;

/// The owner's segment.
pub(crate) struct OwnedSegment {
    /// Unmapped after the server stopped (`drop` stops it first): its threads use it until
    /// then.
    mapping: Mapping,
    base: Base,
    name: String,
    dir: PathBuf,
    /// Held for the segment's life.
    lock: Option<File>,
    server: Option<Server>,
}

/// A generation for a new segment: the creation time in microseconds, so that two runs of one
/// name differ and a later one is greater.
pub fn next_generation(last: u64) -> u64 {
    let now_us = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_micros() as u64);
    now_us.max(last.saturating_add(1))
}

impl OwnedSegment {
    /// Creates segment `name` of `size` bytes as its owner, in the runtime directory shared
    /// with `policy`'s group. One whose owner is alive is refused; what dead owners of this
    /// user left there is removed. Nothing is served until [`serve`](Self::serve).
    pub fn create(name: &str, size: usize, policy: &Policy) -> Result<OwnedSegment, ShmError> {
        let dir = rundir::ensure_owner_dir(name, policy.access_group())?;
        let socket = rundir::socket_path(&dir, name);
        let most = unix::max_path();
        if socket.as_os_str().len() > most {
            return Err(ShmError::SocketPathTooLong {
                name: name.to_string(),
                path: socket,
                most,
            });
        }
        rundir::sweep(&dir, name);
        let Some(lock) = rundir::acquire_lock(&dir, name, Duration::from_millis(100))? else {
            return Err(ShmError::OwnerAlive {
                name: name.to_string(),
                pid: live_owner_pid(&socket),
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
        Ok(OwnedSegment {
            base: mapping.base(),
            mapping,
            name: name.to_string(),
            dir,
            lock: Some(lock),
            server: None,
        })
    }

    /// Starts serving the segment on its socket (mode 0600, or 0660 for the policy's group).
    pub fn serve(&mut self, setup: Setup) -> Result<(), ShmError> {
        let path = rundir::socket_path(&self.dir, &self.name);
        let os = |what: &str, e: std::io::Error| ShmError::Os {
            name: self.name.clone(),
            what: format!("{what} {}", path.display()),
            error: Cause::system(e),
        };
        let listener =
            unix::listen(&path, LISTEN_BACKLOG).map_err(|e| os("cannot listen on", e))?;
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
        self.server = Some(server);
        Ok(())
    }

    /// The mapping.
    pub fn base(&self) -> Base {
        self.base
    }

    /// The segment's name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Whether the mapping was cut short under this process.
    pub fn damaged(&self) -> bool {
        self.mapping.damaged()
    }
}

/// The pid of the live owner serving `socket`, as the kernel gives it for the socket's peer
/// (0 if it cannot be asked): to name the process a second owner is refused for.
fn live_owner_pid(socket: &std::path::Path) -> u64 {
    unix::connect(socket)
        .and_then(|fd| unix::peer(&fd))
        .map_or(0, |peer| u64::try_from(peer.pid).unwrap_or(0))
}

impl Drop for OwnedSegment {
    fn drop(&mut self) {
        let Some(lock) = self.lock.take() else {
            return;
        };
        // Readers still mapping this segment must learn that nobody publishes into it or
        // applies writes any more, even once a new owner has created the name again.
        self.base.store(H_MAGIC, MAGIC_CLOSED);
        // Every server thread stops and every connection closes before the files go.
        drop(self.server.take());
        // Still holding the lock: no new owner can have created either file meanwhile.
        rundir::unlink(&rundir::socket_path(&self.dir, &self.name));
        rundir::unlink(&rundir::lock_path(&self.dir, &self.name));
        drop(lock);
    }
}
