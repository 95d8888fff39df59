//! The writer thread: takes transitions from a bounded queue (the [`Handoff`], looked at
//! every [`POLL`]), appends them to the file in batches, syncs at most once per interval (and
//! at stop), compacts when the file is full; flushes and the stop come on a channel of their
//! own. The cycle's side ([`JournalSender`]) never waits: when the queue is full a transition
//! is counted, and the next batch records the count ([`Entry::Summarised`]).

use super::file::JournalFile;
use super::frame::{Item, encode};
use super::handoff::Handoff;
use super::message::Msg;
use super::record::{Entry, MAX_PATH, Operator, Record, bounded};
use super::{JournalError, JournalOptions};
use plc_core::alarm::AlarmEvent;
use std::sync::Arc;
use std::sync::atomic::{AtomicI64, AtomicU64, Ordering::Relaxed};
use std::sync::mpsc::{Receiver, RecvTimeoutError};
use std::time::{Duration, Instant};

/// How often the writer takes what the cycle queued: each transition is on disk well within
/// a second, and an idle writer wakes 20 times a second for a look at an empty vector.
pub(super) const POLL: Duration = Duration::from_millis(50);

/// What was not recorded one by one, counted by whoever found the queue full.
pub(super) struct Counters {
    transitions: AtomicU64,
    actions: AtomicU64,
    /// The latest time among them, UTC nanoseconds: the summary's time.
    last_ns: AtomicI64,
    /// Summarised since the start, for the status.
    total: AtomicU64,
}

impl Counters {
    pub(super) fn new() -> Counters {
        Counters {
            transitions: AtomicU64::new(0),
            actions: AtomicU64::new(0),
            last_ns: AtomicI64::new(i64::MIN),
            total: AtomicU64::new(0),
        }
    }

    fn count(&self, action: bool, time_ns: i64) {
        let n = if action {
            &self.actions
        } else {
            &self.transitions
        };
        n.fetch_add(1, Relaxed);
        self.total.fetch_add(1, Relaxed);
        self.last_ns.fetch_max(time_ns, Relaxed);
    }

    pub(super) fn total(&self) -> u64 {
        self.total.load(Relaxed)
    }
}

/// The cycle's end of the journal: hands transitions to the writer thread, never blocking.
/// Cheap to clone; each carries the path table its alarm numbers refer to (after an online
/// change, take a new one with the new table: transitions already queued keep the old).
///
/// ```
/// use plc_core::alarm::{AlarmEvent, EventKind, Level};
/// use plc_runtime::alarm_journal::AlarmJournal;
/// let dir = std::env::temp_dir().join(format!("journal-sender-doc-{}", std::process::id()));
/// let journal = AlarmJournal::open(dir.join("press.alarms"), 100)?;
/// let sender = journal.sender(vec!["door".to_string()]);
/// let raised = AlarmEvent { alarm: 0, time_ns: 1, kind: EventKind::Raised { level: Level::Active } };
/// sender.record(&raised, 1.0);
/// journal.finish()?;
/// # std::fs::remove_dir_all(&dir).unwrap();
/// # Ok::<(), plc_runtime::alarm_journal::JournalError>(())
/// ```
#[derive(Clone)]
pub struct JournalSender {
    pub(super) queue: Arc<Handoff>,
    pub(super) paths: Arc<[String]>,
    pub(super) counters: Arc<Counters>,
}

impl JournalSender {
    /// Queues a transition of the evaluator, `value` the alarm's value in that cycle (NaN for
    /// none). Never blocks, allocates nothing: if the queue is full it is counted instead.
    pub fn record(&self, event: &AlarmEvent, value: f64) {
        let msg = Msg::Event {
            paths: self.paths.clone(),
            event: *event,
            value,
        };
        if self.queue.offer(msg).is_err() {
            self.counters.count(false, event.time_ns);
        }
    }

    /// Queues an operator's action (acknowledge, reset, shelve, unshelve) with who did it.
    /// Never blocks: if the queue is full it is counted instead.
    pub fn record_action(&self, event: &AlarmEvent, by: Operator) {
        let msg = Msg::Action {
            paths: self.paths.clone(),
            event: *event,
            by: Box::new(by),
        };
        if self.queue.offer(msg).is_err() {
            self.counters.count(true, event.time_ns);
        }
    }

    /// Transitions and actions not recorded one by one since the start (only counted, in
    /// summary records).
    pub fn summarised(&self) -> u64 {
        self.counters.total()
    }
}

/// Records encoded, not yet appended, and whether the file needs a sync.
struct Out {
    buf: Vec<u8>,
    /// Records in `buf`.
    count: usize,
    /// Appended, not yet synced.
    dirty: bool,
    last_sync: Instant,
    failed_compaction: Option<Instant>,
}

/// The writer thread's state.
pub(super) struct Writer {
    pub file: JournalFile,
    /// Transitions and actions, from the cycle.
    pub queue: Arc<Handoff>,
    /// Flushes and the stop.
    pub rx: Receiver<Msg>,
    pub counters: Arc<Counters>,
    pub options: JournalOptions,
    pub seq: u64,
}

impl Writer {
    /// Runs until stopped (or every sender is gone); the error of the last sync, if it failed.
    pub fn run(mut self) -> Result<(), JournalError> {
        let interval = self.options.sync_interval;
        // Written in chunks of at most the compaction's slack, a compaction between them if
        // due: a batch of any size fits below the hard limit.
        let chunk = super::file::slack(self.options.capacity);
        let mut out = Out {
            buf: Vec::with_capacity(64 * 1024),
            count: 0,
            dirty: false,
            last_sync: Instant::now(),
            failed_compaction: None,
        };
        let mut window = (Instant::now(), 0usize);
        let mut flushes = Vec::new();
        let mut taken = Vec::with_capacity(self.options.queue);
        loop {
            let wait = if out.dirty {
                (out.last_sync + interval).saturating_duration_since(Instant::now())
            } else {
                POLL
            }
            .min(POLL);
            let mut stop = false;
            let first = match self.rx.recv_timeout(wait) {
                Ok(m) => Some(m),
                Err(RecvTimeoutError::Timeout) => None,
                Err(RecvTimeoutError::Disconnected) => {
                    stop = true;
                    None
                }
            };
            // The other control messages waiting, then what the cycle queued: everything
            // queued before a flush was asked for is in it.
            let rest: Vec<Msg> = std::iter::from_fn(|| self.rx.try_recv().ok())
                .take(16)
                .collect();
            self.queue.take(&mut taken);
            for msg in first.into_iter().chain(rest).chain(taken.drain(..)) {
                match msg {
                    Msg::Flush(tx) => flushes.push(tx),
                    Msg::Stop => stop = true,
                    Msg::Event { .. } | Msg::Action { .. } => {
                        if window.0.elapsed() >= Duration::from_secs(1) {
                            window = (Instant::now(), 0);
                        }
                        if window.1 >= self.options.per_second {
                            self.count(&msg);
                        } else if self.encode(&msg, &mut out.buf) {
                            window.1 += 1;
                            out.count += 1;
                            if out.count >= chunk {
                                self.write_out(&mut out);
                            }
                        }
                    }
                }
            }
            if !self.file.full(out.count + 1) {
                out.count += self.summary(&mut out.buf);
            }
            self.write_out(&mut out);
            let due = stop || !flushes.is_empty() || out.last_sync.elapsed() >= interval;
            let mut result = Ok(());
            if out.dirty && due {
                result = self.file.sync().map_err(|error| JournalError::Io {
                    path: self.file.path().to_owned(),
                    error,
                });
                if let Err(e) = &result {
                    log::error!(target: "plc_runtime::alarm_journal", "{e}");
                }
                out.dirty = false;
                out.last_sync = Instant::now();
            }
            for tx in flushes.drain(..) {
                let _ = tx.send(());
            }
            if stop {
                return result;
            }
        }
    }

    /// Appends what `out` holds, with a compaction before if the file is due for one (to make
    /// room) and after (so the file is within its capacity and slack between batches). While
    /// compactions fail (tried again once per interval) the file grows to its hard limit,
    /// then records are only counted, for the summary written once one succeeds.
    fn write_out(&mut self, out: &mut Out) {
        self.compact_if_due(out);
        self.append(out);
        self.compact_if_due(out);
    }

    fn compact_if_due(&mut self, out: &mut Out) {
        let interval = self.options.sync_interval;
        let retry = out
            .failed_compaction
            .is_none_or(|t: Instant| t.elapsed() >= interval);
        if !self.file.needs_compaction() || !retry {
            return;
        }
        match self.file.compact() {
            // The rewrite was synced whole.
            Ok(()) => {
                out.dirty = false;
                out.last_sync = Instant::now();
                out.failed_compaction = None;
            }
            Err(e) => {
                log::error!(target: "plc_runtime::alarm_journal",
                    "{e}; the journal grows to its limit, then only counts transitions, \
                     until a compaction succeeds");
                out.failed_compaction = Some(Instant::now());
            }
        }
    }

    fn append(&mut self, out: &mut Out) {
        let count = std::mem::take(&mut out.count);
        if count == 0 {
            return;
        }
        let written = if self.file.full(count) {
            Err(std::io::Error::other("full, and not compacted"))
        } else {
            self.file.append(&out.buf, count)
        };
        out.buf.clear();
        match written {
            Ok(()) => out.dirty = true,
            Err(e) => {
                log::error!(target: "plc_runtime::alarm_journal",
                    "alarm journal {}: {count} records not written: {e}; they are counted in \
                     the next summary record",
                    self.file.path().display());
                for _ in 0..count {
                    self.counters.count(false, i64::MIN);
                }
            }
        }
    }

    /// Counts a transition the budget per second had no room for.
    fn count(&self, msg: &Msg) {
        match msg {
            Msg::Event { event, .. } => self.counters.count(false, event.time_ns),
            Msg::Action { event, .. } => self.counters.count(true, event.time_ns),
            Msg::Flush(_) | Msg::Stop => {}
        }
    }

    /// Appends the record of a transition or action to `buf`; false if it was not (counted).
    fn encode(&mut self, msg: &Msg, buf: &mut Vec<u8>) -> bool {
        let (paths, event, value, by) = match msg {
            Msg::Event {
                paths,
                event,
                value,
            } => (paths, event, *value, None),
            Msg::Action { paths, event, by } => (paths, event, f64::NAN, Some(by.bounded())),
            Msg::Flush(_) | Msg::Stop => return false,
        };
        let path = paths.get(event.alarm).map_or_else(
            // A number past the table: recorded by its number rather than lost.
            || format!("#{}", event.alarm),
            |p| bounded(p, MAX_PATH),
        );
        let record = Record {
            seq: self.seq,
            time_ns: event.time_ns,
            path,
            entry: Entry::from_event(event, value, by),
        };
        if encode(&Item::Record(record), buf) {
            self.seq += 1;
            true
        } else {
            self.count(msg);
            false
        }
    }

    /// Appends a summary of what was only counted since the last one, if anything was; the
    /// number of records appended (0 or 1).
    fn summary(&mut self, buf: &mut Vec<u8>) -> usize {
        let transitions = self.counters.transitions.swap(0, Relaxed);
        let actions = self.counters.actions.swap(0, Relaxed);
        if transitions == 0 && actions == 0 {
            return 0;
        }
        let last = self.counters.last_ns.swap(i64::MIN, Relaxed);
        let record = Record {
            seq: self.seq,
            // A write that failed counts with no time: then the summary has the wall clock's.
            time_ns: if last == i64::MIN {
                i64::try_from(plc_shm::clock_ns(libc::CLOCK_REALTIME)).unwrap_or(i64::MAX)
            } else {
                last
            },
            path: String::new(),
            entry: Entry::Summarised {
                transitions,
                actions,
            },
        };
        self.seq += 1;
        usize::from(encode(&Item::Record(record), buf))
    }
}
