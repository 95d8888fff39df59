//! What a misbehaving writer and a hostile process do to a running program through its socket
//! and the segment it received: malformed and valid-looking messages, floods, attempts to
//! write or resize the segment. The program neither crashes nor stalls, and writes nothing
//! it should not. (Files, links and other users: `hardening.rs`.)

mod common;

use common::{Cleanup, alone, kill9, role, socket, spawn_role, unique, wait_for};
use plc_core::{GlobalMemory, Value};
use plc_io::shm::{DynSegment, SharedGlobalMemory, list_segments};
use std::os::fd::AsRawFd;
use std::time::{Duration, Instant};

#[derive(GlobalMemory, Debug, Clone, PartialEq)]
pub struct Guarded {
    #[plc(direction = "input")]
    sensor: u16,
    #[plc(direction = "status")]
    state: u8,
    #[plc(read_only, initial = 7)]
    serial: u32,
    #[plc(direction = "command")]
    speed: u8,
    #[plc(direction = "command")]
    note: plc_core::FixedString<8>,
    table: [i16; 4],
}

/// One thing a misbehaving writer sends.
#[derive(Clone, Debug)]
enum Message {
    /// A well-formed request with any index, element and value, past every writer check.
    Post(usize, usize, Box<Value>),
    /// Any bytes as one message.
    Bytes(Vec<u8>),
}

fn any_value() -> impl proptest::strategy::Strategy<Value = Value> {
    use proptest::prelude::*;
    prop_oneof![
        any::<bool>().prop_map(Value::Bool),
        any::<i64>().prop_map(Value::Int),
        any::<u64>().prop_map(Value::UInt),
        any::<f64>().prop_map(Value::Real),
        "[a-z\u{e9}]{0,12}".prop_map(|s| Value::Text(plc_core::FixedString::from_str_truncate(&s))),
    ]
}

fn any_message() -> impl proptest::strategy::Strategy<Value = Message> {
    use proptest::prelude::*;
    prop_oneof![
        (0usize..10, 0usize..8, any_value()).prop_map(|(i, e, v)| Message::Post(i, e, Box::new(v))),
        proptest::collection::vec(any::<u8>(), 0..64).prop_map(|mut b| {
            // Mostly the write tag, to reach past the first check.
            if let Some(first) = b.first_mut() {
                *first %= 3;
            }
            Message::Bytes(b)
        }),
    ]
}

proptest::proptest! {
    #![proptest_config(proptest::test_runner::Config::with_cases(32))]

    /// Whatever arrives on the socket, the owner neither panics nor stalls, the writer is
    /// answered, nothing that may not be written from outside changes, and what is applied is
    /// what `set` accepts.
    #[test]
    fn the_owner_survives_arbitrary_messages_on_its_socket(
        messages in proptest::collection::vec(any_message(), 1..40)
    ) {
        let _alone = alone();
        let name = unique("prop");
        let mut owner = SharedGlobalMemory::<Guarded>::create(&name).unwrap();
        let seg = DynSegment::attach(&name).unwrap();
        let mut gm = Guarded::default();
        for m in &messages {
            let start = Instant::now();
            match m {
                Message::Post(i, e, v) => drop(seg.post_unchecked(*i, *e, **v)),
                Message::Bytes(b) => drop(seg.send_raw(b)),
            }
            proptest::prop_assert!(start.elapsed() < Duration::from_secs(5));
            let mut applied = Vec::new();
            owner.apply_requests_with(&mut gm, |r, outcome| {
                if outcome.is_ok() {
                    applied.push(*r);
                }
            });
            for r in applied {
                let var = &Guarded::VARIABLES[r.index];
                proptest::prop_assert!(var.writable_from_outside(), "{} was written", var.name);
                proptest::prop_assert!(r.leaf < var.elements());
            }
            proptest::prop_assert_eq!((gm.sensor, gm.state, gm.serial), (0, 0, 7));
        }
        // After all that, a correct write still gets through.
        let done = std::sync::atomic::AtomicBool::new(false);
        std::thread::scope(|s| {
            s.spawn(|| while !done.load(std::sync::atomic::Ordering::Relaxed) {
                owner.apply_requests(&mut gm);
            });
            let r = seg.write("speed", Value::UInt(3));
            done.store(true, std::sync::atomic::Ordering::Relaxed);
            r
        }).unwrap();
        proptest::prop_assert_eq!(gm.speed, 3);
        drop(seg);
        drop(owner);
        proptest::prop_assert!(!socket(&name).exists());
    }
}

#[derive(GlobalMemory, Debug, Clone)]
pub struct Attacked {
    #[plc(direction = "status")]
    count: u64,
    /// Always twice `count`: only the program writes either.
    #[plc(direction = "status")]
    doubled: u64,
    #[plc(direction = "command")]
    setpoint: u32,
    /// The last accepted `setpoint`.
    #[plc(direction = "status")]
    echo: u32,
}

/// A small deterministic generator: the attack needs noise, not statistics.
struct Noise(u64);

impl Noise {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    fn below(&mut self, n: u64) -> u64 {
        self.next() % n.max(1)
    }
}

/// Times `f`, which must answer within a few seconds whatever state the segment is in.
fn bounded<R>(what: &str, f: impl FnOnce() -> R) -> R {
    let start = Instant::now();
    let r = f();
    assert!(
        start.elapsed() < Duration::from_secs(5),
        "{what} took {:?}",
        start.elapsed()
    );
    r
}

/// What a hostile tool tries on the segment it received: every attempt must fail.
fn try_to_change_the_segment(seg: &DynSegment, noise: &mut Noise) {
    let fd = seg.segment_fd().as_raw_fd();
    // SAFETY: calls on a descriptor this process holds; a mapping that succeeds (it must not)
    // is unmapped at once.
    unsafe {
        let p = libc::mmap(
            std::ptr::null_mut(),
            4096,
            libc::PROT_READ | libc::PROT_WRITE,
            libc::MAP_SHARED,
            fd,
            0,
        );
        assert_eq!(p, libc::MAP_FAILED, "mapped writable");
        assert_eq!(
            libc::ftruncate(fd, noise.below(1 << 20) as i64),
            -1,
            "resized"
        );
        let bytes: Vec<u8> = (0..64).map(|_| noise.next() as u8).collect();
        let at = noise.below(4096) as i64;
        assert_eq!(
            libc::pwrite(fd, bytes.as_ptr() as *const _, bytes.len(), at),
            -1,
            "written"
        );
    }
}

#[test]
fn a_hostile_process_neither_stops_the_owner_nor_the_tools_for_longer_than_the_attack() {
    let _alone = alone();
    match role().as_deref() {
        Some("attacked_owner") => {
            let name = std::env::var("SEGMENT").unwrap();
            let _ = plc_io::Runtime::<Attacked>::builder()
                .period(Duration::from_millis(2))
                .segment(name)
                .handle_signals(false)
                .build()
                .expect("the runtime's settings are valid")
                .run(|ctx| {
                    // Status variables come from the program alone: had a write from outside
                    // been applied to one, this panics, the run ends and the test sees the
                    // owner gone.
                    assert_eq!(ctx.gm.doubled, ctx.gm.count * 2, "a status was written");
                    ctx.gm.count += 1;
                    ctx.gm.doubled = ctx.gm.count * 2;
                    ctx.gm.echo = ctx.gm.setpoint;
                });
            return;
        }
        Some("attacker") => {
            let name = std::env::var("SEGMENT").unwrap();
            let mut noise = Noise(0x9E37_79B9_7F4A_7C15 ^ u64::from(std::process::id()));
            let start = Instant::now();
            let mut connections = Vec::new();
            while start.elapsed() < Duration::from_secs(3) {
                let Ok(seg) = DynSegment::attach(&name) else {
                    continue;
                };
                try_to_change_the_segment(&seg, &mut noise);
                // Flood the socket: random bytes, requests of any kind past the writer's
                // checks, and valid-looking ones, without waiting for answers.
                for _ in 0..64 {
                    let len = noise.below(300) as usize;
                    let mut bytes: Vec<u8> = (0..len).map(|_| noise.next() as u8).collect();
                    if let Some(b) = bytes.first_mut() {
                        *b %= 3;
                    }
                    let _ = seg.send_raw(&bytes);
                    let value = match noise.below(4) {
                        0 => Value::UInt(noise.next()),
                        1 => Value::Int(noise.next() as i64),
                        2 => Value::Real(f64::from_bits(noise.next())),
                        _ => Value::Bool(noise.next() & 1 == 1),
                    };
                    let _ =
                        seg.post_unchecked(noise.below(6) as usize, noise.below(3) as usize, value);
                    let _ = seg.post_element("setpoint", 0, Value::UInt(noise.below(1000)));
                }
                // Hold connections open, as many as it is let have.
                if connections.len() < 100 {
                    connections.push(seg);
                }
            }
            return;
        }
        Some(_) => return,
        None => {}
    }
    let test = "a_hostile_process_neither_stops_the_owner_nor_the_tools_for_longer_than_the_attack";
    let name = unique("attacked");
    let _c = Cleanup(name.clone());
    let mut owner = spawn_role(test, "attacked_owner", &[("SEGMENT", name.clone())]);
    wait_for(Duration::from_secs(20), || DynSegment::attach(&name).ok());
    let mut attacker = spawn_role(test, "attacker", &[("SEGMENT", name.clone())]);
    // During the attack every tool call answers (rightly or with an error) in bounded time.
    let mut calls = 0;
    while attacker.try_wait().unwrap().is_none() {
        if let Ok(seg) = bounded("attach", || DynSegment::attach(&name)) {
            let _ = bounded("get", || seg.read("count"));
            let _ = bounded("set", || seg.write("setpoint", Value::UInt(1)));
        }
        bounded("list", list_segments);
        calls += 1;
    }
    assert!(
        attacker.wait().unwrap().success(),
        "an attempt on the segment succeeded"
    );
    assert!(calls > 0);
    // Within moments of the end, the tools read the program's own values and writes arrive.
    let attack_over = Instant::now();
    let seg = wait_for(Duration::from_secs(3), || {
        let seg = DynSegment::attach(&name).ok()?;
        let image = seg.snapshot_bytes().ok()?;
        let at = |i: usize| seg.descriptor().variables[i].value_in(&image, 0);
        let (Some(Value::UInt(count)), Some(Value::UInt(doubled))) = (at(0), at(1)) else {
            return None;
        };
        (count > 0 && doubled == 2 * count).then_some(seg)
    });
    seg.write("setpoint", Value::UInt(4242)).unwrap();
    wait_for(Duration::from_secs(3), || {
        (seg.read("echo") == Ok(Value::UInt(4242))).then_some(())
    });
    let listed = list_segments();
    let me = listed.iter().find(|s| s.name == name).expect("listed");
    assert!(
        me.problem.is_none() && me.state == plc_io::shm::OwnerState::Running,
        "{me:?}"
    );
    let status = seg.status();
    assert!(
        status.writes_discarded > 0 && status.writes_rejected > 0,
        "{status:?}"
    );
    let recovered = attack_over.elapsed();
    // The owner cycled through it all: it is still the one process that owns the segment.
    assert!(owner.try_wait().unwrap().is_none(), "the owner died");
    let before = seg.status().cycle_count;
    wait_for(Duration::from_secs(3), || {
        (seg.status().cycle_count > before).then_some(())
    });
    // Killed, it is replaced at once by a new owner.
    kill9(&mut owner);
    let next = SharedGlobalMemory::<Attacked>::create(&name).expect("a new owner starts at once");
    next.publish(&Attacked::default()).unwrap();
    assert!(SharedGlobalMemory::<Attacked>::attach(&name).is_ok());
    eprintln!("recovered {recovered:?} after the attack, {calls} tool rounds during it");
}
