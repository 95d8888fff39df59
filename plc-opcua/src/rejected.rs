//! The folder of refused client certificates, bounded. async-opcua writes every certificate it
//! does not trust into `pki/rejected/` (so that an operator can move a new HMI's certificate to
//! `trusted/`), one file per certificate, with no bound: a client that sends a new
//! self-signed certificate with every session could fill the disk. Every few seconds the
//! newest are kept and the rest removed.

use std::path::{Path, PathBuf};
use std::time::{Duration, SystemTime};

/// How often the folder is looked at.
const EVERY: Duration = Duration::from_secs(2);
/// Entries looked at in one sweep, at most (a folder flooded between two sweeps is swept over
/// several).
const MAX_LOOKED_AT: usize = 100_000;

/// Keeps the newest `keep` certificates of `folder`, for as long as the server runs.
pub async fn keep_newest(folder: PathBuf, keep: usize) {
    loop {
        let f = folder.clone();
        let _ = tokio::task::spawn_blocking(move || sweep(&f, keep)).await;
        tokio::time::sleep(EVERY).await;
    }
}

/// Removes all but the newest `keep` certificate files (`.der`) of `folder`; how many it
/// removed. Links and anything that is not a regular file are left alone, never followed.
pub fn sweep(folder: &Path, keep: usize) -> usize {
    let Ok(entries) = std::fs::read_dir(folder) else {
        return 0;
    };
    let mut files: Vec<(SystemTime, PathBuf)> = entries
        .take(MAX_LOOKED_AT)
        .flatten()
        .filter_map(|e| {
            let path = e.path();
            let meta = std::fs::symlink_metadata(&path).ok()?;
            let der = path.extension().is_some_and(|x| x == "der");
            (meta.is_file() && der)
                .then(|| (meta.modified().unwrap_or(SystemTime::UNIX_EPOCH), path))
        })
        .collect();
    if files.len() <= keep {
        return 0;
    }
    files.sort_by_key(|f| std::cmp::Reverse(f.0));
    let mut removed = 0;
    for (_, path) in files.into_iter().skip(keep) {
        if std::fs::remove_file(&path).is_ok() {
            removed += 1;
        }
    }
    if removed > 0 {
        log::warn!(
            "OPC UA: {removed} refused client certificates removed from {} (the newest {keep} \
             are kept)",
            folder.display()
        );
    }
    removed
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_newest_certificates_are_kept_and_other_files_left_alone() {
        let dir = std::env::temp_dir().join(format!("plc-opcua-rejected-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let t0 = SystemTime::now() - Duration::from_secs(100);
        for n in 0..10u64 {
            let path = dir.join(format!("client{n}.der"));
            std::fs::write(&path, b"cert").unwrap();
            let file = std::fs::File::options().write(true).open(&path).unwrap();
            file.set_modified(t0 + Duration::from_secs(n)).unwrap();
        }
        std::fs::write(dir.join("notes.txt"), b"kept").unwrap();
        std::os::unix::fs::symlink("/etc/hostname", dir.join("link.der")).unwrap();
        assert_eq!(sweep(&dir, 3), 7);
        let mut left: Vec<String> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        left.sort();
        assert_eq!(
            left,
            [
                "client7.der",
                "client8.der",
                "client9.der",
                "link.der",
                "notes.txt"
            ]
        );
        assert_eq!(sweep(&dir, 3), 0);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
