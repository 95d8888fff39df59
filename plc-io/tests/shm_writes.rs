//! Writes through shared memory: refused up front with the reason, bounded by writes waiting,
//! applied and not overwritten; names found as the descriptor has them, layouts and sizes
//! checked when attaching, text from outside read safely; every request checked again by the
//! owner, and damaged headers, descriptors and clock words reported, never a panic.

mod common;

use common::{runtime_file, unique, wait_for, with_cycles};
use plc_core::write::Write;
use plc_core::{FixedString, GlobalMemory, Value};
use plc_io::shm::{DynSegment, SharedGlobalMemory, ShmError};
use std::time::Duration;

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
    let refused = |var: &str, v: Value| {
        // Checking without sending refuses the same way, and sends nothing.
        let checked = seg.check(var, 0, v).unwrap_err();
        let written = seg.write(var, v).unwrap_err();
        assert_eq!(checked, written);
        written.to_string()
    };
    assert_eq!(seg.check("speed", 0, Value::Int(7)), Ok(Value::UInt(7)));
    let sent = |s: &DynSegment| {
        let st = s.status();
        st.writes_pending + st.writes_applied + st.writes_rejected
    };
    assert_eq!(sent(&seg), 0, "a check sends nothing");
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
    assert_eq!(sent(&seg), 0, "refused before anything was sent");
    // A program that takes no writes (stopped, as in a debugger): one connection's requests
    // wait up to a bound, then are refused, never silently dropped.
    for _ in 0..64 {
        seg.post_element("speed", 0, Value::UInt(1)).unwrap();
    }
    assert_eq!(
        seg.write("speed", Value::UInt(1)),
        Err(ShmError::QueueFull(name.clone())),
        "too many waiting is an error, never a silent drop"
    );
}

#[test]
fn requests_of_a_thousand_writes_wait_up_to_a_bound_of_writes_not_only_of_requests() {
    // A request may hold 1,024 writes (an array written whole), so what waits for a program
    // that takes no writes is bounded by writes: 16 such requests, then Busy.
    let name = unique("bigwait");
    let _owner = SharedGlobalMemory::<Machine>::create(&name).unwrap();
    let seg = DynSegment::attach(&name).unwrap();
    let one = seg
        .check_write(named(&seg, "speed", 0, Value::UInt(3)))
        .unwrap();
    let request = vec![one; plc_io::shm::protocol::MAX_WRITES];
    for _ in 0..16 {
        seg.post_checked(&request).unwrap();
    }
    assert_eq!(
        seg.write_checked(&request),
        Err(ShmError::QueueFull(name.clone())),
        "16,384 writes wait: the next request is turned away"
    );
    assert_eq!(seg.status().writes_pending, 16);
    // Larger than a request may be: refused before anything is sent.
    let too_many = vec![one; plc_io::shm::protocol::MAX_WRITES + 1];
    let refused = seg.post_checked(&too_many).unwrap_err();
    assert!(
        matches!(
            refused,
            ShmError::RequestCount {
                count: 1025,
                most: 1024,
                ..
            }
        ),
        "{refused:?}"
    );
    assert!(
        refused
            .to_string()
            .contains("a request holds 1 to 1024; send them in parts"),
        "{refused}"
    );
}

/// A write to element `leaf` of the variable called `name` in `seg`.
fn named(seg: &DynSegment, name: &str, leaf: usize, value: Value) -> Write {
    let index = seg.index_of(name).expect("the variable is declared");
    Write { index, leaf, value }
}

#[test]
fn external_writes_reach_the_program_and_are_not_overwritten() {
    let name = unique("writeback");
    let mut owner = SharedGlobalMemory::<Machine>::create(&name).unwrap();
    let mut gm = Machine::default();
    let hmi = SharedGlobalMemory::<Machine>::attach(&name).unwrap();
    // The program changes other variables meanwhile; only the written ones change.
    gm.state = 3;
    with_cycles(&mut owner, &mut gm, || {
        hmi.write("SPEED", Value::UInt(42)).unwrap();
        hmi.write_element("table", 2, Value::Int(-5)).unwrap();
    });
    owner.publish(&gm).unwrap();
    let seen = hmi.snapshot().unwrap();
    assert_eq!((seen.speed, seen.state, seen.table[2]), (42, 3, -5));
    assert_eq!(hmi.read("speed").unwrap(), Value::UInt(42));
    assert_eq!(hmi.read_element("table", 2).unwrap(), Value::Int(-5));
    // Several writes as one request: applied together, or none of them.
    let tool = DynSegment::attach(&name).unwrap();
    with_cycles(&mut owner, &mut gm, || {
        tool.write_all(&[
            named(&tool, "speed", 0, Value::UInt(9)),
            named(&tool, "table", 1, Value::Int(4)),
        ])
        .unwrap()
    });
    assert_eq!((gm.speed, gm.table[1]), (9, 4));
    let refused = tool.write_all(&[
        named(&tool, "speed", 0, Value::UInt(1)),
        named(&tool, "state", 0, Value::UInt(1)),
    ]);
    assert!(
        matches!(refused, Err(ShmError::NotWritable { .. })),
        "{refused:?}"
    );
    owner.apply_requests(&mut gm);
    assert_eq!(gm.speed, 9, "nothing of a refused request is written");
}

#[derive(GlobalMemory, Debug, Clone)]
pub struct Other {
    count: u32,
}

#[test]
fn a_tool_finds_every_name_as_the_descriptor_does_in_any_case() {
    let name = unique("names");
    let _owner = SharedGlobalMemory::<Machine>::create(&name).unwrap();
    let seg = DynSegment::attach(&name).unwrap();
    for (i, v) in seg.descriptor().variables.iter().enumerate() {
        for spelled in [v.name.clone(), v.name.to_ascii_uppercase()] {
            assert_eq!(seg.index_of(&spelled), Some(i), "{spelled}");
            assert_eq!(seg.descriptor().index_of(&spelled), Some(i), "{spelled}");
        }
    }
    assert_eq!(seg.index_of("Speed"), Machine::index_of("speed"));
    assert_eq!(seg.index_of("no_such_variable"), None);
    assert_eq!(seg.index_of(""), None);
    assert_eq!(
        seg.index_of("table[1]"),
        None,
        "an element is not a variable's name"
    );
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
    // The socket's path works too, and the descriptor describes the program.
    let socket = runtime_file(&format!("{name}.sock"));
    let seg = DynSegment::attach(&socket.display().to_string()).unwrap();
    assert_eq!(seg.descriptor().variables.len(), 6);
    assert_eq!(seg.descriptor().layout_hash, Machine::LAYOUT_HASH);

    // A file that is not a socket where the socket would be.
    let fake = unique("fake");
    let path = runtime_file(&format!("{fake}.sock"));
    std::fs::write(&path, [0u8; 100]).unwrap();
    let refused = DynSegment::attach(&fake).err();
    std::fs::remove_file(&path).unwrap();
    assert!(
        matches!(&refused, Some(ShmError::Unsafe { problem, .. }) if problem.contains("not a socket")),
        "{refused:?}"
    );
}

#[test]
fn invalid_utf8_written_from_outside_reads_as_the_valid_prefix() {
    let name = unique("utf8");
    let mut owner = SharedGlobalMemory::<Machine>::create(&name).unwrap();
    let mut gm = Machine::default();
    gm.note.set("ok");
    owner.publish(&gm).unwrap();
    owner.apply_requests(&mut gm);
    // The string's bytes are not UTF-8 (an owner built from other code, or damaged).
    let note = &Machine::VARIABLES[4];
    owner.scribble(192 + note.offset, &[b'o', b'k', 0xFF, 0xFE, b'x']);
    let hmi = SharedGlobalMemory::<Machine>::attach(&name).unwrap();
    assert_eq!(hmi.snapshot().unwrap().note, "ok");
    assert_eq!(hmi.read("note").unwrap().to_string(), "ok");
}

#[test]
fn the_owner_checks_every_request_again_and_rejects_what_a_writer_should_not_post() {
    use plc_io::shm::WriteOutcome as Outcome;
    let name = unique("distrust");
    let mut owner = SharedGlobalMemory::<Machine>::create(&name).unwrap();
    let mut gm = Machine::default();
    // A misbehaving process posts without the writer's checks.
    let seg = DynSegment::attach(&name).unwrap();
    let index = |n: &str| Machine::index_of(n).unwrap();
    let forged = [
        (index("serial"), 0, Value::UInt(1)),
        (index("sensor"), 0, Value::UInt(1)),
        (index("state"), 0, Value::UInt(1)),
        (index("table"), 4, Value::Int(1)),
        (99, 0, Value::UInt(1)),
        (index("speed"), 0, Value::UInt(300)),
    ];
    let tickets: Vec<_> = forged
        .iter()
        .map(|&(i, e, v)| seg.post_unchecked(i, e, v).unwrap())
        .collect();
    // Refused by the owner's server thread, before the cycle sees them.
    let outcomes: Vec<Outcome> = tickets
        .iter()
        .map(|&t| {
            wait_for(Duration::from_secs(5), || {
                Some(seg.outcome(t)).filter(|o| *o != Outcome::Pending)
            })
        })
        .collect();
    assert_eq!(owner.apply_requests(&mut gm), 0);
    assert!(
        outcomes.iter().all(|o| *o == Outcome::Rejected),
        "{outcomes:?}"
    );
    // Each reason, as a writer that skips the checks hears it.
    let reason = |k: usize| {
        let (i, e, v) = forged[k];
        match seg.write_unchecked(i, e, v) {
            Err(err @ ShmError::WriteRejected { .. }) => err.to_string(),
            other => panic!("{other:?}"),
        }
    };
    assert!(
        reason(0).contains("`serial` cannot be written: it is read-only"),
        "{}",
        reason(0)
    );
    assert!(reason(1).contains("an input"));
    assert!(reason(2).contains("status"));
    assert!(reason(3).contains("out of range"));
    assert!(reason(4).contains("no variable number 99"));
    assert!(reason(5).contains("USINT"), "{}", reason(5));
    assert_eq!(
        (gm.serial, gm.sensor, gm.state, gm.table, gm.speed),
        (0, 0, 0, [0; 4], 0),
        "nothing changed"
    );
    assert_eq!(owner.status().writes_rejected, 12);
}

#[test]
fn a_damaged_header_or_descriptor_is_an_error_naming_the_damage_never_a_panic() {
    let name = unique("damaged");
    // Only the owner can write its sealed segment: a damaged or hostile owner is played
    // through its own mapping. Header words: 8 format version, 16 layout hash, 24 image
    // size, 48 descriptor offset, 56 descriptor length.
    let owner = SharedGlobalMemory::<Machine>::create(&name).unwrap();
    let attach = || DynSegment::attach(&name).err().expect("refused");
    let set = |at: usize, v: u64| owner.scribble(at, &v.to_le_bytes());
    let with = |at: usize, v: u64, check: &dyn Fn(ShmError)| {
        let old = owner.word(at);
        set(at, v);
        check(attach());
        set(at, old);
    };
    with(8, 999, &|e| {
        assert!(matches!(e, ShmError::Format { .. }), "{e:?}");
        assert!(e.to_string().contains("format version 999"), "{e}");
    });
    with(24, u64::MAX, &|e| {
        assert!(matches!(e, ShmError::Corrupt { .. }), "{e:?}");
        assert!(e.to_string().contains("image size"), "{e}");
    });
    with(24, 1 << 40, &|e| {
        assert!(matches!(e, ShmError::Corrupt { .. }), "{e:?}");
        assert!(e.to_string().contains("more than"), "{e}");
    });
    with(24, 1 << 20, &|e| {
        assert!(matches!(e, ShmError::TooSmall { .. }), "{e:?}");
    });
    with(56, u64::MAX, &|e| {
        assert!(matches!(e, ShmError::Corrupt { .. }), "{e:?}");
    });
    with(56, 1 << 20, &|e| {
        assert!(matches!(e, ShmError::TooSmall { .. }), "{e:?}");
    });
    with(48, 200, &|e| {
        assert!(e.to_string().contains("descriptor at byte 200"), "{e}");
    });
    let d_off = owner.word(48) as usize;
    with(d_off, u64::from_le_bytes(*b"garbage!"), &|e| {
        assert!(e.to_string().contains("not valid JSON"), "{e}");
    });
    with(16, 12345, &|e| {
        assert!(e.to_string().contains("layout hash"), "{e}");
    });
    assert!(DynSegment::attach(&name).is_ok(), "restored, it attaches");

    // Descriptors whose numbers overflow, with a matching layout hash (the hash is no
    // signature: anybody can recompute it).
    let good = DynSegment::attach(&name).unwrap().descriptor().clone();
    let (d_len, hash) = (owner.word(56), owner.word(16));
    let json_was = serde_json::to_vec(&good).unwrap();
    assert_eq!(json_was.len() as u64, d_len);
    let forge = |edit: &dyn Fn(&mut plc_io::shm::VarDescriptor)| {
        let mut d = good.clone();
        d.variables.truncate(1);
        edit(&mut d.variables[0]);
        d.layout_hash = d.computed_hash();
        let json = serde_json::to_vec(&d).unwrap();
        assert!(json.len() <= json_was.len());
        owner.scribble(d_off, &json);
        set(56, json.len() as u64);
        set(16, d.layout_hash);
        let e = attach();
        owner.scribble(d_off, &json_was);
        set(56, d_len);
        set(16, hash);
        e
    };
    let e = forge(&|v| v.offset = usize::MAX);
    assert!(e.to_string().contains("outside the image"), "{e}");
    let e = forge(&|v| v.dims = vec![1 << 32, 1 << 32]);
    assert!(e.to_string().contains("whole number of elements"), "{e}");
    let e = forge(&|v| {
        v.bit = Some(plc_io::shm::BitDescriptor {
            source: 1000,
            bit: 3,
        })
    });
    assert!(e.to_string().contains("does not exist"), "{e}");
    assert!(DynSegment::attach(&name).is_ok());
}

#[test]
fn the_bus_clocks_reach_the_tools_and_damaged_clock_words_read_as_none() {
    use plc_io::shm::{BusClocks, BusState, CycleStats, IoStatus};
    let name = unique("clocks");
    let owner = SharedGlobalMemory::<Machine>::create(&name).unwrap();
    let seg = DynSegment::attach(&name).unwrap();
    assert_eq!(seg.status().clocks, None, "a new segment has none");
    let clocks = BusClocks {
        sync0_period_ns: 500_000,
        max_time_difference_ns: Some(42),
        sync0_offset_ns: 77_000,
    };
    let io = IoStatus {
        inputs_valid: true,
        bus_fault: false,
        bus_state: BusState::Op,
        clocks: Some(clocks),
    };
    owner.report(1, &CycleStats::default(), &io);
    assert_eq!(seg.status().clocks, Some(clocks));
    // The three clock words sit right before the two alarm counts, which sit right before
    // the descriptor (header word 48).
    let descriptor = owner.word(48) as usize;
    owner.set_alarm_counts(3, 2);
    assert_eq!(
        (owner.word(descriptor - 16), owner.word(descriptor - 8)),
        (3, 2)
    );
    let status = seg.status();
    assert_eq!((status.alarms_active, status.alarms_unacknowledged), (3, 2));
    let at = descriptor - 16 - 24;
    owner.scribble(at, &u64::MAX.to_le_bytes());
    assert_eq!(
        seg.status().clocks,
        None,
        "a period that does not fit: none"
    );
    owner.report(2, &CycleStats::default(), &IoStatus::NONE);
    assert_eq!(
        seg.status().clocks,
        None,
        "a bus without clocks clears them"
    );
}
