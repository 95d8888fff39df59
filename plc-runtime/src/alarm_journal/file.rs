//! The journal file on disk. Opened without following a link, refused if it (or its
//! directory) is not this user's own and private, refused if larger than a journal of its
//! capacity can be; appended to; compacted (rewritten whole through `plc_files`) when it holds
//! a quarter more records than its capacity.

use super::JournalError;
use super::frame::{Item, MAX_LINE, encode};
use super::read::{self, Contents};
use super::replay;
use plc_shm::euid;
use std::collections::BTreeMap;
use std::fs::{self, File, OpenOptions};
use std::io::{self, Write};
use std::os::unix::fs::{DirBuilderExt, FileExt, OpenOptionsExt};
use std::path::{Path, PathBuf};

/// Records over the capacity before a compaction: a quarter more, so a compaction (which
/// rewrites the whole file) comes once every capacity/4 records, not at each one.
pub(super) fn slack(capacity: usize) -> usize {
    (capacity / 4).max(1)
}

/// The most records a file holds: when compactions fail (the directory became unsafe, the
/// disk is full) records past this are only counted, so the file stays within [`max_bytes`].
pub(super) fn hard_limit(capacity: usize) -> usize {
    capacity.saturating_add(slack(capacity).saturating_mul(2))
}

/// The most alarm states a compaction writes: one per alarm not normal at the cut, which
/// the number of alarms bounds, not the capacity (a small journal of a large program keeps
/// them all); past this many (a program with more alarms not normal at once) the rest are
/// left out, and logged.
pub(super) fn max_states(capacity: usize) -> usize {
    capacity.max(10_000)
}

/// The largest file a journal of `capacity` records can be: its records up to the
/// [`hard_limit`], its [`max_states`], the header, every line at its longest. A larger file
/// is no journal this program wrote, and is not read into memory.
pub(super) fn max_bytes(capacity: usize) -> u64 {
    let lines = hard_limit(capacity)
        .saturating_add(max_states(capacity))
        .saturating_add(1);
    (lines as u64).saturating_mul(MAX_LINE as u64)
}

/// An open journal file, appended to.
pub(super) struct JournalFile {
    path: PathBuf,
    file: File,
    capacity: usize,
    /// Records in the file (after the header and states): what the capacity counts.
    records: usize,
    /// The file's length after the last whole write: a write that fails halfway is cut back
    /// to it, so the next record starts a line of its own.
    len: u64,
    /// Writes so far, for the test hook.
    #[cfg(feature = "fault-injection")]
    writes: u64,
}

impl JournalFile {
    /// Opens the journal at `path` for appending (creating it, mode 0600, and its directory,
    /// mode 0700, if missing), reads it, and cuts off a torn end so the next record starts a
    /// line of its own (the torn bytes are reported in the contents).
    pub fn open(path: &Path, capacity: usize) -> Result<(JournalFile, Contents), JournalError> {
        checked_dir(path, true)?;
        remove_stale_temps(path);
        let file = open_checked(path, true, capacity)?
            .ok_or_else(|| io_error(path, io::ErrorKind::NotFound.into()))?;
        let bytes = read_all(path, &file, capacity)?;
        let contents = Contents::from_bytes(&bytes, capacity);
        if bytes.is_empty() {
            // A new (or empty) file: its directory entry must survive a power cut too.
            File::open(plc_files::dir_of(path))
                .and_then(|d| d.sync_all())
                .map_err(|e| io_error(path, e))?;
        }
        let mut len = bytes.len() as u64;
        if let Some(torn) = contents.torn() {
            file.set_len(torn.offset)
                .and_then(|()| file.sync_all())
                .map_err(|e| io_error(path, e))?;
            len = torn.offset;
        }
        let mut journal = JournalFile {
            path: path.to_owned(),
            file,
            capacity,
            records: contents.records_in_file(),
            len,
            #[cfg(feature = "fault-injection")]
            writes: 0,
        };
        if journal.needs_compaction() {
            journal.compact()?;
        }
        Ok((journal, contents))
    }

    /// The file's path.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Appends whole lines (`count` records), in one write. On an error nothing of them
    /// stays in the file.
    pub fn append(&mut self, lines: &[u8], count: usize) -> io::Result<()> {
        #[cfg(feature = "fault-injection")]
        {
            self.writes += 1;
            stall_halfway(&mut self.file, lines, self.writes)?;
        }
        if let Err(e) = self.file.write_all(lines) {
            let _ = self.file.set_len(self.len);
            return Err(e);
        }
        self.len += lines.len() as u64;
        self.records += count;
        Ok(())
    }

    /// Puts what was appended on disk.
    pub fn sync(&mut self) -> io::Result<()> {
        self.file.sync_data()
    }

    /// Whether the file holds its slack over the capacity.
    pub fn needs_compaction(&self) -> bool {
        self.records > self.capacity + slack(self.capacity)
    }

    /// Whether `count` more records would take the file past its [`hard_limit`] (only when
    /// compactions fail).
    pub fn full(&self, count: usize) -> bool {
        self.records.saturating_add(count) > hard_limit(self.capacity)
    }

    /// Rewrites the file whole (temporary file, fsync, rename): a header with the count of
    /// records dropped, the state of each alarm not normal at the cut, and the last
    /// `capacity` records as they are, with the damaged lines among them (a damaged line
    /// stays, for whoever looks into it, until it is old enough to go).
    pub fn compact(&mut self) -> Result<(), JournalError> {
        let bytes = read_all(&self.path, &self.file, self.capacity)?;
        let (lines, _) = read::lines(&bytes);
        let mut dropped = 0u64;
        let mut states = BTreeMap::new();
        let mut units = Vec::with_capacity(lines.len());
        for (i, line) in lines.iter().enumerate() {
            match &line.item {
                Ok(Item::Header { dropped: d }) if i == 0 => dropped = *d,
                Ok(Item::State { path, state }) => {
                    states.insert(path.clone(), state.clone());
                }
                _ => units.push(line),
            }
        }
        let records = units
            .iter()
            .filter(|l| matches!(l.item, Ok(Item::Record(_))))
            .count();
        let excess = records.saturating_sub(self.capacity);
        // The cut: just past the `excess`-th record (damaged lines before it go with it).
        let mut cut = 0;
        let mut seen = 0;
        while seen < excess {
            if let Ok(Item::Record(r)) = &units[cut].item {
                replay::apply(&mut states, r);
                seen += 1;
            }
            cut += 1;
        }
        let mut out = Vec::with_capacity(bytes.len());
        encode(
            &Item::Header {
                dropped: dropped.saturating_add(excess as u64),
            },
            &mut out,
        );
        let notable: Vec<_> = states
            .into_iter()
            .filter(|(_, s)| replay::notable(s))
            .collect();
        let limit = max_states(self.capacity);
        if notable.len() > limit {
            log::warn!(target: "plc_runtime::alarm_journal",
                "alarm journal {}: {} alarms not normal where the file was cut, only {limit} \
                 kept (the file's limit): the others start normal after a restart unless a \
                 record kept names them",
                self.path.display(), notable.len());
        }
        for (path, state) in notable.into_iter().take(limit) {
            encode(&Item::State { path, state }, &mut out);
        }
        for line in &units[cut..] {
            let start = line.offset as usize;
            out.extend_from_slice(&bytes[start..start + line.len]);
            out.push(b'\n');
        }
        checked_dir(&self.path, false)?;
        plc_files::write_atomically(&self.path, &out, 0o600)
            .map_err(|e| io_error(&self.path, e))?;
        self.file = open_checked(&self.path, true, self.capacity)?
            .ok_or_else(|| io_error(&self.path, io::ErrorKind::NotFound.into()))?;
        self.records = records - excess;
        self.len = out.len() as u64;
        Ok(())
    }
}

/// Reads the journal at `path` without changing it (`None` if there is none): for a tool
/// that shows the history of a running program.
pub(super) fn read_only(path: &Path, capacity: usize) -> Result<Option<Contents>, JournalError> {
    if !plc_files::dir_of(path).exists() {
        return Ok(None);
    }
    checked_dir(path, false)?;
    let Some(file) = open_checked(path, false, capacity)? else {
        return Ok(None);
    };
    let bytes = read_all(path, &file, capacity)?;
    Ok(Some(Contents::from_bytes(&bytes, capacity)))
}

fn io_error(path: &Path, error: io::Error) -> JournalError {
    JournalError::Io {
        path: path.to_owned(),
        error,
    }
}

/// The whole file, refused if larger than a journal of `capacity` can be.
fn read_all(path: &Path, file: &File, capacity: usize) -> Result<Vec<u8>, JournalError> {
    let size = file.metadata().map_err(|e| io_error(path, e))?.len();
    within_bound(path, size, capacity)?;
    let mut bytes = vec![0; size as usize];
    file.read_exact_at(&mut bytes, 0)
        .map_err(|e| io_error(path, e))?;
    Ok(bytes)
}

/// Opens the file without following a link (for appending if `write`, then created 0600 if
/// missing), checked: a regular file of this user that no other user may read or write.
/// `None` if it does not exist and `write` is false.
fn open_checked(path: &Path, write: bool, capacity: usize) -> Result<Option<File>, JournalError> {
    let mut options = OpenOptions::new();
    options.read(true);
    if write {
        options.append(true).create(true).mode(0o600);
    }
    // O_NONBLOCK: a FIFO planted at the path must not hang the open; a regular file ignores it.
    options.custom_flags(libc::O_NOFOLLOW | libc::O_CLOEXEC | libc::O_NONBLOCK);
    let file = match options.open(path) {
        Ok(f) => f,
        Err(e) if e.kind() == io::ErrorKind::NotFound && !write => return Ok(None),
        Err(e) if e.raw_os_error() == Some(libc::ELOOP) => {
            let (problem, fix) = crate::private_dir::link_problem(path);
            return Err(JournalError::Unsafe {
                path: path.to_owned(),
                problem,
                fix,
            });
        }
        Err(e) => return Err(io_error(path, e)),
    };
    let meta = file.metadata().map_err(|e| io_error(path, e))?;
    if let Some((problem, fix)) = crate::private_dir::file_problem(path, &meta, euid()) {
        return Err(JournalError::Unsafe {
            path: path.to_owned(),
            problem,
            fix,
        });
    }
    within_bound(path, meta.len(), capacity)?;
    Ok(Some(file))
}

/// Refuses a file of `size` bytes larger than a journal of `capacity` can be: not one this
/// program wrote.
fn within_bound(path: &Path, size: u64, capacity: usize) -> Result<(), JournalError> {
    let max = max_bytes(capacity);
    if size > max {
        return Err(JournalError::TooLarge {
            path: path.to_owned(),
            size,
            max,
        });
    }
    Ok(())
}

/// The directory of `path`, checked as the retain file's is: a directory (not a link) of
/// this user that no other user may write, since whoever can write it can swap the file.
/// `create`: made 0700 if missing.
fn checked_dir(path: &Path, create: bool) -> Result<(), JournalError> {
    let dir = plc_files::dir_of(path);
    if create && !dir.exists() {
        fs::DirBuilder::new()
            .recursive(true)
            .mode(0o700)
            .create(dir)
            .map_err(|e| io_error(dir, e))?;
    }
    let meta = fs::symlink_metadata(dir).map_err(|e| io_error(dir, e))?;
    if let Some((problem, fix)) = crate::private_dir::problem(dir, &meta, euid()) {
        return Err(JournalError::Unsafe {
            path: dir.to_owned(),
            problem,
            fix,
        });
    }
    Ok(())
}

/// Removes the temporary files of compactions by processes that are gone (each could be as
/// large as the journal). A live process's is left alone: it may be compacting now.
fn remove_stale_temps(path: &Path) {
    let Ok(entries) = fs::read_dir(plc_files::dir_of(path)) else {
        return;
    };
    for entry in entries.flatten() {
        let Some(pid) = plc_files::temp_owner(path, &entry.file_name()) else {
            continue;
        };
        let alive = i32::try_from(pid).is_ok_and(|p| {
            // SAFETY: signal 0 only checks that the process exists; nothing is delivered.
            let reached = unsafe { libc::kill(p, 0) } == 0;
            reached || io::Error::last_os_error().raw_os_error() == Some(libc::EPERM)
        });
        if !alive {
            let _ = fs::remove_file(entry.path());
        }
    }
}

/// Test hook (feature `fault-injection`, which only tests enable): with the environment
/// variable `PLC_JOURNAL_FAULT=stall`, the 20th write of a batch of more than one record
/// stops inside its second record and the writer sleeps from then on, so a test can kill the process with its
/// last record torn, as a kill in the middle of a write (or a power cut) leaves it. Without
/// the feature there is no such hook: a production program never stalls because of its
/// environment.
#[cfg(feature = "fault-injection")]
fn stall_halfway(file: &mut File, lines: &[u8], writes: u64) -> io::Result<()> {
    if writes >= 20
        && lines.iter().filter(|&&b| b == b'\n').count() > 1
        && std::env::var("PLC_JOURNAL_FAULT").is_ok_and(|v| v == "stall")
    {
        // The first line and ten bytes of the second (every line is longer: its checksum
        // alone is nine), so the cut is surely inside a record.
        let first = lines.iter().position(|&b| b == b'\n').unwrap_or(0);
        file.write_all(&lines[..first + 11])?;
        loop {
            std::thread::sleep(std::time::Duration::from_secs(3600));
        }
    }
    Ok(())
}
