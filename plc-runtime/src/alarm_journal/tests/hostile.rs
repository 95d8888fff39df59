//! Files and directories someone else prepared: links, other owners, open modes, FIFOs,
//! files too large, temporary files left behind. Each refused naming the path, or cleaned.

use super::super::file::max_bytes;
use super::super::{AlarmJournal, JournalError, read_journal};
use super::private_dir;
use std::os::unix::fs::PermissionsExt;
use std::time::{Duration, Instant};

fn refusal(r: Result<AlarmJournal, JournalError>) -> String {
    match r {
        Ok(_) => panic!("opened"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn a_link_at_the_path_is_refused_and_its_target_untouched() {
    let dir = private_dir("hostile-link");
    let target = dir.join("target");
    std::fs::write(&target, b"precious").unwrap();
    let file = dir.join("j.alarms");
    std::os::unix::fs::symlink(&target, &file).unwrap();
    let e = refusal(AlarmJournal::open(&file, 100));
    assert!(e.contains("j.alarms") && e.contains("symbolic link"), "{e}");
    assert!(e.contains("rm "), "says what to do: {e}");
    assert!(
        read_journal(&file, 100)
            .unwrap_err()
            .to_string()
            .contains("symbolic link")
    );
    assert_eq!(std::fs::read(&target).unwrap(), b"precious");
    // A dangling link is not followed to create its target either.
    std::fs::remove_file(&target).unwrap();
    refusal(AlarmJournal::open(&file, 100));
    assert!(!target.exists());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_linked_or_open_directory_is_refused() {
    let dir = private_dir("hostile-dir");
    let real = dir.join("real");
    std::fs::create_dir(&real).unwrap();
    std::fs::set_permissions(&real, std::fs::Permissions::from_mode(0o700)).unwrap();
    let link = dir.join("link");
    std::os::unix::fs::symlink(&real, &link).unwrap();
    let e = refusal(AlarmJournal::open(link.join("j.alarms"), 100));
    assert!(e.contains("link") && e.contains("not a directory"), "{e}");
    std::fs::set_permissions(&real, std::fs::Permissions::from_mode(0o777)).unwrap();
    let e = refusal(AlarmJournal::open(real.join("j.alarms"), 100));
    assert!(e.contains("0777") && e.contains("chmod 700"), "{e}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_file_open_to_others_or_of_another_owner_is_refused() {
    let dir = private_dir("hostile-mode");
    let file = dir.join("j.alarms");
    std::fs::write(&file, super::file_of(3)).unwrap();
    std::fs::set_permissions(&file, std::fs::Permissions::from_mode(0o644)).unwrap();
    let e = refusal(AlarmJournal::open(&file, 100));
    assert!(e.contains("0644") && e.contains("chmod 600"), "{e}");
    std::fs::set_permissions(&file, std::fs::Permissions::from_mode(0o600)).unwrap();
    if plc_shm::euid() == 0 {
        // Only root can give a file away.
        std::os::unix::fs::chown(&file, Some(4242), None).unwrap();
        let e = refusal(AlarmJournal::open(&file, 100));
        assert!(e.contains("uid 4242"), "{e}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_fifo_is_refused_without_hanging() {
    let dir = private_dir("hostile-fifo");
    let file = dir.join("j.alarms");
    let c = std::ffi::CString::new(file.as_os_str().as_encoded_bytes()).unwrap();
    // SAFETY: a valid NUL-terminated path.
    assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o600) }, 0);
    let start = Instant::now();
    let e = read_journal(&file, 100).unwrap_err().to_string();
    assert!(e.contains("not a regular file"), "{e}");
    let e = refusal(AlarmJournal::open(&file, 100));
    assert!(e.contains("not a regular file"), "{e}");
    assert!(start.elapsed() < Duration::from_secs(5));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_file_larger_than_a_journal_can_be_is_refused_unread() {
    let dir = private_dir("hostile-large");
    let file = dir.join("j.alarms");
    let f = std::fs::File::create(&file).unwrap();
    f.set_len(max_bytes(10) + 1).unwrap();
    std::fs::set_permissions(&file, std::fs::Permissions::from_mode(0o600)).unwrap();
    let e = refusal(AlarmJournal::open(&file, 10));
    assert!(e.contains("j.alarms") && e.contains("move it away"), "{e}");
    assert_eq!(
        std::fs::metadata(&file).unwrap().len(),
        max_bytes(10) + 1,
        "left untouched"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_compactions_temporary_file_of_a_dead_process_is_removed_a_live_ones_kept() {
    let dir = private_dir("hostile-temp");
    let file = dir.join("j.alarms");
    // No process has pid 2^22 + 1 (above Linux's pid_max).
    let stale = plc_files::temp_path(&file, 4_194_305).unwrap();
    std::fs::write(&stale, b"half a compaction").unwrap();
    // A live process's (this one's) may be a compaction under way: left alone.
    let live = plc_files::temp_path(&file, std::process::id()).unwrap();
    std::fs::write(&live, b"compacting").unwrap();
    let journal = AlarmJournal::open(&file, 100).unwrap();
    assert!(!stale.exists());
    assert!(live.exists());
    drop(journal);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_new_journal_is_private() {
    let dir = private_dir("hostile-new");
    let file = dir.join("sub").join("j.alarms");
    drop(AlarmJournal::open(&file, 100).unwrap());
    let mode = |p: &std::path::Path| std::fs::metadata(p).unwrap().permissions().mode() & 0o777;
    assert_eq!(mode(&file), 0o600);
    assert_eq!(mode(file.parent().unwrap()), 0o700);
    std::fs::remove_dir_all(&dir).unwrap();
}
