//! One line of the journal file, framed and checked: `XXXXXXXX {json}\n`, where `XXXXXXXX` is
//! the CRC-32 (lowercase hex) of the JSON text between the space and the newline.
//!
//! A line is one of three things, told apart by its first key: the header (`"journal"`, the
//! first line of a compacted file: how many records were dropped), an alarm's state at the cut
//! (`"state"`, written by a compaction for each alarm not normal, so that dropping old records
//! never loses an unacknowledged alarm), or a [`Record`].

use super::record::{Record, level};
use plc_core::alarm::{Level, Shelf, Snapshot};
use serde::{Deserialize, Serialize};
use std::io::Write;

/// The longest line a journal holds (a record's strings are cut so that every line fits): a
/// reader takes anything longer for damage without parsing it.
pub const MAX_LINE: usize = 4096;

/// What the header line's `journal` key says: the file is a plc-vars alarm journal.
const MAGIC: &str = "plc-vars alarm journal";
/// The format's version; a newer one is refused line by line (reported, never guessed at).
const VERSION: u32 = 1;

/// One line's content.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum Item {
    /// The first line of a compacted file.
    Header {
        /// Records dropped by the bound so far, in all the file's history.
        dropped: u64,
    },
    /// An alarm's state where a compaction cut the file.
    State {
        /// The alarm's path.
        path: String,
        /// Its state then.
        state: Snapshot,
    },
    /// A transition.
    Record(Record),
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct HeaderWire {
    journal: String,
    version: u32,
    dropped: u64,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct StateWire {
    state: String,
    #[serde(with = "level")]
    level: Level,
    acknowledged: bool,
    held: bool,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    shelf: Option<ShelfWire>,
    since: i64,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct ShelfWire {
    by: String,
    since: i64,
    until: i64,
}

/// Appends `item`'s line to `out`. False (and `out` as it was) if it would be longer than
/// [`MAX_LINE`], which the bounds on a record's strings keep from happening.
pub(super) fn encode(item: &Item, out: &mut Vec<u8>) -> bool {
    let start = out.len();
    // The checksum goes first but covers what follows: write a placeholder, then patch it.
    out.extend_from_slice(b"00000000 ");
    let written = match item {
        Item::Header { dropped } => serde_json::to_writer(
            &mut *out,
            &HeaderWire {
                journal: MAGIC.into(),
                version: VERSION,
                dropped: *dropped,
            },
        ),
        Item::State { path, state } => serde_json::to_writer(
            &mut *out,
            &StateWire {
                state: path.clone(),
                level: state.level,
                acknowledged: state.acknowledged,
                held: state.held,
                shelf: state.shelf.as_ref().map(|s| ShelfWire {
                    by: s.by.clone(),
                    since: s.since_ns,
                    until: s.until_ns,
                }),
                since: state.since_ns,
            },
        ),
        Item::Record(r) => serde_json::to_writer(&mut *out, r),
    };
    if written.is_err() || out.len() - start + 1 > MAX_LINE {
        out.truncate(start);
        return false;
    }
    let crc = crc32fast::hash(&out[start + 9..]);
    let mut hex = [0u8; 8];
    let _ = write!(&mut hex[..], "{crc:08x}");
    out[start..start + 8].copy_from_slice(&hex);
    out.push(b'\n');
    true
}

/// The content of one line (without its newline), or why it is damaged.
pub(super) fn decode(line: &[u8]) -> Result<Item, String> {
    if line.len() > MAX_LINE {
        return Err(format!(
            "{} bytes, longer than any record ({MAX_LINE})",
            line.len()
        ));
    }
    let (Some(hex), Some(b' '), Some(json)) = (line.get(..8), line.get(8), line.get(9..)) else {
        return Err("too short for a record".into());
    };
    let crc = std::str::from_utf8(hex)
        .ok()
        .filter(|h| h.bytes().all(|b| b.is_ascii_hexdigit()))
        .and_then(|h| u32::from_str_radix(h, 16).ok())
        .ok_or("no checksum at its start")?;
    if crc32fast::hash(json) != crc {
        return Err("checksum mismatch: the record was changed or cut".into());
    }
    let value: serde_json::Value =
        serde_json::from_slice(json).map_err(|e| format!("not JSON: {e}"))?;
    let object = value.as_object().ok_or("not a JSON object")?;
    let item = if object.contains_key("journal") {
        let h: HeaderWire = serde_json::from_value(value).map_err(|e| e.to_string())?;
        if h.journal != MAGIC || h.version != VERSION {
            return Err(format!(
                "a header of `{}` version {}, not of `{MAGIC}` version {VERSION}",
                h.journal, h.version
            ));
        }
        Item::Header { dropped: h.dropped }
    } else if object.contains_key("state") {
        let s: StateWire = serde_json::from_value(value).map_err(|e| e.to_string())?;
        Item::State {
            path: s.state,
            state: Snapshot {
                level: s.level,
                acknowledged: s.acknowledged,
                held: s.held,
                shelf: s.shelf.map(|f| Shelf {
                    by: f.by,
                    since_ns: f.since,
                    until_ns: f.until,
                }),
                since_ns: s.since,
            },
        }
    } else {
        Item::Record(serde_json::from_value(value).map_err(|e| format!("not a record: {e}"))?)
    };
    Ok(item)
}
