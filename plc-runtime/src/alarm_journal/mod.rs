//! The alarm journal: a file that records every alarm transition (raised, acknowledged by
//! whom, cleared, shelved, reset, suppressed), read back when a program starts so that an
//! alarm unacknowledged before a restart is unacknowledged after it, and shown as the alarm
//! history.
//!
//! # The file
//!
//! Text, one record a line, each line checked on its own:
//!
//! ```text
//! fde8fe9f {"journal":"plc-vars alarm journal","version":1,"dropped":1250}
//! 2d106143 {"state":"oil","level":"high","acknowledged":false,"held":false,"since":1764950400000000000}
//! 7d075397 {"seq":1251,"t":1764950401000000000,"path":"door","ev":"raised","level":"active","value":1.0}
//! 83d67a7c {"seq":1252,"t":1764950405000000000,"path":"door","ev":"acknowledged","by":{"uid":1000,"user":"anna","comment":"checked"}}
//! ```
//!
//! Each line starts with the CRC-32 of the JSON after the space. Why lines of JSON rather than
//! a compact binary: an auditor reads the file with `less` or `grep` and needs no tool of
//! ours to trust it; a damaged line ends at its newline, so the next one is found without
//! guessing (a binary length that is itself damaged loses every record after it); and the
//! cost (about 150 bytes a record, a few microseconds to write) is the writer thread's, never
//! the cycle's. A line is taken only whole and with its checksum right: a damaged one is
//! reported ([`Damage`]: line, byte offset, why) and the others read; a last line without its
//! newline (a write a crash cut short) is reported ([`Torn`]), never read, and cut off when
//! the writer opens the file.
//!
//! # Bounded
//!
//! It keeps its capacity's last records ([`DEFAULT_CAPACITY`], 10,000). Records are appended;
//! once the file holds a quarter more, it is rewritten whole (temporary file, fsync, rename,
//! as every plc-vars file is): a header saying how many records were dropped in all, the state
//! of each alarm that was not normal where the file was cut (so dropping its old records
//! never loses an unacknowledged alarm), then the records kept. A reader counts records past
//! the capacity as dropped already, so it always sees at most the capacity.
//!
//! # Written off the cycle
//!
//! [`AlarmJournal::open`] reads the file and starts a writer thread; the cycle hands each
//! transition to a [`JournalSender`], which never waits and allocates nothing: when its
//! queue is full (or the writer is taking it that instant) the transition is only counted,
//! and the journal gets a [`Entry::Summarised`] record with the count. The writer takes the
//! queue every 50 ms, and also records at most [`JournalOptions::per_second`] records a
//! second (the rest summarised), so a flood cannot wear the disk out. Each record is written
//! when taken and synced within [`JournalOptions::sync_interval`] (one second) of that, at
//! most one sync per interval, and a last time at stop.
//!
//! # Hostile files
//!
//! The file is opened without following a link (a link at its path is refused, naming it);
//! it and its directory must be this user's own and private, as the retain file's; a file
//! larger than a journal of its capacity can be is refused without being read; no input
//! makes the reader panic or loop without end.
//!
//! ```
//! use plc_core::alarm::{AlarmEvent, AlarmState, Alarms, Condition, EventKind, Level};
//! use plc_runtime::alarm_journal::{self, AlarmJournal};
//!
//! let dir = std::env::temp_dir().join(format!("journal-doc-{}", std::process::id()));
//! let file = dir.join("press.alarms");
//! let paths = vec!["door".to_string()];
//!
//! // A run: the door alarm is raised, nobody acknowledges it.
//! let journal = AlarmJournal::open(&file, alarm_journal::DEFAULT_CAPACITY)?;
//! let sender = journal.sender(paths.clone());
//! let raised = AlarmEvent { alarm: 0, time_ns: 1_000, kind: EventKind::Raised { level: Level::Active } };
//! sender.record(&raised, 1.0);
//! journal.finish()?;
//!
//! // The next run starts with it still unacknowledged.
//! let journal = AlarmJournal::open(&file, alarm_journal::DEFAULT_CAPACITY)?;
//! let mut alarms = Alarms::new([Condition::discrete(true)]);
//! alarm_journal::restore(&mut alarms, &paths, journal.contents().states());
//! assert_eq!(alarms.state(0), AlarmState::ActiveUnacknowledged);
//! assert_eq!(journal.contents().history(None).count(), 1);
//! # drop(journal);
//! # std::fs::remove_dir_all(&dir).unwrap();
//! # Ok::<(), alarm_journal::JournalError>(())
//! ```

mod display;
mod file;
mod frame;
mod handoff;
mod journal;
mod message;
mod read;
mod record;
mod replay;
mod writer;

#[cfg(test)]
mod tests;

pub use frame::MAX_LINE;
pub use journal::{AlarmJournal, JournalOptions, beside_retain, read_journal};
pub use read::{Contents, Damage, Torn};
pub use record::{Entry, Operator, Record};
pub use replay::{RestoreReport, restore};
pub use writer::JournalSender;

use std::fmt;
use std::path::PathBuf;

/// The records a journal keeps unless told otherwise.
pub const DEFAULT_CAPACITY: usize = 10_000;

/// Why the journal could not be used.
#[derive(Debug)]
pub enum JournalError {
    /// Reading or writing failed.
    Io {
        /// The file or directory.
        path: PathBuf,
        /// The OS error.
        error: std::io::Error,
    },
    /// The file or its directory is a symbolic link, not a regular file or directory,
    /// belongs to another user or is open to other users: it is not used, so that nobody else
    /// can plant or change the alarm history, or make the program write elsewhere.
    Unsafe {
        /// The file or directory.
        path: PathBuf,
        /// What is wrong with it.
        problem: String,
        /// What to do.
        fix: String,
    },
    /// The file is larger than a journal of its capacity can be: not one this program wrote.
    TooLarge {
        /// The file.
        path: PathBuf,
        /// Its size in bytes.
        size: u64,
        /// The largest a journal of this capacity can be.
        max: u64,
    },
}

impl fmt::Display for JournalError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            JournalError::Io { path, error } => {
                write!(f, "alarm journal {}: {error}", path.display())
            }
            JournalError::Unsafe { path, problem, fix } => write!(
                f,
                "refusing alarm journal path {}: it {problem}; {fix}",
                path.display()
            ),
            JournalError::TooLarge { path, size, max } => write!(
                f,
                "alarm journal {} is {size} bytes, more than a journal of this capacity can be \
                 ({max}): it was left untouched; move it away to start a new history, or give \
                 the journal a larger capacity",
                path.display()
            ),
        }
    }
}

impl std::error::Error for JournalError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            JournalError::Io { error, .. } => Some(error),
            JournalError::Unsafe { .. } | JournalError::TooLarge { .. } => None,
        }
    }
}
