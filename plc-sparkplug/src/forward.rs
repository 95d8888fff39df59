//! Store-and-forward: the data that changes while no birth is out (the broker away, the
//! primary host offline) kept on disk, bounded, and sent after the next births as historical
//! values, oldest first.
//!
//! Two files in the store directory: `forward.1` takes new records; when it holds half the
//! bound it becomes `forward.0`, replacing the older one, whose records are dropped and
//! counted. So the store never holds more than the bound, and drops the oldest half when
//! full. A record is `[u32 LE length][u16 LE device length][device id][Payload]`; the files
//! are appended without syncing (a crash loses what the kernel had not written yet).

use crate::proto::Payload;
use prost::Message;
use std::fs::{self, File, OpenOptions};
use std::io::{Read, Write};
use std::os::unix::fs::OpenOptionsExt;
use std::path::{Path, PathBuf};

const OLD: &str = "forward.0";
const NEW: &str = "forward.1";
/// The default bound of the store, in bytes.
pub const DEFAULT_MAX: u64 = 64 << 20;
/// The smallest bound: a few records of a large program.
pub const MIN_MAX: u64 = 64 << 10;

/// The store of data waiting for a birth.
pub struct Forward {
    dir: PathBuf,
    max: u64,
    new_len: u64,
    file: Option<File>,
    /// Records dropped because the store was full, since start.
    pub dropped: u64,
}

fn open_append(path: &Path) -> std::io::Result<File> {
    OpenOptions::new()
        .append(true)
        .create(true)
        .mode(0o600)
        .custom_flags(libc::O_NOFOLLOW)
        .open(path)
}

impl Forward {
    /// The store in `dir`, at most `max` bytes; records left by an earlier run are kept and
    /// sent after the next births.
    pub fn open(dir: &Path, max: u64) -> Forward {
        let new_len = fs::symlink_metadata(dir.join(NEW)).map_or(0, |m| m.len());
        Forward {
            dir: dir.to_path_buf(),
            max: max.max(MIN_MAX),
            new_len,
            file: None,
            dropped: 0,
        }
    }

    /// Whether nothing waits.
    pub fn is_empty(&self) -> bool {
        self.new_len == 0 && !self.dir.join(OLD).exists()
    }

    /// Appends `payload` of device `device`; a full store drops its older half first.
    pub fn push(&mut self, device: &str, payload: &Payload) -> Result<(), String> {
        let body = payload.encode_to_vec();
        let id = device.as_bytes();
        let len = 2 + id.len() + body.len();
        let mut record = Vec::with_capacity(4 + len);
        record.extend_from_slice(&(len as u32).to_le_bytes());
        record.extend_from_slice(&(id.len() as u16).to_le_bytes());
        record.extend_from_slice(id);
        record.extend_from_slice(&body);
        let fail = |e: std::io::Error| {
            format!(
                "cannot keep data in the store {} ({e}): it is lost while no birth is out",
                self.dir.display()
            )
        };
        if self.new_len + record.len() as u64 > self.max / 2 {
            self.file = None;
            let old = self.dir.join(OLD);
            let dropped = read_records(&old, self.max).map_or(0, |r| r.len() as u64);
            if dropped > 0 {
                self.dropped += dropped;
                log::warn!(target: "plc_sparkplug",
                    "the store is full ({} bytes): its {dropped} oldest records dropped \
                     ({} since start)", self.max, self.dropped);
            }
            if self.new_len > 0 {
                fs::rename(self.dir.join(NEW), &old).map_err(fail)?;
            }
            self.new_len = 0;
        }
        if self.file.is_none() {
            self.file = Some(open_append(&self.dir.join(NEW)).map_err(fail)?);
        }
        if let Some(f) = self.file.as_mut() {
            f.write_all(&record).map_err(fail)?;
        }
        self.new_len += record.len() as u64;
        Ok(())
    }

    /// Everything stored, oldest first, and the store emptied. Records that do not read
    /// (a file cut short by a crash) end what is read from their file.
    pub fn take(&mut self) -> Vec<(String, Payload)> {
        self.file = None;
        let mut out = Vec::new();
        for name in [OLD, NEW] {
            let path = self.dir.join(name);
            match read_records(&path, self.max) {
                Ok(records) => out.extend(records),
                Err(e) => log::warn!(target: "plc_sparkplug", "{}: {e}", path.display()),
            }
            let _ = fs::remove_file(&path);
        }
        self.new_len = 0;
        out
    }
}

/// The records of one file (none if it is missing), at most `max` bytes of them.
fn read_records(path: &Path, max: u64) -> Result<Vec<(String, Payload)>, String> {
    let file = match OpenOptions::new()
        .read(true)
        .custom_flags(libc::O_NOFOLLOW)
        .open(path)
    {
        Ok(f) => f,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(Vec::new()),
        Err(e) => return Err(format!("cannot be read ({e})")),
    };
    let mut bytes = Vec::new();
    file.take(max)
        .read_to_end(&mut bytes)
        .map_err(|e| format!("cannot be read ({e})"))?;
    let mut out = Vec::new();
    let mut rest = bytes.as_slice();
    while rest.len() >= 6 {
        let len = u32::from_le_bytes([rest[0], rest[1], rest[2], rest[3]]) as usize;
        let Some(record) = rest.get(4..4 + len) else {
            break;
        };
        let Some((id_len, tail)) = record.split_first_chunk::<2>() else {
            break;
        };
        let id_len = usize::from(u16::from_le_bytes(*id_len));
        let (Some(id), Some(body)) = (tail.get(..id_len), tail.get(id_len..)) else {
            break;
        };
        let (Ok(id), Ok(payload)) = (std::str::from_utf8(id), Payload::decode(body)) else {
            break;
        };
        out.push((id.to_string(), payload));
        rest = &rest[4 + len..];
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn payload(seq: u64) -> Payload {
        Payload {
            timestamp: Some(seq),
            ..Payload::default()
        }
    }

    #[test]
    fn records_come_back_in_order_once_and_a_full_store_drops_the_oldest() {
        let dir = std::env::temp_dir().join(format!("plc-sparkplug-fwd-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        let mut f = Forward::open(&dir, MIN_MAX);
        assert!(f.is_empty());
        for i in 0..10 {
            f.push("press", &payload(i)).unwrap();
        }
        assert!(!f.is_empty());
        // A restart finds them.
        let mut f = Forward::open(&dir, MIN_MAX);
        let got: Vec<u64> = f.take().iter().map(|(_, p)| p.timestamp.unwrap()).collect();
        assert_eq!(got, (0..10).collect::<Vec<_>>());
        assert!(f.is_empty() && f.take().is_empty());
        // Far more than the bound: the newest kept, in order, the oldest dropped and counted.
        for i in 0..20_000 {
            f.push("press", &payload(i)).unwrap();
        }
        let got: Vec<u64> = f.take().iter().map(|(_, p)| p.timestamp.unwrap()).collect();
        assert!(f.dropped > 0);
        assert_eq!(got.len() as u64 + f.dropped, 20_000);
        assert_eq!(got.last(), Some(&19_999));
        assert!(got.windows(2).all(|w| w[1] == w[0] + 1));
        let bytes: u64 = 20_000 * 16;
        assert!(bytes > MIN_MAX, "the test overfills the store");
        // A file cut short: what reads is kept.
        f.push("press", &payload(1)).unwrap();
        f.push("press", &payload(2)).unwrap();
        let path = dir.join(NEW);
        let len = fs::metadata(&path).unwrap().len();
        let file = OpenOptions::new().write(true).open(&path).unwrap();
        file.set_len(len - 3).unwrap();
        assert_eq!(f.take().len(), 1);
        fs::remove_dir_all(&dir).unwrap();
    }
}
