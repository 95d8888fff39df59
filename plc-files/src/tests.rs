use super::{Step, temp_path, write_atomically, write_atomically_with};
use std::os::unix::fs::PermissionsExt;
use std::path::PathBuf;

/// A directory of its own for each test, removed at the end.
struct Scratch(PathBuf);

impl Scratch {
    fn new(name: &str) -> Scratch {
        let dir = std::env::temp_dir().join(format!("plc-files-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        Scratch(dir)
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

#[test]
fn a_file_is_replaced_whole_with_its_mode_and_no_temporary_file_left() {
    let dir = Scratch::new("replace");
    let file = dir.0.join("users");
    std::fs::write(&file, b"old").unwrap();
    write_atomically(&file, b"new", 0o600).unwrap();
    assert_eq!(std::fs::read(&file).unwrap(), b"new");
    let mode = std::fs::metadata(&file).unwrap().permissions().mode() & 0o777;
    assert_eq!(mode, 0o600);
    let names: Vec<_> = std::fs::read_dir(&dir.0)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names, ["users"]);
}

#[test]
fn a_link_planted_at_the_temporary_name_is_removed_not_written_through() {
    let dir = Scratch::new("planted");
    let victim = dir.0.join("victim");
    std::fs::write(&victim, b"precious").unwrap();
    let file = dir.0.join("project.rs");
    let tmp = temp_path(&file, std::process::id()).unwrap();
    std::os::unix::fs::symlink(&victim, &tmp).unwrap();
    write_atomically(&file, b"generated", 0o644).unwrap();
    assert_eq!(std::fs::read(&victim).unwrap(), b"precious");
    assert_eq!(std::fs::read(&file).unwrap(), b"generated");
    assert!(std::fs::symlink_metadata(&tmp).is_err());
}

#[test]
fn a_failed_write_keeps_the_old_file_and_removes_the_temporary_one() {
    let dir = Scratch::new("failed");
    let file = dir.0.join("gm.retain");
    std::fs::write(&file, b"last good").unwrap();
    let err = write_atomically_with(
        &file,
        0o600,
        |f| {
            use std::io::Write;
            f.write_all(b"half")?;
            Err(std::io::Error::other("disk full"))
        },
        |_| {},
    )
    .unwrap_err();
    assert_eq!(err.to_string(), "disk full");
    assert_eq!(std::fs::read(&file).unwrap(), b"last good");
    assert!(!temp_path(&file, std::process::id()).unwrap().exists());
}

#[test]
fn every_step_is_reported_in_order() {
    let dir = Scratch::new("steps");
    let mut steps = Vec::new();
    write_atomically_with(&dir.0.join("f"), 0o644, |_| Ok(()), |s| steps.push(s)).unwrap();
    use Step::*;
    assert_eq!(steps, [Created, Written, Synced, Renamed, DirSynced]);
}

#[test]
fn a_path_naming_no_file_is_refused_naming_it() {
    let err = write_atomically("/".as_ref(), b"x", 0o644).unwrap_err();
    assert_eq!(err.kind(), std::io::ErrorKind::InvalidInput);
    assert_eq!(err.to_string(), "/ names no file to write");
}

#[test]
fn temporary_names_are_hidden_and_apart_for_each_file() {
    let a = temp_path("dir/gm.retain".as_ref(), 7).unwrap();
    let b = temp_path("dir/gm.json".as_ref(), 7).unwrap();
    assert_eq!(a, PathBuf::from("dir/.gm.retain.tmp.7"));
    assert_ne!(a, b);
    assert_eq!(
        temp_path("bus".as_ref(), 1).unwrap(),
        PathBuf::from("./.bus.tmp.1")
    );
}
