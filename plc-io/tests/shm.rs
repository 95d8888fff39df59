//! Shared memory between real processes: no torn snapshots, every mailbox write applied once
//! and in order, owner crashes, writer crashes, refusals, and damaged segments.

mod common;

use common::{kill9, role, spawn_role, unique, wait_for};
use plc_core::{FixedString, GlobalMemory, Value};
use plc_io::shm::{DynSegment, OwnerState, SharedGlobalMemory, ShmError};
use std::time::Duration;

/// Every word of `data` equals `seq` in a consistent image.
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
            owner.apply_mailbox(&mut gm);
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
    let (mut torn, mut distinct, mut last, mut taken) = (0u64, 0u64, 0u64, 0u64);
    // A snapshot takes well under a microsecond, so on a busy machine a million of them can be
    // over before the writer process gets a core: go on until the writer has been seen
    // publishing concurrently too (bounded in time).
    let deadline = std::time::Instant::now() + Duration::from_secs(60);
    while taken < 1_000_000 || (distinct <= 100 && std::time::Instant::now() < deadline) {
        taken += 1;
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
                    Err(ShmError::MailboxFull(_)) => std::thread::sleep(Duration::from_micros(50)),
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
        owner.apply_mailbox_with(&mut gm, |r, result| {
            assert!(result.is_ok());
            let Value::UInt(v) = r.value else {
                panic!("kind")
            };
            if v != next[r.index] {
                problems.push((r.index, v, next[r.index]));
            }
            next[r.index] = v + 1;
        });
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
    assert!(
        matches!(
            SharedGlobalMemory::<Pattern>::create(&name),
            Err(ShmError::OwnerAlive { .. })
        ),
        "a second live owner is refused"
    );
    kill9(&mut child);
    std::thread::sleep(Duration::from_millis(30));
    let err = reader.snapshot().unwrap_err();
    assert_eq!(err, ShmError::OwnerGone(name.clone()));
    assert!(err.to_string().contains("is gone"));
    assert_eq!(reader.owner_state(), OwnerState::Gone);

    let owner = SharedGlobalMemory::<Pattern>::create(&name).unwrap();
    assert_eq!(owner.generation(), 2);
    assert_eq!(
        reader.snapshot().unwrap_err(),
        ShmError::Replaced(name.clone())
    );
    let again = SharedGlobalMemory::<Pattern>::attach(&name).unwrap();
    assert_eq!(again.generation(), 2);
    assert!(again.snapshot().is_ok());
}

#[test]
fn a_writer_killed_mid_write_does_not_stall_the_mailbox() {
    if role().as_deref() == Some("stuck_writer") {
        let name = std::env::var("SEGMENT").unwrap();
        let seg = DynSegment::attach(&name).unwrap();
        plc_io::shm::mailbox::STOP_AFTER_CLAIM.store(true, std::sync::atomic::Ordering::Relaxed);
        let _ = seg.write("w0", Value::UInt(666)); // parks forever after claiming a slot
        return;
    }
    if role().is_some() {
        return;
    }
    let name = unique("stuck");
    let mut owner = SharedGlobalMemory::<Counters>::create(&name).unwrap();
    let mut gm = Counters::default();
    let mut child = spawn_role(
        "a_writer_killed_mid_write_does_not_stall_the_mailbox",
        "stuck_writer",
        &[("SEGMENT", name.clone())],
    );
    std::thread::sleep(Duration::from_millis(300));
    kill9(&mut child);
    let writer = DynSegment::attach(&name).unwrap();
    writer.write("w1", Value::UInt(7)).unwrap();
    wait_for(Duration::from_secs(5), || {
        owner.apply_mailbox(&mut gm);
        (gm.w1 == 7).then_some(())
    });
    assert_eq!(
        gm.w0, 0,
        "the half-written request was skipped, not applied"
    );
    assert_eq!(owner.status().writes_reclaimed, 1);
}

#[derive(GlobalMemory, Debug, Clone)]
pub struct Machine {
    #[plc(direction = "input")]
    sensor: u16,
    #[plc(direction = "status")]
    state: u8,
    #[plc(read_only)]
    serial: u32,
    #[plc(direction = "command")]
    speed: u8,
    #[plc(direction = "command")]
    note: FixedString<8>,
    table: [i16; 4],
}

#[test]
fn writes_are_refused_up_front_with_the_reason() {
    let name = unique("refuse");
    let _owner = SharedGlobalMemory::<Machine>::create(&name).unwrap();
    let seg = DynSegment::attach(&name).unwrap();
    let refused = |var: &str, v: Value| seg.write(var, v).unwrap_err().to_string();
    assert!(refused("sensor", Value::UInt(1)).contains("an input"));
    assert!(refused("state", Value::UInt(1)).contains("status"));
    assert!(refused("serial", Value::UInt(1)).contains("read-only"));
    assert!(refused("nope", Value::UInt(1)).contains("has no variable `nope`"));
    assert!(refused("speed", Value::UInt(256)).contains("out of range for USINT"));
    assert!(refused("speed", Value::Bool(true)).contains("expected a USINT value"));
    let long = Value::Text(FixedString::from_str_truncate("nine char"));
    assert!(refused("note", long).contains("capacity of 8"));
    assert!(matches!(
        seg.write_element("table", 4, Value::Int(1)),
        Err(ShmError::ElementOutOfRange { len: 4, .. })
    ));
    for _ in 0..64 {
        seg.write("speed", Value::UInt(1)).unwrap();
    }
    assert_eq!(
        seg.write("speed", Value::UInt(1)),
        Err(ShmError::MailboxFull(name.clone())),
        "a full mailbox is an error, never a silent drop"
    );
}

#[test]
fn external_writes_reach_the_program_and_are_not_overwritten() {
    let name = unique("writeback");
    let mut owner = SharedGlobalMemory::<Machine>::create(&name).unwrap();
    let mut gm = Machine::default();
    let hmi = SharedGlobalMemory::<Machine>::attach(&name).unwrap();
    hmi.write("SPEED", Value::UInt(42)).unwrap();
    hmi.write_element("table", 2, Value::Int(-5)).unwrap();
    // The program changes other variables in the same cycle; only the written ones change.
    gm.state = 3;
    owner.apply_mailbox(&mut gm);
    owner.publish(&gm).unwrap();
    let seen = hmi.snapshot().unwrap();
    assert_eq!((seen.speed, seen.state, seen.table[2]), (42, 3, -5));
    assert_eq!(hmi.read("speed").unwrap(), Value::UInt(42));
    assert_eq!(hmi.read_element("table", 2).unwrap(), Value::Int(-5));
}

#[derive(GlobalMemory, Debug, Clone)]
pub struct Other {
    count: u32,
}

#[test]
fn attaching_checks_name_layout_and_size() {
    assert_eq!(
        DynSegment::attach("no_such_segment_here").err(),
        Some(ShmError::NotFound("no_such_segment_here".into()))
    );
    assert!(matches!(
        DynSegment::attach("a/b").err(),
        Some(ShmError::BadName(_))
    ));
    let name = unique("layout");
    let _owner = SharedGlobalMemory::<Machine>::create(&name).unwrap();
    let err = SharedGlobalMemory::<Other>::attach(&name).err().unwrap();
    assert!(matches!(err, ShmError::LayoutMismatch { .. }));
    assert!(err.to_string().contains("another variable layout"));
    // The /dev/shm name works too, and the descriptor describes the program.
    let seg = DynSegment::attach(&format!("/dev/shm/plc.{name}")).unwrap();
    assert_eq!(seg.descriptor().variables.len(), 6);
    assert_eq!(seg.descriptor().layout_hash, Machine::LAYOUT_HASH);

    // A segment too small for its own header.
    let small = unique("small");
    let _raw = shared_memory::ShmemConf::new()
        .size(100)
        .os_id(format!("/plc.{small}"))
        .create()
        .unwrap();
    assert!(matches!(
        DynSegment::attach(&small).err(),
        Some(ShmError::TooSmall { .. })
    ));
}

#[test]
fn invalid_utf8_written_from_outside_reads_as_the_valid_prefix() {
    let name = unique("utf8");
    let mut owner = SharedGlobalMemory::<Machine>::create(&name).unwrap();
    let mut gm = Machine::default();
    gm.note.set("ok");
    owner.publish(&gm).unwrap();
    owner.apply_mailbox(&mut gm);
    // Another process scribbles over the string's bytes.
    let raw = shared_memory::ShmemConf::new()
        .os_id(format!("/plc.{name}"))
        .open()
        .unwrap();
    let note = &Machine::VARIABLES[4];
    // SAFETY: test-only raw write into the image area (offset 192) of a live segment, as a
    // misbehaving process would.
    unsafe {
        let p = raw.as_ptr().add(192 + note.offset);
        for (i, b) in [b'o', b'k', 0xFF, 0xFE, b'x'].iter().enumerate() {
            p.add(i).write_volatile(*b);
        }
    }
    let hmi = SharedGlobalMemory::<Machine>::attach(&name).unwrap();
    assert_eq!(hmi.snapshot().unwrap().note, "ok");
    assert_eq!(hmi.read("note").unwrap().to_string(), "ok");
}
