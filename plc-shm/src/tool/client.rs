//! A tool's connection to a program: the greeting that brings the segment's descriptor,
//! requests sent and their answers collected, and the owner's liveness (the connection hangs
//! up when the owner's process ends, however it ends).

use crate::error::Cause;
use crate::error::ShmError;
use crate::limits::MAX_MESSAGE;
use crate::protocol::{self, Code, Reply, Ticket, WriteOutcome, WriteRequest};
use crate::sys::{rundir, unix};
use plc_core::write::Checked;
use std::cell::{Cell, RefCell};
use std::collections::HashMap;
use std::os::fd::{AsRawFd, OwnedFd};
use std::path::Path;
use std::time::{Duration, Instant};

/// How long a tool waits for the greeting.
const GREETING_PATIENCE: Duration = Duration::from_secs(2);

/// A connection to a segment's owner.
pub(crate) struct Client {
    fd: OwnedFd,
    name: String,
    may_write: bool,
    next_id: Cell<u64>,
    /// Requests sent, and their answers once received.
    sent: RefCell<HashMap<u64, Option<Reply>>>,
    /// Memory files that came with answers (a trace's ring), by request.
    files: RefCell<HashMap<u64, OwnedFd>>,
}

impl Client {
    /// Connects to the socket at `path`, checks that the process serving it is of uid `owner`
    /// (the directory's owner), and returns the connection and the segment's descriptor.
    pub fn connect(name: &str, path: &Path, owner: u32) -> Result<(Client, OwnedFd), ShmError> {
        let fd = unix::connect(path).map_err(|e| match e.raw_os_error() {
            Some(libc::ENOENT) => ShmError::NotFound(name.to_string()),
            // A socket nobody listens on: its owner was killed and nobody removed it yet.
            Some(libc::ECONNREFUSED) => ShmError::OwnerGone(name.to_string()),
            _ => rundir::open_error(name, path, "cannot connect to", e),
        })?;
        let os = |what: &str, e: std::io::Error| ShmError::Os {
            name: name.to_string(),
            what: format!("{what} {}", path.display()),
            error: Cause::system(e),
        };
        let peer = unix::peer(&fd).map_err(|e| os("cannot identify the owner at", e))?;
        if peer.uid != owner {
            return Err(rundir::refuse(
                name,
                path,
                format!(
                    "is served by uid {}, not by its directory's owner uid {owner}",
                    peer.uid
                ),
                format!("remove it (`rm {}`)", path.display()),
            ));
        }
        if !unix::readable(fd.as_raw_fd(), GREETING_PATIENCE).unwrap_or(false) {
            return Err(ShmError::NoGreeting {
                name: name.to_string(),
                path: path.to_path_buf(),
                waited: GREETING_PATIENCE,
            });
        }
        let mut buf = vec![0u8; MAX_MESSAGE];
        let got = unix::receive(fd.as_raw_fd(), &mut buf, false)
            .map_err(|e| os("cannot receive the greeting from", e))?;
        let message = &buf[..got.len];
        let greeting = match protocol::decode_greeting(message) {
            Ok(g) => g,
            Err(e) => {
                // A connection turned away says why in a reply.
                if let Ok(reply) = protocol::decode_reply(message) {
                    return Err(ShmError::TurnedAway {
                        name: name.to_string(),
                        reason: reply.reason,
                    });
                }
                if got.len == 0 {
                    return Err(ShmError::NotFound(name.to_string()));
                }
                return Err(ShmError::Protocol {
                    name: name.to_string(),
                    why: format!("its greeting: {e}"),
                });
            }
        };
        if greeting.version != protocol::VERSION {
            return Err(ShmError::Format {
                name: name.to_string(),
                found: format!("write protocol version {}", greeting.version),
            });
        }
        let Some(memfd) = got.fd else {
            return Err(ShmError::Protocol {
                name: name.to_string(),
                why: "its greeting came without the segment".into(),
            });
        };
        Ok((
            Client {
                fd,
                name: name.to_string(),
                may_write: greeting.may_write,
                next_id: Cell::new(1),
                sent: RefCell::new(HashMap::new()),
                files: RefCell::new(HashMap::new()),
            },
            memfd,
        ))
    }

    /// Whether the owner's policy lets this process write (the owner checks again).
    pub fn may_write(&self) -> bool {
        self.may_write
    }

    /// Whether the owner closed the connection (its process ended or it stopped).
    pub fn hung_up(&self) -> bool {
        unix::hung_up(self.fd.as_raw_fd())
    }

    /// Sends checked writes as one request.
    pub fn post(&self, writes: &[Checked]) -> Result<Ticket, ShmError> {
        self.post_with(|id| {
            protocol::encode_request(&WriteRequest {
                id,
                writes: writes.iter().map(|w| *w.write()).collect(),
            })
        })
    }

    /// Sends the message `encode` makes for the next request id.
    pub fn post_with(&self, encode: impl FnOnce(u64) -> Vec<u8>) -> Result<Ticket, ShmError> {
        let id = self.next_id.get();
        self.next_id.set(id.wrapping_add(1));
        self.send_raw(&encode(id))?;
        self.sent.borrow_mut().insert(id, None);
        Ok(Ticket(id))
    }

    /// The memory file that came with the answer to `ticket`, if one did.
    pub fn take_file(&self, ticket: Ticket) -> Option<OwnedFd> {
        self.files.borrow_mut().remove(&ticket.0)
    }

    /// Sends `bytes` as one message, whatever they are.
    pub fn send_raw(&self, bytes: &[u8]) -> Result<(), ShmError> {
        unix::send(self.fd.as_raw_fd(), bytes, None, true).map_err(|e| match e.raw_os_error() {
            Some(libc::EPIPE | libc::ECONNRESET | libc::ENOTCONN) => {
                ShmError::OwnerGone(self.name.clone())
            }
            _ => ShmError::Os {
                name: self.name.clone(),
                what: "cannot send a write".into(),
                error: Cause::system(e),
            },
        })
    }

    /// Takes every answer that has arrived, without waiting.
    fn collect(&self) {
        let mut buf = vec![0u8; MAX_MESSAGE];
        // Bounded: at most one answer per request sent, and a few unasked ones.
        let bound = self.sent.borrow().len() + 16;
        for _ in 0..bound {
            let Ok(got) = unix::receive(self.fd.as_raw_fd(), &mut buf, false) else {
                return;
            };
            if got.len == 0 && self.hung_up() {
                return;
            }
            if let Ok(reply) = protocol::decode_reply(&buf[..got.len])
                && let Some(slot) = self.sent.borrow_mut().get_mut(&reply.id)
            {
                // Kept only for a request still waiting: at most one per request sent.
                if let Some(fd) = got.fd {
                    self.files.borrow_mut().insert(reply.id, fd);
                }
                *slot = Some(reply);
            }
        }
    }

    /// What became of request `ticket`; a final answer is forgotten once asked for.
    pub fn outcome(&self, ticket: Ticket) -> WriteOutcome {
        self.collect();
        let mut sent = self.sent.borrow_mut();
        match sent.get(&ticket.0) {
            None => WriteOutcome::Unknown,
            Some(None) if self.hung_up() => {
                sent.remove(&ticket.0);
                WriteOutcome::Unknown
            }
            Some(None) => WriteOutcome::Pending,
            Some(Some(reply)) => {
                let o = WriteOutcome::of(reply.code);
                sent.remove(&ticket.0);
                o
            }
        }
    }

    /// Waits up to `patience` for the answer to `ticket`.
    pub fn wait(&self, ticket: Ticket, patience: Duration) -> Result<Reply, ShmError> {
        let deadline = Instant::now() + patience;
        loop {
            self.collect();
            let answered = matches!(self.sent.borrow().get(&ticket.0), Some(Some(_)));
            if answered && let Some(Some(reply)) = self.sent.borrow_mut().remove(&ticket.0) {
                return Ok(reply);
            }
            if self.hung_up() {
                self.sent.borrow_mut().remove(&ticket.0);
                return Err(ShmError::OwnerGone(self.name.clone()));
            }
            let now = Instant::now();
            if now >= deadline {
                self.sent.borrow_mut().remove(&ticket.0);
                return Err(ShmError::NoAnswer {
                    name: self.name.clone(),
                    waited: patience,
                });
            }
            let _ = unix::readable(
                self.fd.as_raw_fd(),
                (deadline - now).min(Duration::from_millis(100)),
            );
        }
    }
}

/// What a tool's write call returns for an answer: `Ok` once applied, else the owner's
/// reason; `variables` are the request's variable names, in order.
pub(crate) fn answer_result(
    name: &str,
    variables: &[String],
    reply: Reply,
) -> Result<(), ShmError> {
    let variable = || {
        variables
            .get(usize::from(reply.which))
            .cloned()
            .unwrap_or_default()
    };
    Err(match reply.code {
        Code::Applied => return Ok(()),
        Code::Rejected => ShmError::WriteRejected {
            name: name.to_string(),
            variable: variable(),
            reason: reply.reason,
        },
        Code::Forced => ShmError::Forced {
            name: name.to_string(),
            variable: variable(),
            reason: reply.reason,
        },
        Code::Refused => ShmError::WriteRefused {
            name: name.to_string(),
            rule: reply.reason,
        },
        Code::Busy => ShmError::QueueFull(name.to_string()),
        Code::Stopped => ShmError::Closed {
            name: name.to_string(),
            faulted: false,
        },
        Code::Malformed => ShmError::Protocol {
            name: name.to_string(),
            why: reply.reason,
        },
    })
}
