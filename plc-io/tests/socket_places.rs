//! The owner's socket under a crowd: readers of other uids cannot take the places kept for
//! tools that may write, and a connection that never takes its greeting (and so holds no
//! segment) is closed instead of keeping its place.

mod common;

use common::{role, spawn_role, wait_for};
use plc_core::{GlobalMemory, Value};
use plc_io::shm::{DynSegment, SharedGlobalMemory, Sharing};
use std::os::fd::{AsRawFd, FromRawFd, OwnedFd};
use std::os::unix::fs::PermissionsExt;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

#[derive(GlobalMemory, Debug, Clone)]
pub struct Plain {
    count: u64,
    #[plc(direction = "command")]
    setpoint: u32,
}

fn is_root() -> bool {
    // SAFETY: geteuid has no preconditions.
    unsafe { libc::geteuid() == 0 }
}

/// A scratch directory that others may traverse, as /run is.
fn scratch(what: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("plc-places-{what}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir(&dir).unwrap();
    std::fs::set_permissions(&dir, std::fs::Permissions::from_mode(0o755)).unwrap();
    dir
}

/// Runs an owner of segment `crowded` shared with group nogroup, until `setpoint` is 7.
fn owner_role() {
    let mut owner =
        SharedGlobalMemory::<Plain>::create_with("crowded", &Sharing::new().read_group("nogroup"))
            .unwrap();
    let mut gm = Plain::default();
    let start = Instant::now();
    while gm.setpoint != 7 && start.elapsed() < Duration::from_secs(60) {
        owner.apply_requests(&mut gm);
        gm.count += 1;
        owner.publish(&gm).unwrap();
        std::thread::sleep(Duration::from_millis(1));
    }
}

/// As uid `uid` of group nogroup: holds as many connections as the owner lets it have for a
/// while, and reports how many and why the next was refused.
fn crowd_role(uid: u32) {
    // SAFETY: dropping privileges in this child process only, before any thread.
    unsafe {
        assert_eq!(libc::setgroups(0, std::ptr::null()), 0);
        assert_eq!(libc::setgid(65534), 0);
        assert_eq!(libc::setuid(uid), 0);
    }
    let mut held = Vec::new();
    let why = loop {
        match DynSegment::attach("crowded") {
            Ok(seg) if held.len() < 100 => held.push(seg),
            Ok(_) => break "never refused".to_string(),
            Err(e) => break e.to_string(),
        }
    };
    let out = std::env::var("OUT").unwrap();
    std::fs::write(out, format!("{}\n{why}", held.len())).unwrap();
    // Hold them until the test ends us.
    std::thread::sleep(Duration::from_secs(60));
}

#[test]
fn readers_of_other_uids_cannot_take_the_places_kept_for_writers() {
    const TEST: &str = "readers_of_other_uids_cannot_take_the_places_kept_for_writers";
    match role().as_deref() {
        Some("owner") => return owner_role(),
        Some("crowd") => return crowd_role(std::env::var("UID").unwrap().parse().unwrap()),
        Some(_) => return,
        None if !is_root() => {
            eprintln!("skipped: switching to other uids needs root");
            return;
        }
        None => {}
    }
    let base = scratch("crowd");
    let dir = base.join("rt").display().to_string();
    let env = |extra: &[(&'static str, String)]| -> Vec<(&'static str, String)> {
        let mut e = vec![(plc_io::shm::RUNTIME_DIR_ENV, dir.clone())];
        e.extend(extra.iter().cloned());
        e
    };
    let mut owner = spawn_role(TEST, "owner", &env(&[]));
    // SAFETY: setting this test process's environment before it starts any thread of its own
    // that reads it.
    unsafe { std::env::set_var(plc_io::shm::RUNTIME_DIR_ENV, &dir) };
    let mine = wait_for(Duration::from_secs(20), || {
        DynSegment::attach("crowded").ok()
    });
    // Two reader uids, each allowed 32: together they reach the readers' limit of 56.
    let mut crowds = Vec::new();
    // Where the crowd, of other uids, reports.
    let reports = base.join("reports");
    std::fs::create_dir(&reports).unwrap();
    std::fs::set_permissions(&reports, std::fs::Permissions::from_mode(0o1777)).unwrap();
    for (uid, n) in [(65534u32, 0), (65533, 1)] {
        let out = reports.join(format!("crowd{n}"));
        let child = spawn_role(
            TEST,
            "crowd",
            &env(&[("UID", uid.to_string()), ("OUT", out.display().to_string())]),
        );
        let report = wait_for(Duration::from_secs(30), || {
            std::fs::read_to_string(&out)
                .ok()
                .filter(|t| t.contains('\n'))
        });
        crowds.push((child, report));
    }
    let held: usize = crowds
        .iter()
        .map(|(_, r)| r.lines().next().unwrap().parse::<usize>().unwrap())
        .sum();
    // This test's own connection counts among the 64, not among the readers' 56.
    assert_eq!(
        held,
        56 - 1,
        "{crowds:?}",
        crowds = crowds.iter().map(|c| &c.1).collect::<Vec<_>>()
    );
    let second = &crowds[1].1;
    assert!(
        second.contains("places for tools that may write"),
        "{second}"
    );
    // The owner's uid still connects and writes.
    let writer = DynSegment::attach("crowded").expect("a place kept for a writer");
    writer.write("setpoint", Value::UInt(7)).unwrap();
    drop((mine, writer));
    let _ = owner.wait();
    for (mut c, _) in crowds {
        let _ = c.kill();
        let _ = c.wait();
    }
    let _ = std::fs::remove_dir_all(&base);
}

#[test]
fn a_connection_that_never_takes_the_segment_is_closed() {
    const TEST: &str = "a_connection_that_never_takes_the_segment_is_closed";
    if role().as_deref() == Some("owner") {
        return owner_role();
    }
    if role().is_some() {
        return;
    }
    let base = scratch("idle");
    let dir = base.join("rt");
    let mut owner = spawn_role(
        TEST,
        "owner",
        &[(plc_io::shm::RUNTIME_DIR_ENV, dir.display().to_string())],
    );
    let socket = dir.join("crowded.sock");
    // A raw connection that reads nothing: its greeting and the segment stay in the socket.
    // The socket's file appears when it is bound, a moment before the owner listens on it
    // (a connection then is refused): retried until it is accepted.
    let fd = wait_for(Duration::from_secs(20), || raw_connect(&socket));
    let start = Instant::now();
    let closed = wait_for(Duration::from_secs(15), || {
        let mut p = libc::pollfd {
            fd: fd.as_raw_fd(),
            events: libc::POLLRDHUP,
            revents: 0,
        };
        // SAFETY: one valid pollfd, no waiting.
        let n = unsafe { libc::poll(&mut p, 1, 0) };
        (n > 0 && p.revents & (libc::POLLHUP | libc::POLLRDHUP) != 0).then(|| start.elapsed())
    });
    assert!(
        closed >= Duration::from_secs(4),
        "closed after {closed:?}: too soon"
    );
    // A tool that takes its greeting stays connected past the grace.
    // SAFETY: as above, for this test process's own environment.
    unsafe { std::env::set_var(plc_io::shm::RUNTIME_DIR_ENV, &dir) };
    let seg = DynSegment::attach("crowded").unwrap();
    std::thread::sleep(plc_io::shm::GREETING_GRACE + Duration::from_secs(1));
    seg.write("setpoint", Value::UInt(7)).unwrap();
    let _ = owner.wait();
    let _ = std::fs::remove_dir_all(&base);
}

/// A raw SOCK_SEQPACKET connection to `socket`, or `None` while it cannot be made.
fn raw_connect(socket: &Path) -> Option<OwnedFd> {
    // SAFETY: a plain socket call; the descriptor is ours.
    let fd = unsafe { libc::socket(libc::AF_UNIX, libc::SOCK_SEQPACKET | libc::SOCK_CLOEXEC, 0) };
    assert!(fd >= 0);
    // SAFETY: a fresh descriptor nobody else owns.
    let fd = unsafe { OwnedFd::from_raw_fd(fd) };
    // SAFETY: sockaddr_un is plain data.
    let mut addr: libc::sockaddr_un = unsafe { std::mem::zeroed() };
    addr.sun_family = libc::AF_UNIX as libc::sa_family_t;
    for (d, s) in addr
        .sun_path
        .iter_mut()
        .zip(socket.as_os_str().as_encoded_bytes())
    {
        *d = *s as libc::c_char;
    }
    // SAFETY: a valid address of the size given.
    let r = unsafe {
        libc::connect(
            fd.as_raw_fd(),
            &addr as *const libc::sockaddr_un as *const libc::sockaddr,
            std::mem::size_of::<libc::sockaddr_un>() as libc::socklen_t,
        )
    };
    (r == 0).then_some(fd)
}
