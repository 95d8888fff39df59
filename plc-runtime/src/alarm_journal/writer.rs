//! The writer thread: takes transitions from a bounded queue, appends them to the file in
//! batches, syncs at most once per interval (and at stop), compacts when the file is full.
//! The cycle's side ([`JournalSender`]) never blocks: when the queue is full a transition is
//! counted, and the next batch records the count ([`Entry::Summarised`]).

use super::file::JournalFile;
use super::frame::{Item, encode};
use super::record::{Entry, MAX_PATH, Operator, Record, bounded};
use super::{JournalError, JournalOptions};
use plc_core::alarm::AlarmEvent;
use std::sync::Arc;
use std::sync::atomic::{AtomicI64, AtomicU64, Ordering::Relaxed};
use std::sync::mpsc::{Receiver, RecvTimeoutError, SyncSender, TrySendError};
use std::time::{Duration, Instant};

/// What goes through the queue. An evaluator's transition is plain data and the path table is
/// shared, so handing one over allocates nothing.
pub(super) enum Msg {
    Event {
        paths: Arc<[String]>,
        event: AlarmEvent,
        value: f64,
    },
    Action {
        paths: Arc<[String]>,
        event: AlarmEvent,
        by: Box<Operator>,
    },
    /// Answer once everything before is on disk.
    Flush(SyncSender<()>),
    Stop,
}

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
    pub(super) tx: SyncSender<Msg>,
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
        if let Err(TrySendError::Full(_) | TrySendError::Disconnected(_)) = self.tx.try_send(msg) {
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
        if self.tx.try_send(msg).is_err() {
            self.counters.count(true, event.time_ns);
        }
    }

    /// Transitions and actions not recorded one by one since the start (only counted, in
    /// summary records).
    pub fn summarised(&self) -> u64 {
        self.counters.total()
    }
}

/// The writer thread's state.
pub(super) struct Writer {
    pub file: JournalFile,
    pub rx: Receiver<Msg>,
    pub counters: Arc<Counters>,
    pub options: JournalOptions,
    pub seq: u64,
}

impl Writer {
    /// Runs until stopped (or every sender is gone); the error of the last sync, if it failed.
    pub fn run(mut self) -> Result<(), JournalError> {
        let interval = self.options.sync_interval;
        let mut buf = Vec::with_capacity(64 * 1024);
        let mut dirty = false;
        let mut last_sync = Instant::now();
        let mut window = (Instant::now(), 0usize);
        let mut flushes = Vec::new();
        loop {
            let wait = if dirty {
                (last_sync + interval).saturating_duration_since(Instant::now())
            } else {
                Duration::from_secs(3600)
            };
            let mut stop = false;
            let mut count = 0;
            let first = match self.rx.recv_timeout(wait) {
                Ok(m) => Some(m),
                Err(RecvTimeoutError::Timeout) => None,
                Err(RecvTimeoutError::Disconnected) => {
                    stop = true;
                    None
                }
            };
            // What else is queued now, at most a queue's worth: a flood cannot hold the
            // batch open forever.
            let rest = std::iter::from_fn(|| self.rx.try_recv().ok()).take(self.options.queue);
            for msg in first.into_iter().chain(rest.collect::<Vec<_>>()) {
                match msg {
                    Msg::Flush(tx) => flushes.push(tx),
                    Msg::Stop => stop = true,
                    Msg::Event { .. } | Msg::Action { .. } => {
                        if window.0.elapsed() >= Duration::from_secs(1) {
                            window = (Instant::now(), 0);
                        }
                        if window.1 >= self.options.per_second {
                            self.count(&msg);
                        } else if self.encode(&msg, &mut buf) {
                            window.1 += 1;
                            count += 1;
                        }
                    }
                }
            }
            count += self.summary(&mut buf);
            if count > 0 {
                match self.file.append(&buf, count) {
                    Ok(()) => dirty = true,
                    Err(e) => {
                        log::error!(target: "plc_runtime::alarm_journal",
                            "alarm journal {}: {count} records not written: {e}; they are \
                             counted in the next summary record",
                            self.file.path().display());
                        for _ in 0..count {
                            self.counters.count(false, i64::MIN);
                        }
                    }
                }
                buf.clear();
            }
            if self.file.needs_compaction() {
                match self.file.compact() {
                    // The rewrite was synced whole.
                    Ok(()) => {
                        dirty = false;
                        last_sync = Instant::now();
                    }
                    Err(e) => log::error!(target: "plc_runtime::alarm_journal",
                        "{e}; the journal grows until a compaction succeeds"),
                }
            }
            let due = stop || !flushes.is_empty() || last_sync.elapsed() >= interval;
            let mut result = Ok(());
            if dirty && due {
                result = self.file.sync().map_err(|error| JournalError::Io {
                    path: self.file.path().to_owned(),
                    error,
                });
                if let Err(e) = &result {
                    log::error!(target: "plc_runtime::alarm_journal", "{e}");
                }
                dirty = false;
                last_sync = Instant::now();
            }
            for tx in flushes.drain(..) {
                let _ = tx.send(());
            }
            if stop {
                return result;
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
