//! The journal's tests, one concern a file; what they share is here.

mod bound;
mod compaction;
mod damage;
mod framing;
mod hostile;
mod reader_fuzz;
mod replay;
mod writer;

use super::frame::{Item, encode};
use super::record::{Entry, Record};
use plc_core::alarm::Level;
use std::os::unix::fs::PermissionsExt;
use std::path::PathBuf;

/// A new private directory (mode 0700, as the journal wants its directory) for one test.
pub(super) fn private_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("plc-journal-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::set_permissions(&dir, std::fs::Permissions::from_mode(0o700)).unwrap();
    dir
}

/// Record `seq` of alarm `path`: raised at time `seq`.
pub(super) fn raised(seq: u64, path: &str) -> Record {
    Record {
        seq,
        time_ns: seq as i64,
        path: path.into(),
        entry: Entry::Raised {
            level: Level::Active,
            value: Some(1.0),
        },
    }
}

/// The line of `item`.
pub(super) fn line(item: Item) -> Vec<u8> {
    let mut out = Vec::new();
    assert!(encode(&item, &mut out));
    out
}

/// A file's bytes: one raised record for each of `1..=n`, alarms `a0`..`a9`.
pub(super) fn file_of(n: u64) -> Vec<u8> {
    (1..=n)
        .flat_map(|s| line(Item::Record(raised(s, &format!("a{}", s % 10)))))
        .collect()
}
