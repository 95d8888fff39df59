//! A segment as a tool holds it: the memory the owner sent, mapped read-only, and the
//! connection it came through.

use super::client::Client;
use crate::error::ShmError;
use crate::limits::{MAX_DESCRIPTOR, MAX_IMAGE};
use crate::sys::base::Base;
use crate::sys::memfd::Mapping;
use crate::sys::rundir;

/// The largest segment a tool maps: a header, the largest image and the largest descriptor a
/// tool reads, and the words between.
const MAX_SEGMENT: usize = MAX_IMAGE + MAX_DESCRIPTOR + (1 << 20);

/// A tool's segment.
pub(crate) struct AttachedSegment {
    /// Kept mapped while attached.
    _mapping: Mapping,
    base: Base,
    name: String,
    client: Client,
}

impl AttachedSegment {
    /// Attaches to segment `name` as a tool: the first of the tool directories that has it.
    pub fn open(name: &str) -> Result<AttachedSegment, ShmError> {
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
                    return Ok(AttachedSegment {
                        base: mapping.base(),
                        _mapping: mapping,
                        name: name.to_string(),
                        client,
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

    /// The connection to the owner.
    pub fn client(&self) -> &Client {
        &self.client
    }

    /// Whether the owner is alive: while the connection stands.
    pub fn owner_alive(&self) -> bool {
        !self.client.hung_up()
    }

    /// The segment's descriptor.
    #[cfg(feature = "fault-injection")]
    pub fn fd(&self) -> std::os::fd::BorrowedFd<'_> {
        use std::os::fd::AsFd;
        self._mapping.fd().as_fd()
    }
}
