//! [`AlarmJournal`]: a journal file opened, read back, and its writer thread started; and
//! [`read_journal`], reading one without writing (a tool showing a running program's history).

use super::file::{self, JournalFile};
use super::handoff::Handoff;
use super::message::Msg;
use super::read::Contents;
use super::writer::{Counters, JournalSender, Writer};
use super::{DEFAULT_CAPACITY, JournalError};
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::mpsc;
use std::thread::JoinHandle;
use std::time::Duration;

/// How a journal is kept.
///
/// ```
/// use plc_runtime::alarm_journal::JournalOptions;
/// let o = JournalOptions { capacity: 1_000, ..JournalOptions::default() };
/// assert_eq!(o.per_second, 1_000);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct JournalOptions {
    /// Records kept; older ones are dropped, and counted (10,000).
    pub capacity: usize,
    /// Transitions the queue to the writer holds (8,192): more in one go are summarised.
    pub queue: usize,
    /// Records written at most each second (1,000); more are summarised. A flood of
    /// transitions then writes a bounded amount, and compacts at most every quarter
    /// capacity's worth of records.
    pub per_second: usize,
    /// The longest a record waits to be synced to disk (1 s); at most one sync each.
    pub sync_interval: Duration,
}

impl Default for JournalOptions {
    fn default() -> JournalOptions {
        JournalOptions {
            capacity: DEFAULT_CAPACITY,
            queue: 8192,
            per_second: 1000,
            sync_interval: Duration::from_secs(1),
        }
    }
}

/// An alarm journal being written: what it held when opened ([`contents`](Self::contents)),
/// and a writer thread fed by [`JournalSender`]s. Stopped by [`finish`](Self::finish) (or
/// when dropped), which syncs what is written.
///
/// ```
/// use plc_runtime::alarm_journal::AlarmJournal;
/// let dir = std::env::temp_dir().join(format!("journal-open-doc-{}", std::process::id()));
/// let journal = AlarmJournal::open(dir.join("line.alarms"), 10_000)?;
/// assert!(journal.contents().records().is_empty());
/// journal.finish()?;
/// # std::fs::remove_dir_all(&dir).unwrap();
/// # Ok::<(), plc_runtime::alarm_journal::JournalError>(())
/// ```
pub struct AlarmJournal {
    /// Flushes and the stop.
    tx: Option<mpsc::SyncSender<Msg>>,
    /// Transitions and actions, from the cycle.
    queue: Arc<Handoff>,
    counters: Arc<Counters>,
    thread: Option<JoinHandle<Result<(), JournalError>>>,
    path: PathBuf,
    contents: Contents,
}

impl AlarmJournal {
    /// Opens the journal at `path` keeping `capacity` records (creating it, and its
    /// directory, if missing), reads it back (damage and a torn end are logged), and starts
    /// the writer.
    pub fn open(path: impl AsRef<Path>, capacity: usize) -> Result<AlarmJournal, JournalError> {
        AlarmJournal::open_with(
            path,
            JournalOptions {
                capacity,
                ..JournalOptions::default()
            },
        )
    }

    /// [`open`](Self::open) with every option.
    pub fn open_with(
        path: impl AsRef<Path>,
        options: JournalOptions,
    ) -> Result<AlarmJournal, JournalError> {
        let path = path.as_ref();
        let options = JournalOptions {
            capacity: options.capacity.max(1),
            queue: options.queue.max(1),
            per_second: options.per_second.max(1),
            sync_interval: options.sync_interval,
        };
        let (file, contents) = JournalFile::open(path, options.capacity)?;
        contents.log(path);
        let (tx, rx) = mpsc::sync_channel(16);
        let queue = Arc::new(Handoff::new(options.queue));
        let counters = Arc::new(Counters::new());
        let writer = Writer {
            file,
            queue: queue.clone(),
            rx,
            counters: counters.clone(),
            options,
            seq: contents.next_seq(),
        };
        let thread = std::thread::Builder::new()
            .name("plc-alarm-journal".into())
            .spawn(move || {
                // Writing and syncing must not compete with a realtime cycle, whose priority
                // this thread would otherwise inherit.
                plc_shm::normal_priority();
                writer.run()
            })
            .map_err(|error| JournalError::Io {
                path: path.to_owned(),
                error,
            })?;
        Ok(AlarmJournal {
            tx: Some(tx),
            queue,
            counters,
            thread: Some(thread),
            path: path.to_owned(),
            contents,
        })
    }

    /// What the journal held when opened: its records, the state of each alarm by path
    /// (for [`restore`](super::restore)), what was damaged.
    pub fn contents(&self) -> &Contents {
        &self.contents
    }

    /// The file.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// A sender for the cycle, for alarms named by `paths` in the evaluator's order.
    pub fn sender(&self, paths: impl Into<Arc<[String]>>) -> JournalSender {
        JournalSender {
            queue: self.queue.clone(),
            paths: paths.into(),
            counters: self.counters.clone(),
        }
    }

    /// Transitions and actions not recorded one by one so far (only counted, in summary
    /// records).
    pub fn summarised(&self) -> u64 {
        self.counters.total()
    }

    /// Waits until everything queued before is written and synced (blocks: not for the
    /// cycle).
    pub fn flush(&self) -> Result<(), JournalError> {
        let (done, wait) = mpsc::sync_channel(1);
        let gone = || JournalError::Io {
            path: self.path.clone(),
            error: std::io::Error::other("the alarm journal's writer has stopped"),
        };
        let tx = self.tx.as_ref().ok_or_else(gone)?;
        tx.send(Msg::Flush(done)).map_err(|_| gone())?;
        wait.recv().map_err(|_| gone())
    }

    /// Writes and syncs what is queued, and stops the writer. An error if the last sync
    /// failed: the file then holds what the system had written of it.
    pub fn finish(mut self) -> Result<(), JournalError> {
        self.stop()
    }

    fn stop(&mut self) -> Result<(), JournalError> {
        if let Some(tx) = self.tx.take() {
            let _ = tx.send(Msg::Stop);
        }
        match self.thread.take().map(JoinHandle::join) {
            Some(Ok(result)) => result,
            Some(Err(_)) => Err(JournalError::Io {
                path: self.path.clone(),
                error: std::io::Error::other("the alarm journal's writer thread panicked"),
            }),
            None => Ok(()),
        }
    }
}

impl Drop for AlarmJournal {
    fn drop(&mut self) {
        if let Err(e) = self.stop() {
            log::error!(target: "plc_runtime::alarm_journal", "{e}");
        }
    }
}

/// Where the journal of a program with retain file `retain` goes unless told otherwise:
/// beside it, the same name with the extension `alarms` (`alarms.journal` for a retain file
/// that has that extension already, so that the two are never one file).
///
/// ```
/// use plc_runtime::alarm_journal::beside_retain;
/// use std::path::Path;
/// assert_eq!(beside_retain(Path::new("state/press.retain")), Path::new("state/press.alarms"));
/// assert_eq!(beside_retain(Path::new("press")), Path::new("press.alarms"));
/// assert_eq!(beside_retain(Path::new("odd.alarms")), Path::new("odd.alarms.journal"));
/// ```
pub fn beside_retain(retain: &Path) -> PathBuf {
    if retain.extension().is_some_and(|e| e == "alarms") {
        retain.with_extension("alarms.journal")
    } else {
        retain.with_extension("alarms")
    }
}

/// Reads the journal at `path` (keeping `capacity` records) without writing to it: `None` if
/// there is none. The same checks as [`AlarmJournal::open`]: no link followed, this user's
/// own private file, no larger than a journal can be.
///
/// ```
/// let dir = std::env::temp_dir().join(format!("journal-read-doc-{}", std::process::id()));
/// std::fs::create_dir_all(&dir).unwrap();
/// # use std::os::unix::fs::PermissionsExt;
/// # std::fs::set_permissions(&dir, std::fs::Permissions::from_mode(0o700)).unwrap();
/// let c = plc_runtime::alarm_journal::read_journal(dir.join("none.alarms"), 10_000)?;
/// assert!(c.is_none());
/// # std::fs::remove_dir_all(&dir).unwrap();
/// # Ok::<(), plc_runtime::alarm_journal::JournalError>(())
/// ```
pub fn read_journal(
    path: impl AsRef<Path>,
    capacity: usize,
) -> Result<Option<Contents>, JournalError> {
    file::read_only(path.as_ref(), capacity.max(1))
}
