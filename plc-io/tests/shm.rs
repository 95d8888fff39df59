//! Shared memory between real processes: no torn snapshots, every write applied once and in
//! order, owner crashes, writer crashes, and damaged segments. Writes refused or applied and
//! names found: `shm_writes.rs`.

mod common;

use common::{kill9, role, runtime_file, spawn_role, unique, wait_for, with_cycles};
use plc_core::{GlobalMemory, Value};
use plc_io::shm::{DynSegment, OwnerState, SharedGlobalMemory, ShmError};
use std::time::Duration;

/// Every word of `data` equals `seq` in a consistent image (520 bytes over nine cache lines,
/// which the string moves of both sides copy a line at a time; a larger image made this debug
/// test take 90 s in CI).
#[derive(GlobalMemory, Debug, Clone)]
pub struct Pattern {
    seq: u64,
    data: [u64; 64],
    #[plc(direction = "command")]
    stop: bool,
}

#[test]
fn a_reader_never_sees_a_torn_image_in_a_million_snapshots() {
    if role().as_deref() == Some("pattern_writer") {
        let name = std::env::var("SEGMENT").unwrap();
        let mut owner = SharedGlobalMemory::<Pattern>::create(&name).unwrap();
        let mut gm = Pattern::default();
        while !gm.stop {
            gm.seq += 1;
            gm.data = [gm.seq; 64];
            owner.publish(&gm).unwrap();
            owner.apply_requests(&mut gm);
        }
        return;
    }
    if role().is_some() {
        return;
    }
    let name = unique("torn");
    let mut child = spawn_role(
        "a_reader_never_sees_a_torn_image_in_a_million_snapshots",
        "pattern_writer",
        &[("SEGMENT", name.clone())],
    );
    let reader = wait_for(Duration::from_secs(10), || {
        SharedGlobalMemory::<Pattern>::attach(&name).ok()
    });
    let (mut torn, mut distinct, mut last, mut snapshots) = (0u64, 0u64, 0u64, 0u64);
    // A million snapshots, and on to 1000 distinct images: on a loaded machine the writer may
    // get little CPU while the reader runs (a back-to-back writer starves seqlock readers in
    // between, so images are mostly seen when it is preempted).
    let start = std::time::Instant::now();
    while snapshots < 1_000_000 || (distinct < 1000 && start.elapsed() < Duration::from_secs(30)) {
        snapshots += 1;
        let p = reader.snapshot().unwrap();
        if p.data.iter().any(|&w| w != p.seq) {
            torn += 1;
        }
        if p.seq != last {
            distinct += 1;
            last = p.seq;
        }
    }
    reader.write("stop", Value::Bool(true)).unwrap();
    let _ = child.wait();
    assert_eq!(torn, 0, "torn snapshots");
    assert!(
        distinct > 100,
        "the writer was publishing concurrently ({distinct} images seen)"
    );
}

#[derive(GlobalMemory, Debug, Clone)]
pub struct Counters {
    #[plc(direction = "command")]
    w0: u32,
    #[plc(direction = "command")]
    w1: u32,
    #[plc(direction = "command")]
    w2: u32,
    #[plc(direction = "command")]
    w3: u32,
}

const WRITES: u32 = 10_000;

#[test]
fn four_processes_times_ten_thousand_writes_arrive_once_and_in_order() {
    if role().as_deref() == Some("writer") {
        let name = std::env::var("SEGMENT").unwrap();
        let var = std::env::var("VAR").unwrap();
        let seg = DynSegment::attach(&name).unwrap();
        for v in 1..=WRITES {
            loop {
                match seg.write(&var, Value::UInt(v as u64)) {
                    Ok(()) => break,
                    Err(ShmError::QueueFull(_)) => std::thread::sleep(Duration::from_micros(50)),
                    Err(e) => panic!("{e}"),
                }
            }
        }
        return;
    }
    if role().is_some() {
        return;
    }
    let name = unique("mailbox");
    let mut owner = SharedGlobalMemory::<Counters>::create(&name).unwrap();
    let mut gm = Counters::default();
    let mut children: Vec<_> = (0..4)
        .map(|i| {
            spawn_role(
                "four_processes_times_ten_thousand_writes_arrive_once_and_in_order",
                "writer",
                &[("SEGMENT", name.clone()), ("VAR", format!("w{i}"))],
            )
        })
        .collect();
    let mut next = [1u64; 4];
    let mut problems = Vec::new();
    let start = std::time::Instant::now();
    while next.iter().any(|&n| n <= WRITES as u64) {
        assert!(
            start.elapsed() < Duration::from_secs(60),
            "writes stopped arriving: {next:?}"
        );
        owner.apply_requests_with(&mut gm, |r, result| {
            assert!(result.is_ok());
            let Value::UInt(v) = r.value else {
                panic!("kind")
            };
            if v != next[r.index] {
                problems.push((r.index, v, next[r.index]));
            }
            next[r.index] = v + 1;
        });
        // As a program's cycle does: its writers hear "applied" once the image holds it.
        owner.publish(&gm).unwrap();
        std::thread::sleep(Duration::from_micros(200));
    }
    for c in &mut children {
        assert!(c.wait().unwrap().success());
    }
    assert!(
        problems.is_empty(),
        "lost, duplicated or reordered: {:?}",
        &problems[..problems.len().min(5)]
    );
    assert_eq!(
        (gm.w0, gm.w1, gm.w2, gm.w3),
        (WRITES, WRITES, WRITES, WRITES)
    );
    assert_eq!(owner.status().writes_applied, 4 * WRITES as u64);
}

#[test]
fn a_killed_owner_is_reported_gone_and_a_new_owner_takes_over() {
    if role().as_deref() == Some("owner") {
        let name = std::env::var("SEGMENT").unwrap();
        let owner = SharedGlobalMemory::<Pattern>::create(&name).unwrap();
        let mut gm = Pattern::default();
        loop {
            gm.seq += 1;
            owner.publish(&gm).unwrap();
            std::thread::sleep(Duration::from_millis(1));
        }
    }
    if role().is_some() {
        return;
    }
    let name = unique("takeover");
    let mut child = spawn_role(
        "a_killed_owner_is_reported_gone_and_a_new_owner_takes_over",
        "owner",
        &[("SEGMENT", name.clone())],
    );
    let reader = wait_for(Duration::from_secs(10), || {
        SharedGlobalMemory::<Pattern>::attach(&name).ok()
    });
    wait_for(Duration::from_secs(5), || {
        (reader.snapshot().ok()?.seq > 0).then_some(())
    });
    let second = SharedGlobalMemory::<Pattern>::create(&name).map(|_| ());
    assert_eq!(
        second,
        Err(ShmError::OwnerAlive {
            name: name.clone(),
            pid: u64::from(child.id()),
        }),
        "a second live owner is refused, naming the live one"
    );
    kill9(&mut child);
    std::thread::sleep(Duration::from_millis(30));
    let err = reader.snapshot().unwrap_err();
    assert_eq!(err, ShmError::OwnerGone(name.clone()));
    assert!(err.to_string().contains("is gone"));
    assert_eq!(reader.owner_state(), OwnerState::Gone);

    let owner = SharedGlobalMemory::<Pattern>::create(&name).unwrap();
    assert!(owner.generation() > reader.generation());
    assert_eq!(
        reader.snapshot().unwrap_err(),
        ShmError::OwnerGone(name.clone()),
        "the old segment stays dead for its readers"
    );
    let again = SharedGlobalMemory::<Pattern>::attach(&name).unwrap();
    assert_eq!(again.generation(), owner.generation());
    assert!(again.snapshot().is_ok());
}

#[test]
fn a_writer_killed_with_writes_in_flight_does_not_stall_the_others() {
    if role().as_deref() == Some("killed_writer") {
        let name = std::env::var("SEGMENT").unwrap();
        let seg = DynSegment::attach(&name).unwrap();
        // Sent, and the process dies before the answers come.
        for v in 0..16 {
            seg.post_element("w0", 0, Value::UInt(v)).unwrap();
        }
        // SAFETY: ends this child process at once, as a crash would.
        unsafe { libc::kill(libc::getpid(), libc::SIGKILL) };
        return;
    }
    if role().is_some() {
        return;
    }
    let name = unique("stuck");
    let mut owner = SharedGlobalMemory::<Counters>::create(&name).unwrap();
    let mut gm = Counters::default();
    let mut child = spawn_role(
        "a_writer_killed_with_writes_in_flight_does_not_stall_the_others",
        "killed_writer",
        &[("SEGMENT", name.clone())],
    );
    let _ = child.wait();
    let writer = DynSegment::attach(&name).unwrap();
    with_cycles(&mut owner, &mut gm, || {
        writer.write("w1", Value::UInt(7)).unwrap()
    });
    assert_eq!(gm.w1, 7);
    assert_eq!(owner.status().writes_pending, 0);
}

#[test]
fn after_a_clean_stop_readers_still_attached_get_an_error_even_once_a_new_owner_runs() {
    if role().as_deref() == Some("clean_owner") {
        let name = std::env::var("SEGMENT").unwrap();
        let mut owner = SharedGlobalMemory::<Pattern>::create(&name).unwrap();
        let mut gm = Pattern::default();
        while !gm.stop {
            gm.seq += 1;
            owner.publish(&gm).unwrap();
            owner.apply_requests(&mut gm);
            std::thread::sleep(Duration::from_millis(1));
        }
        return; // dropping `owner` stops it cleanly
    }
    if role().is_some() {
        return;
    }
    let name = unique("restart");
    let mut child = spawn_role(
        "after_a_clean_stop_readers_still_attached_get_an_error_even_once_a_new_owner_runs",
        "clean_owner",
        &[("SEGMENT", name.clone())],
    );
    let reader = wait_for(Duration::from_secs(10), || {
        SharedGlobalMemory::<Pattern>::attach(&name).ok()
    });
    let tool = DynSegment::attach(&name).unwrap();
    wait_for(Duration::from_secs(5), || {
        (reader.snapshot().ok()?.seq > 0).then_some(())
    });
    let first = reader.generation();
    reader.write("stop", Value::Bool(true)).unwrap();
    assert!(child.wait().unwrap().success());

    let closed = ShmError::Closed {
        name: name.clone(),
        faulted: false,
    };
    assert_eq!(reader.snapshot().unwrap_err(), closed);
    assert!(closed.to_string().contains("stopped"), "{closed}");
    assert!(
        !runtime_file(&format!("{name}.lock")).exists()
            && !runtime_file(&format!("{name}.sock")).exists(),
        "a clean stop leaves no file behind"
    );

    // A new run of the program: the old mapping stays dead for the readers still holding it.
    let owner = SharedGlobalMemory::<Pattern>::create(&name).unwrap();
    assert!(
        owner.generation() > first,
        "generations increase across clean restarts"
    );
    let gm = Pattern {
        seq: 77,
        ..Default::default()
    };
    owner.publish(&gm).unwrap();
    assert_eq!(reader.snapshot().unwrap_err(), closed);
    assert_eq!(reader.write("stop", Value::Bool(true)), Err(closed.clone()));
    assert!(reader.owner_state() == OwnerState::Gone);
    assert_eq!(tool.read("seq").unwrap_err(), closed);
    assert_eq!(tool.owner_state(), OwnerState::Gone);
    let again = SharedGlobalMemory::<Pattern>::attach(&name).unwrap();
    assert_eq!(again.generation(), owner.generation());
    assert_eq!(again.snapshot().unwrap().seq, 77);
}

#[test]
fn the_heartbeat_is_on_the_monotonic_clock_every_process_shares() {
    let name = unique("heartbeat");
    let owner = SharedGlobalMemory::<Pattern>::create(&name).unwrap();
    owner.publish(&Pattern::default()).unwrap();
    let mut ts = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: clock_gettime writes into the timespec we pass.
    assert_eq!(
        unsafe { libc::clock_gettime(libc::CLOCK_MONOTONIC, &mut ts) },
        0
    );
    let now = ts.tv_sec as u64 * 1_000_000_000 + ts.tv_nsec as u64;
    let beat = owner.word(152);
    assert!(
        now >= beat && now - beat < 5_000_000_000,
        "heartbeat {beat} ns, CLOCK_MONOTONIC {now} ns: not the wall clock, which jumps"
    );
    assert!(DynSegment::attach(&name).unwrap().status().heartbeat_age < Duration::from_secs(5));
}

#[test]
fn a_tool_probing_liveness_does_not_make_a_new_owner_fail() {
    use std::os::fd::AsRawFd;
    let name = unique("probe");
    // The lock file a killed owner leaves (a clean stop removes it).
    let path = runtime_file(&format!("{name}.lock"));
    std::fs::create_dir_all(plc_io::shm::runtime_dir()).unwrap();
    std::fs::write(&path, b"").unwrap();
    std::fs::set_permissions(&path, std::os::unix::fs::PermissionsExt::from_mode(0o600)).unwrap();
    // What `owner_alive` does for a moment at every probe (`plc watch` probes each refresh):
    // a shared lock on the owner's lock file, here held for 30 ms while a new owner starts.
    let lock = std::fs::File::open(&path).unwrap();
    // SAFETY: flock on a descriptor this test owns.
    assert_eq!(unsafe { libc::flock(lock.as_raw_fd(), libc::LOCK_SH) }, 0);
    let probe = std::thread::spawn(move || {
        std::thread::sleep(Duration::from_millis(30));
        drop(lock);
    });
    let owner = SharedGlobalMemory::<Counters>::create(&name);
    probe.join().unwrap();
    assert!(owner.is_ok(), "refused: {:?}", owner.err());
}
