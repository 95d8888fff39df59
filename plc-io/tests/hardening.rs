//! What another process can do to a program's shared files and its socket, tried as an
//! attacker or a buggy tool would: plant symbolic links, leave files, open directories to
//! others, write or resize the segment it received, flood the socket with malformed and
//! valid-looking messages, write as another user. The program neither crashes, stalls, nor
//! writes where it should not. Misbehaving writers and a hostile process on the socket:
//! `hostile_tools.rs`.

mod common;

use common::{
    Cleanup, Scratch, alone, is_root, kill9, lock, role, socket, spawn_role, unique, wait_for,
};
use plc_core::{GlobalMemory, Value};
use plc_io::shm::{DynSegment, SharedGlobalMemory, Sharing, ShmError, list_segments};
use std::os::fd::AsRawFd;
use std::os::unix::fs::PermissionsExt;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

#[derive(GlobalMemory, Debug, Clone)]
pub struct Plain {
    count: u64,
    #[plc(direction = "command")]
    setpoint: u32,
    #[plc(direction = "output")]
    valve: bool,
}

fn runtime_dir_ready() {
    let _ = SharedGlobalMemory::<Plain>::create(&unique("dirready"));
}

#[test]
fn a_symlink_at_the_lock_or_socket_path_is_refused_and_its_target_untouched() {
    let _alone = alone();
    runtime_dir_ready();
    let dir = Scratch::new("link");
    let victim = dir.path("victim");
    std::fs::write(&victim, b"precious").unwrap();
    let paths: [fn(&str) -> PathBuf; 2] = [lock, socket];
    for (i, path_of) in paths.into_iter().enumerate() {
        let name = unique(&format!("link{i}"));
        let _c = Cleanup(name.clone());
        std::os::unix::fs::symlink(&victim, path_of(&name)).unwrap();
        let err = SharedGlobalMemory::<Plain>::create(&name)
            .err()
            .expect("refused");
        let text = err.to_string();
        assert!(matches!(err, ShmError::Unsafe { .. }), "{err:?}");
        assert!(
            text.contains("symbolic link") && text.contains(&path_of(&name).display().to_string()),
            "{text}"
        );
        assert_eq!(std::fs::read(&victim).unwrap(), b"precious");
    }
}

#[test]
fn a_lock_file_open_to_others_or_of_another_user_is_refused_with_the_fix() {
    let _alone = alone();
    runtime_dir_ready();
    let name = unique("lockmode");
    let _c = Cleanup(name.clone());
    std::fs::write(lock(&name), b"").unwrap();
    std::fs::set_permissions(lock(&name), std::fs::Permissions::from_mode(0o644)).unwrap();
    let err = SharedGlobalMemory::<Plain>::create(&name)
        .err()
        .expect("refused");
    assert!(
        err.to_string().contains("mode 0644") && err.to_string().contains("chmod 600"),
        "{err}"
    );
    if is_root() {
        std::fs::set_permissions(lock(&name), std::fs::Permissions::from_mode(0o600)).unwrap();
        std::os::unix::fs::chown(lock(&name), Some(65534), None).unwrap();
        let err = SharedGlobalMemory::<Plain>::create(&name)
            .err()
            .expect("refused");
        assert!(err.to_string().contains("belongs to uid 65534"), "{err}");
    }
}

/// Points this process's runtime directory at `dir`.
///
/// Only in a child process of one test (`--test-threads=1`), before it starts any thread of
/// its own: nothing else reads the environment meanwhile.
fn use_runtime_dir(dir: &Path) {
    // SAFETY: see above: no other thread of this process reads the environment now.
    unsafe { std::env::set_var(plc_io::shm::RUNTIME_DIR_ENV, dir) };
}

#[test]
fn a_runtime_directory_that_is_a_link_open_to_others_or_another_users_is_refused_with_the_fix() {
    let _alone = alone();
    if role().as_deref() == Some("dir_cases") {
        let base = PathBuf::from(std::env::var("BASE").unwrap());
        let victim = base.join("victim");
        std::fs::create_dir(&victim).unwrap();
        let refused = |dir: &Path, expect: &[&str]| {
            use_runtime_dir(dir);
            let err = SharedGlobalMemory::<Plain>::create("dircase")
                .err()
                .expect("refused");
            let text = err.to_string();
            assert!(matches!(err, ShmError::Unsafe { .. }), "{err:?}");
            assert!(text.contains(&dir.display().to_string()), "{text}");
            for e in expect {
                assert!(text.contains(e), "{text} lacks {e}");
            }
        };
        // A planted link to a directory.
        let link = base.join("link");
        std::os::unix::fs::symlink(&victim, &link).unwrap();
        refused(&link, &["symbolic link", "rm "]);
        // World-writable, and readable by others.
        let open = base.join("open");
        std::fs::create_dir(&open).unwrap();
        std::fs::set_permissions(&open, std::fs::Permissions::from_mode(0o777)).unwrap();
        refused(&open, &["mode 0777", "chmod 700"]);
        std::fs::set_permissions(&open, std::fs::Permissions::from_mode(0o755)).unwrap();
        refused(&open, &["mode 0755", "chmod 700"]);
        // Another user's.
        if is_root() {
            let foreign = base.join("foreign");
            std::fs::create_dir(&foreign).unwrap();
            std::fs::set_permissions(&foreign, std::fs::Permissions::from_mode(0o700)).unwrap();
            std::os::unix::fs::chown(&foreign, Some(65534), None).unwrap();
            refused(&foreign, &["belongs to uid 65534", "PLC_VARS_RUNTIME_DIR"]);
        }
        // Nothing was created through the link, and a private directory is made and used.
        assert_eq!(std::fs::read_dir(&victim).unwrap().count(), 0);
        let fresh = base.join("fresh");
        use_runtime_dir(&fresh);
        let owner = SharedGlobalMemory::<Plain>::create("dircase").unwrap();
        let mode = std::fs::metadata(&fresh).unwrap().permissions().mode() & 0o777;
        assert_eq!(mode, 0o700);
        let sock = std::fs::metadata(fresh.join("dircase.sock")).unwrap();
        assert_eq!(sock.permissions().mode() & 0o777, 0o600);
        assert!(DynSegment::attach("dircase").is_ok());
        drop(owner);
        assert_eq!(
            std::fs::read_dir(&fresh).unwrap().count(),
            0,
            "a clean stop leaves no file"
        );
        return;
    }
    if role().is_some() {
        return;
    }
    let base = Scratch::new("dirs");
    let mut child = spawn_role(
        "a_runtime_directory_that_is_a_link_open_to_others_or_another_users_is_refused_with_the_fix",
        "dir_cases",
        &[("BASE", base.0.display().to_string())],
    );
    assert!(child.wait().unwrap().success());
}

#[test]
fn a_tool_receives_a_segment_it_cannot_write_resize_or_map_writable() {
    let _alone = alone();
    let name = unique("sealed");
    let owner = SharedGlobalMemory::<Plain>::create(&name).unwrap();
    owner
        .publish(&Plain {
            count: 5,
            ..Default::default()
        })
        .unwrap();
    let seg = DynSegment::attach(&name).unwrap();
    let fd = seg.segment_fd().as_raw_fd();
    let errno = || std::io::Error::last_os_error().raw_os_error();
    // SAFETY: each call below only asks the kernel to change a descriptor or mapping this test
    // holds; each is expected to fail, and a mapping that succeeds is unmapped at once.
    unsafe {
        let len = 4096;
        let p = libc::mmap(
            std::ptr::null_mut(),
            len,
            libc::PROT_READ | libc::PROT_WRITE,
            libc::MAP_SHARED,
            fd,
            0,
        );
        let mapped = p != libc::MAP_FAILED;
        if mapped {
            libc::munmap(p, len);
        }
        assert!(
            !mapped && errno() == Some(libc::EPERM),
            "a writable shared mapping"
        );
        assert_eq!(libc::ftruncate(fd, 0), -1, "shrunk");
        assert_eq!(libc::ftruncate(fd, 1 << 30), -1, "grown");
        assert_eq!(
            libc::pwrite(fd, b"x".as_ptr() as *const _, 1, 0),
            -1,
            "written"
        );
        assert_eq!(
            libc::fallocate(
                fd,
                libc::FALLOC_FL_PUNCH_HOLE | libc::FALLOC_FL_KEEP_SIZE,
                0,
                4096
            ),
            -1,
            "a hole punched"
        );
        assert_eq!(
            libc::fcntl(fd, libc::F_ADD_SEALS, libc::F_SEAL_WRITE),
            -1,
            "sealed again"
        );
        // A read-only mapping cannot be made writable either.
        let r = libc::mmap(
            std::ptr::null_mut(),
            len,
            libc::PROT_READ,
            libc::MAP_SHARED,
            fd,
            0,
        );
        assert_ne!(r, libc::MAP_FAILED);
        assert_eq!(
            libc::mprotect(r, len, libc::PROT_READ | libc::PROT_WRITE),
            -1
        );
        libc::munmap(r, len);
    }
    assert_eq!(
        seg.read("count"),
        Ok(Value::UInt(5)),
        "the values are intact"
    );
}

#[test]
fn a_clean_stop_leaves_no_file_and_a_killed_owners_files_are_removed_by_the_next_owner() {
    let _alone = alone();
    if role().as_deref() == Some("killed_owner") {
        let name = std::env::var("SEGMENT").unwrap();
        let owner = SharedGlobalMemory::<Plain>::create(&name).unwrap();
        loop {
            owner.publish(&Plain::default()).unwrap();
            std::thread::sleep(Duration::from_millis(2));
        }
    }
    if role().is_some() {
        return;
    }
    let clean = unique("cleanstop");
    drop(SharedGlobalMemory::<Plain>::create(&clean).unwrap());
    assert!(!socket(&clean).exists(), "socket removed");
    assert!(!lock(&clean).exists(), "lock file removed");

    let killed = unique("killedleft");
    let _c = Cleanup(killed.clone());
    let mut child = spawn_role(
        "a_clean_stop_leaves_no_file_and_a_killed_owners_files_are_removed_by_the_next_owner",
        "killed_owner",
        &[("SEGMENT", killed.clone())],
    );
    let tool = wait_for(Duration::from_secs(20), || DynSegment::attach(&killed).ok());
    let other = unique("sweeper");
    let alive = SharedGlobalMemory::<Plain>::create(&other).unwrap();
    assert!(
        socket(&killed).exists() && lock(&killed).exists(),
        "a live owner's files are left alone"
    );
    drop(alive);
    kill9(&mut child);
    assert!(socket(&killed).exists(), "a kill leaves the files");
    assert_eq!(tool.read("count"), Err(ShmError::OwnerGone(killed.clone())));
    assert!(
        list_segments()
            .iter()
            .any(|s| s.name == killed && s.problem.is_some()),
        "a dead owner's leftover is listed as such until removed"
    );
    let _next = SharedGlobalMemory::<Plain>::create(&other).unwrap();
    assert!(
        !socket(&killed).exists() && !lock(&killed).exists(),
        "the next owner of any name removed them"
    );
}

#[test]
fn a_new_owner_after_a_clean_stop_has_a_later_generation() {
    let _alone = alone();
    let name = unique("generation");
    let first = SharedGlobalMemory::<Plain>::create(&name)
        .unwrap()
        .generation();
    let second = SharedGlobalMemory::<Plain>::create(&name)
        .unwrap()
        .generation();
    assert!(second > first, "{first} then {second}");
}

/// Owner and tools in the same private runtime directory, the owner sharing with group
/// `nogroup` (gid 65534) as `SHARING` says: `read` (read only) or `write` (read and write).
#[test]
fn another_uid_is_refused_naming_the_rule_and_a_write_group_member_writes() {
    let _alone = alone();
    let test = "another_uid_is_refused_naming_the_rule_and_a_write_group_member_writes";
    match role().as_deref() {
        Some("shared_owner") => {
            use_runtime_dir(Path::new(&std::env::var("DIR").unwrap()));
            let sharing = match std::env::var("SHARING").unwrap().as_str() {
                "read" => Sharing::new().read_group("nogroup"),
                _ => Sharing::new().read_group("nogroup").write_group("nogroup"),
            };
            let mut owner = SharedGlobalMemory::<Plain>::create_with("shared", &sharing).unwrap();
            let mut gm = Plain::default();
            let start = Instant::now();
            while !gm.valve && start.elapsed() < Duration::from_secs(30) {
                owner.apply_requests(&mut gm);
                gm.count += 1;
                gm.valve = gm.setpoint == 99;
                owner.publish(&gm).unwrap();
                std::thread::sleep(Duration::from_millis(1));
            }
            return;
        }
        Some("stranger") => {
            use_runtime_dir(Path::new(&std::env::var("DIR").unwrap()));
            // SAFETY: dropping privileges in this child process only, before any thread.
            unsafe {
                assert_eq!(libc::setgroups(0, std::ptr::null()), 0);
                assert_eq!(libc::setgid(65534), 0);
                assert_eq!(libc::setuid(65534), 0);
            }
            let seg = wait_for(Duration::from_secs(20), || {
                DynSegment::attach("shared").ok()
            });
            assert!(
                matches!(seg.read("count"), Ok(Value::UInt(_))),
                "the read group reads"
            );
            let written = seg.write("setpoint", Value::UInt(99));
            if std::env::var("SHARING").unwrap() == "read" {
                let err = written.expect_err("refused");
                let text = err.to_string();
                assert!(matches!(err, ShmError::WriteRefused { .. }), "{err:?}");
                assert!(
                    text.contains("uid 65534")
                        && text.contains("may not write `shared`")
                        && text.contains("only uid 0 may")
                        && text.contains("RuntimeBuilder::write_group"),
                    "{text}"
                );
                assert!(!seg.may_write());
                assert!(seg.status().writes_refused >= 1);
            } else {
                written.expect("a member of the write group writes");
                assert!(seg.may_write());
            }
            std::process::exit(0);
        }
        Some(_) => return,
        None => {}
    }
    if !is_root() {
        eprintln!("skipped: switching to another uid needs root");
        return;
    }
    for sharing in ["read", "write"] {
        let base = Scratch::new(&format!("policy-{sharing}"));
        // World-traversable parent, as /run is: the directory itself is the owner's.
        std::fs::set_permissions(&base.0, std::fs::Permissions::from_mode(0o755)).unwrap();
        let dir = base.path("rt").display().to_string();
        let env = [("DIR", dir.clone()), ("SHARING", sharing.to_string())];
        let mut owner = spawn_role(test, "shared_owner", &env);
        let mut stranger = spawn_role(test, "stranger", &env);
        assert!(stranger.wait().unwrap().success(), "{sharing}");
        let meta = std::fs::metadata(&dir).unwrap();
        assert_eq!(meta.permissions().mode() & 0o777, 0o750);
        assert_eq!(std::os::unix::fs::MetadataExt::gid(&meta), 65534);
        kill9(&mut owner);
    }
}

#[test]
fn a_tool_outside_the_read_group_is_told_permission_is_denied() {
    let _alone = alone();
    if role().as_deref() == Some("outsider") {
        let name = std::env::var("SEGMENT").unwrap();
        // SAFETY: dropping privileges in this child process only.
        unsafe {
            assert_eq!(libc::setgroups(0, std::ptr::null()), 0);
            assert_eq!(libc::setgid(65534), 0);
            assert_eq!(libc::setuid(65534), 0);
        }
        let err = DynSegment::attach(&name).err().expect("refused");
        assert!(
            matches!(err, ShmError::PermissionDenied { .. })
                && err.to_string().contains("read group"),
            "{err:?}"
        );
        std::process::exit(0);
    }
    if role().is_some() || !is_root() {
        return;
    }
    let name = unique("outsider");
    let _owner = SharedGlobalMemory::<Plain>::create(&name).unwrap();
    let mut child = spawn_role(
        "a_tool_outside_the_read_group_is_told_permission_is_denied",
        "outsider",
        &[
            ("SEGMENT", name.clone()),
            (
                plc_io::shm::RUNTIME_DIR_ENV,
                plc_io::shm::runtime_dir().display().to_string(),
            ),
        ],
    );
    assert!(child.wait().unwrap().success());
}
