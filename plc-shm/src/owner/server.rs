//! The owner's socket server: threads of their own, never the cycle thread's time.
//!
//! One thread accepts connections (at most [`MAX_CONNECTIONS`], [`MAX_PER_UID`] of one user, the
//! last [`RESERVED_FOR_WRITERS`] only for tools that may write), learns each peer's
//! credentials, and sends it the greeting with the segment's descriptor; a tool that has not
//! taken it within [`GREETING_GRACE`] is disconnected. Refusals are logged at a bounded rate.
//! Each connection then has a thread that receives its requests (one message each, at most
//! [`protocol::MAX_MESSAGE`] bytes), refuses a writer the policy does not let write, decodes
//! and checks each request against the program's declaration and queues it (bounded, and at
//! most [`MAX_OUTSTANDING`] per connection) for the cycle thread, which answers it once
//! applied. Forces and releases travel the same way, checked as forces; a trace is set up here
//! (its ring made and passed to the tool) and handed to the cycle. Every send to a tool has a
//! timeout or does not wait, so a tool that stops reading blocks nothing but its own
//! connection. The accepting thread also formats and logs the force and release events the
//! cycle leaves (at a bounded rate, saying what it did not show or could not log).

use super::alarm_commands::{self, AlarmCommand};
use super::force_log::{ForceLogReader, Level};
use super::policy::Policy;
use super::recording::Recording;
use super::requests::{self, Batch, Conn, Count, Counters, Kind};
use super::spent::Spent;
use crate::format::layout::{Offsets, S_PERIOD_NS};
use crate::limits::{
    GREETING_GRACE, MAX_CONNECTIONS, MAX_OUTSTANDING, MAX_PER_UID, MAX_QUEUED, MAX_TRACES,
    MAX_WAITING_WRITES, RESERVED_FOR_WRITERS,
};
use crate::log_limit::LogLimit;
use crate::protocol::{self, Code};
use crate::sys::base::Base;
use crate::sys::priority::normal_priority;
use crate::sys::unix::{self, Peer};
use plc_core::VarInfo;
use plc_core::write::Checked;
use std::collections::HashMap;
use std::os::fd::{AsRawFd, OwnedFd, RawFd};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering::Relaxed};
use std::sync::mpsc::{Receiver, SyncSender, TrySendError};
use std::sync::{Arc, Mutex};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

/// How long a send to a tool (the greeting, a refusal) may wait for room.
const SEND_TIMEOUT: Duration = Duration::from_secs(1);
/// Force and release events the accepting thread takes per look at the channel (which is
/// bounded too).
const LOG_LINES_PER_CALL: usize = 4096;
/// How often the accepting thread looks whether it should stop.
const STOP_POLL: Duration = Duration::from_millis(50);

/// What every server thread shares.
struct Shared {
    name: String,
    policy: Policy,
    vars: &'static [VarInfo],
    /// Alarms the program declares.
    alarms: usize,
    memfd: RawFd,
    base: Base,
    off: Offsets,
    counters: Arc<Counters>,
    queue: SyncSender<Batch>,
    stop: AtomicBool,
    conns: Mutex<Registry>,
    /// Traces running.
    traces: AtomicUsize,
    /// Forces and releases the cycle thread logs, formatted and written here.
    log: Mutex<ForceLogReader>,
    /// Traces whose tools left, freed here: unmapping a ring costs milliseconds the cycle
    /// thread must not spend.
    spent: Mutex<Receiver<Spent>>,
    /// Refusals and closed connections, logged at a bounded rate.
    refusals: LogLimit,
}

#[derive(Default)]
struct Registry {
    open: Vec<(Arc<Conn>, JoinHandle<()>)>,
    per_uid: HashMap<u32, usize>,
}

/// A running server; stopped (every thread joined) on drop.
pub(crate) struct Server {
    shared: Arc<Shared>,
    listener: Arc<OwnedFd>,
    accept: Option<JoinHandle<()>>,
}

/// What the server needs to start.
pub(crate) struct Setup {
    pub name: String,
    pub policy: Policy,
    pub vars: &'static [VarInfo],
    pub alarms: usize,
    pub off: Offsets,
    pub counters: Arc<Counters>,
    pub queue: SyncSender<Batch>,
    pub log: ForceLogReader,
    pub spent: Receiver<Spent>,
}

impl Server {
    /// Serves `listener` until dropped, passing `memfd` (which outlives the server: the
    /// segment drops the server first) to each tool; `base` is its mapping.
    pub fn start(
        listener: OwnedFd,
        setup: Setup,
        memfd: RawFd,
        base: Base,
    ) -> std::io::Result<Server> {
        let shared = Arc::new(Shared {
            name: setup.name,
            policy: setup.policy,
            vars: setup.vars,
            alarms: setup.alarms,
            memfd,
            base,
            off: setup.off,
            counters: setup.counters,
            queue: setup.queue,
            stop: AtomicBool::new(false),
            conns: Mutex::new(Registry::default()),
            traces: AtomicUsize::new(0),
            log: Mutex::new(setup.log),
            spent: Mutex::new(setup.spent),
            refusals: LogLimit::default(),
        });
        let listener = Arc::new(listener);
        let (s, l) = (shared.clone(), listener.clone());
        let accept = std::thread::Builder::new()
            .name(format!("plc-shm-{}", shared.name))
            .spawn(move || accept_loop(&s, &l))?;
        Ok(Server {
            shared,
            listener,
            accept: Some(accept),
        })
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        write_log(&self.shared, true);
        self.shared.stop.store(true, Relaxed);
        unix::shutdown(self.listener.as_raw_fd());
        if let Some(a) = self.accept.take() {
            let _ = a.join();
        }
        let open = std::mem::take(&mut lock(&self.shared.conns).open);
        for (conn, _) in &open {
            unix::shutdown(conn.fd.as_raw_fd());
        }
        for (_, thread) in open {
            let _ = thread.join();
        }
    }
}

fn lock(m: &Mutex<Registry>) -> std::sync::MutexGuard<'_, Registry> {
    // A panic in a server thread leaves the registry as it was: go on with it.
    m.lock().unwrap_or_else(|p| p.into_inner())
}

/// Does what the cycle thread left to the server's threads (the accepting one, and each
/// connection's after a request): writes the lines of its forces and releases
/// (at a bounded rate; with `closing`, every count still held back too) and frees the traces
/// whose tools left.
fn write_log(shared: &Shared, closing: bool) {
    if let Ok(spent) = shared.spent.try_lock() {
        // Bounded: the channel is.
        for freed in spent.try_iter() {
            freed.free();
        }
    }
    let Ok(mut log) = shared.log.try_lock() else {
        return;
    };
    let now = (!closing).then(Instant::now);
    // Bounded per call; the channel is bounded too.
    log.drain(shared.vars, now, LOG_LINES_PER_CALL, &mut |level, line| {
        let name = &shared.name;
        match level {
            Level::Info => log::info!(target: "plc_io::shm", "segment `{name}`: {line}"),
            Level::Warn => log::warn!(target: "plc_io::shm", "segment `{name}`: {line}"),
        }
    });
}

fn accept_loop(shared: &Arc<Shared>, listener: &OwnedFd) {
    normal_priority();
    while !shared.stop.load(Relaxed) {
        write_log(shared, false);
        match unix::readable(listener.as_raw_fd(), STOP_POLL) {
            Ok(true) => {}
            Ok(false) => continue,
            Err(e) => {
                log::error!(target: "plc_io::shm", "segment `{}`: the socket failed: {e}", shared.name);
                return;
            }
        }
        let Ok(Some(fd)) = unix::accept(listener) else {
            continue;
        };
        if shared.stop.load(Relaxed) {
            return;
        }
        admit(shared, fd);
    }
}

/// Takes a new connection in, or turns it away with the reason.
fn admit(shared: &Arc<Shared>, fd: OwnedFd) {
    let _ = unix::set_timeouts(&fd, SEND_TIMEOUT, Duration::ZERO);
    let Ok(peer) = unix::peer(&fd) else {
        return;
    };
    let mut reg = lock(&shared.conns);
    // Connections whose threads ended leave first.
    let (done, open): (Vec<_>, Vec<_>) = std::mem::take(&mut reg.open)
        .into_iter()
        .partition(|(_, t)| t.is_finished());
    reg.open = open;
    for (_, t) in done {
        let _ = t.join();
    }
    let mine = reg.per_uid.get(&peer.uid).copied().unwrap_or(0);
    let writer = shared.policy.may_write(&peer);
    let full = if reg.open.len() >= MAX_CONNECTIONS {
        Some(format!("it has {MAX_CONNECTIONS} connections already"))
    } else if !writer && reg.open.len() >= MAX_CONNECTIONS - RESERVED_FOR_WRITERS {
        Some(format!(
            "it has {} connections, and keeps the last {RESERVED_FOR_WRITERS} places for \
             tools that may write",
            reg.open.len()
        ))
    } else if mine >= MAX_PER_UID {
        Some(format!(
            "uid {} has {MAX_PER_UID} connections already",
            peer.uid
        ))
    } else {
        None
    };
    let conn = Arc::new(Conn {
        fd,
        outstanding: Default::default(),
    });
    if let Some(why) = full {
        shared.refusals.warn(|| {
            format!(
                "segment `{}`: turned away a connection of uid {} (pid {}): {why}",
                shared.name, peer.uid, peer.pid
            )
        });
        conn.answer(
            0,
            Code::Busy,
            0,
            format!("the program turned the connection away: {why}"),
        );
        return;
    }
    let greeting = protocol::encode_greeting(shared.policy.may_write(&peer));
    if unix::send(conn.fd.as_raw_fd(), &greeting, Some(shared.memfd), true).is_err() {
        return;
    }
    *reg.per_uid.entry(peer.uid).or_default() += 1;
    let (s, c, uid) = (shared.clone(), conn.clone(), peer.uid);
    let spawned = std::thread::Builder::new()
        .name(format!("plc-shm-conn-{}", peer.pid))
        .spawn(move || {
            normal_priority();
            serve(&s, &c, &peer);
            // However it ended, the tool sees the connection closed, never a silent one.
            unix::shutdown(c.fd.as_raw_fd());
            let mut reg = lock(&s.conns);
            if let Some(n) = reg.per_uid.get_mut(&peer.uid) {
                *n = n.saturating_sub(1);
            }
        });
    if let Ok(thread) = spawned {
        reg.open.push((conn, thread));
    } else if let Some(n) = reg.per_uid.get_mut(&uid) {
        *n = n.saturating_sub(1);
    }
}

/// Waits until the tool has taken its greeting (and the segment), at most [`GREETING_GRACE`];
/// whether it did.
fn greeting_taken(shared: &Shared, conn: &Conn, peer: &Peer) -> bool {
    let fd = conn.fd.as_raw_fd();
    let start = std::time::Instant::now();
    loop {
        match unix::unread(fd) {
            Ok(0) => return true,
            Ok(_) => {}
            // Unknown: do not close what may be a working tool.
            Err(_) => return true,
        }
        if shared.stop.load(Relaxed) || unix::hung_up(fd) {
            return false;
        }
        if start.elapsed() >= GREETING_GRACE {
            shared.refusals.warn(|| {
                format!(
                    "segment `{}`: closed a connection of uid {} (pid {}) that did not take the \
                     segment within {GREETING_GRACE:?}",
                    shared.name, peer.uid, peer.pid
                )
            });
            return false;
        }
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// Receives one connection's requests until it closes or the server stops.
fn serve(shared: &Shared, conn: &Arc<Conn>, peer: &Peer) {
    if !greeting_taken(shared, conn, peer) {
        return;
    }
    let mut session = Session {
        shared,
        conn,
        peer,
        may_write: shared.policy.may_write(peer),
        trace: None,
    };
    // One byte more than a message may have: a longer one arrives truncated and is refused.
    let mut buf = vec![0u8; protocol::MAX_MESSAGE + 1];
    loop {
        let got = match unix::receive(conn.fd.as_raw_fd(), &mut buf, true) {
            Ok(r) => r,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(_) => break,
        };
        // A descriptor a tool attached is closed here (`got.fd` drops): nothing of it is used.
        // An empty message reads as zero bytes too: only a hang-up ends the connection.
        if got.len == 0 && !got.truncated && unix::hung_up(conn.fd.as_raw_fd()) {
            break; // closed, or shut down by `Server::drop`
        }
        if shared.stop.load(Relaxed) {
            break;
        }
        let message = &buf[..got.len.min(buf.len())];
        let request = if got.truncated || got.len > protocol::MAX_MESSAGE {
            Err(protocol::DecodeError::TooLong { len: None })
        } else {
            protocol::decode(message)
        };
        match request {
            Ok(r) => session.handle(r),
            Err(e) => {
                shared
                    .counters
                    .add(Count::Malformed, 1, &shared.base, &shared.off);
                conn.answer(0, Code::Malformed, 0, format!("not a request: {e}"));
            }
        }
        // The log as fast as requests come (a flood of forces would fill it between two
        // polls of the accepting thread, and what does not fit is only counted): one lock
        // tried and a look at an empty channel when there is nothing to write.
        write_log(shared, false);
    }
    // The trace of a tool that left ends with it.
    if let Some(left) = session.trace.take() {
        left.store(true, Relaxed);
        shared.traces.fetch_sub(1, Relaxed);
    }
}

/// One connection's state on its thread.
struct Session<'a> {
    shared: &'a Shared,
    conn: &'a Arc<Conn>,
    peer: &'a Peer,
    may_write: bool,
    /// Its trace's flag, set when the connection ends.
    trace: Option<Arc<AtomicBool>>,
}

impl Session<'_> {
    fn handle(&mut self, request: protocol::Request) {
        let id = request.id();
        let kind = match request {
            protocol::Request::Trace(trace) => return self.trace(trace),
            _ if !self.may_write => return self.refuse(id),
            protocol::Request::Write(w) => self.validated(&w, false).map(Kind::Write),
            protocol::Request::Force(w) => self.validated(&w, true).map(Kind::Force),
            protocol::Request::Release(r) => Some(Kind::Release(r)),
            protocol::Request::Alarm(a) => self.alarm_command(a),
        };
        if let Some(kind) = kind {
            self.queue(id, kind);
        }
    }

    /// A writer the policy does not let write: refused, whatever it asks.
    fn refuse(&self, id: u64) {
        let shared = self.shared;
        shared
            .counters
            .add(Count::Refused, 1, &shared.base, &shared.off);
        let text = shared.policy.refusal(self.peer, &shared.name);
        shared
            .refusals
            .warn(|| format!("segment `{}`: {text}", shared.name));
        self.conn.answer(id, Code::Refused, 0, text);
    }

    /// The writes (or forces) of `request`, checked against the program's declaration; a
    /// refusal is answered here.
    fn validated(&self, request: &protocol::WriteRequest, force: bool) -> Option<Vec<Checked>> {
        let shared = self.shared;
        match requests::validate(shared.vars, request, force) {
            Ok(w) => Some(w),
            Err(refused) => {
                let n = request.writes.len() as u64;
                shared
                    .counters
                    .add(Count::Rejected, n, &shared.base, &shared.off);
                self.conn.refuse(request.id, refused);
                None
            }
        }
    }

    /// The command of an action on alarms whose numbers the program declares; a refusal is
    /// answered here.
    fn alarm_command(&self, request: protocol::AlarmRequest) -> Option<Kind> {
        let shared = self.shared;
        match alarm_commands::check_numbers(&request, shared.alarms) {
            Ok(()) => Some(Kind::Alarm(Box::new(AlarmCommand::new(
                request,
                self.peer.uid,
            )))),
            Err((which, why)) => {
                shared
                    .counters
                    .add(Count::Rejected, 1, &shared.base, &shared.off);
                self.conn.answer(request.id, Code::Rejected, which, why);
                None
            }
        }
    }

    /// Starts a trace: any tool that may connect may trace (it reads what it could read
    /// anyway), one per connection, [`MAX_TRACES`] at once, of which tools that may not write
    /// take half at most. The ring goes to the tool with the answer; the cycle records from
    /// the next cycle on.
    fn trace(&mut self, trace: protocol::TraceRequest) {
        let shared = self.shared;
        let busy = |why: String| self.conn.answer(trace.id, Code::Busy, 0, why);
        if self.trace.is_some() {
            return busy("this connection traces already: one trace per connection".into());
        }
        // Readers take at most half of the places: tools that may not write cannot keep an
        // engineer who may from tracing.
        let limit = if self.may_write {
            MAX_TRACES
        } else {
            MAX_TRACES / 2
        };
        if shared.traces.fetch_add(1, Relaxed) >= limit {
            shared.traces.fetch_sub(1, Relaxed);
            return busy(format!(
                "{limit} traces run already (of {MAX_TRACES}, half of them kept for tools that \
                 may write): end one first"
            ));
        }
        let period_ns = shared.base.load(S_PERIOD_NS);
        let made = Recording::create(
            &shared.name,
            shared.vars,
            &trace.values,
            trace.every,
            period_ns,
        );
        let (recording, fd) = match made {
            Ok(r) => r,
            Err(refused) => {
                shared.traces.fetch_sub(1, Relaxed);
                return self.conn.refuse(trace.id, refused);
            }
        };
        let left = recording.left.clone();
        if self.queue(trace.id, Kind::Record(Box::new(recording))) {
            self.trace = Some(left);
            self.conn.answer_with(trace.id, Code::Applied, &fd);
        } else {
            shared.traces.fetch_sub(1, Relaxed);
        }
    }

    /// Queues a request for the cycle thread (bounded); answers `Busy` if it cannot wait.
    fn queue(&self, id: u64, kind: Kind) -> bool {
        let (shared, conn) = (self.shared, self.conn);
        let (base, off) = (&shared.base, &shared.off);
        if conn.outstanding.load(Relaxed) >= MAX_OUTSTANDING {
            shared.counters.add(Count::Busy, 1, base, off);
            conn.answer(
                id,
                Code::Busy,
                0,
                format!("{MAX_OUTSTANDING} requests of this connection wait already"),
            );
            return false;
        }
        let writes = kind.count();
        let waiting = &shared.counters.waiting_writes;
        if waiting.fetch_add(writes, Relaxed) + writes > MAX_WAITING_WRITES {
            waiting.fetch_sub(writes, Relaxed);
            shared.counters.add(Count::Busy, 1, base, off);
            conn.answer(
                id,
                Code::Busy,
                0,
                format!("{MAX_WAITING_WRITES} writes wait for the program already"),
            );
            return false;
        }
        conn.outstanding.fetch_add(1, Relaxed);
        shared.counters.queued(1, base, off);
        let batch = Batch {
            id,
            kind,
            conn: conn.clone(),
            uid: self.peer.uid,
        };
        match shared.queue.try_send(batch) {
            Ok(()) => true,
            Err(TrySendError::Full(b) | TrySendError::Disconnected(b)) => {
                waiting.fetch_sub(writes, Relaxed);
                conn.outstanding.fetch_sub(1, Relaxed);
                shared.counters.queued(-1, base, off);
                shared.counters.add(Count::Busy, 1, base, off);
                conn.answer(
                    b.id,
                    Code::Busy,
                    0,
                    format!("{MAX_QUEUED} requests wait for the program already"),
                );
                false
            }
        }
    }
}
