//! Forces and traces through a running `Runtime`: a forced input is what the program reads, a
//! forced output is what it publishes whatever it writes, writes to forced values are refused
//! naming the force, releases restore or not; a trace holds every cycle, in order, with the
//! cycle's number.

mod common;

use common::{run_program, unique, wait_for};
use plc_core::write::Write;
use plc_core::{GlobalMemory, Value};
use plc_io::shm::trace::TraceEvent;
use plc_io::shm::{DynSegment, ShmError};
use std::time::Duration;

#[derive(GlobalMemory, Debug, Clone)]
pub struct Gm {
    #[plc(direction = "input")]
    start_button: bool,
    #[plc(direction = "output")]
    motor_on: bool,
    #[plc(direction = "output")]
    lamp: bool,
    #[plc(direction = "command")]
    setpoint: f32,
    #[plc(direction = "status")]
    counter: u64,
    #[plc(direction = "command")]
    speeds: [i16; 300],
}

/// The program: the motor follows the start button, the lamp is always written off, the
/// counter counts cycles.
fn program(name: &str) -> (plc_io::StopHandle, std::thread::JoinHandle<Gm>) {
    run_program(name, |ctx: &mut plc_io::Context<Gm>| {
        ctx.gm.motor_on = ctx.gm.start_button;
        ctx.gm.lamp = false;
        ctx.gm.counter += 1;
    })
}

fn force(seg: &DynSegment, name: &str, leaf: usize, value: Value) -> Result<(), ShmError> {
    let index = seg.index_of(name).unwrap();
    let checked = seg.check_force(Write { index, leaf, value })?;
    seg.force(&[checked])
}

/// Waits until `name` reads `want` (a force is applied at the owner's next cycle).
fn settles(seg: &DynSegment, name: &str, want: Value) {
    wait_for(Duration::from_secs(5), || {
        (seg.read(name).ok() == Some(want)).then_some(())
    });
}

#[test]
fn forced_inputs_and_outputs_hold_and_writes_to_them_are_refused() {
    let name = unique("force");
    let (stop, program) = program(&name);
    let seg = wait_for(Duration::from_secs(10), || DynSegment::attach(&name).ok());
    // An input the program reacts to, an output it writes the opposite of.
    force(&seg, "start_button", 0, Value::Bool(true)).unwrap();
    force(&seg, "lamp", 0, Value::Bool(true)).unwrap();
    settles(&seg, "motor_on", Value::Bool(true));
    for _ in 0..20 {
        assert_eq!(seg.read("lamp").unwrap(), Value::Bool(true));
        std::thread::sleep(Duration::from_millis(1));
    }
    assert_eq!(seg.status().forces, 2);
    let held = seg.forces().unwrap();
    assert_eq!(held.len(), 2);
    assert!(held.iter().all(|f| f.uid == plc_io::shm::euid()));
    assert!(held[0].since_utc_ns > 0);

    // A write to a forced value is refused, naming the force.
    let index = seg.index_of("setpoint").unwrap();
    force(&seg, "setpoint", 0, Value::Real(2.5)).unwrap();
    let refused = seg.write_all(&[Write {
        index,
        leaf: 0,
        value: Value::Real(1.0),
    }]);
    let Err(ShmError::Forced {
        variable, reason, ..
    }) = &refused
    else {
        panic!("{refused:?}");
    };
    assert_eq!(variable, "setpoint");
    assert!(
        reason.contains("forced") && reason.contains(&format!("uid {}", plc_io::shm::euid())),
        "{reason}"
    );
    assert_eq!(seg.read("setpoint").unwrap(), Value::Real(2.5));

    // An element of an array, and a release that restores the value before the force.
    seg.write_all(&[Write {
        index: seg.index_of("speeds").unwrap(),
        leaf: 7,
        value: Value::Int(-3),
    }])
    .unwrap();
    force(&seg, "speeds", 7, Value::Int(40)).unwrap();
    assert_eq!(seg.read_element("speeds", 7).unwrap(), Value::Int(40));
    let speeds = seg.index_of("speeds").unwrap();
    seg.release(&[(speeds, 7)], true).unwrap();
    assert_eq!(seg.read_element("speeds", 7).unwrap(), Value::Int(-3));

    // Released without restore, the program's next value stands.
    let lamp = seg.index_of("lamp").unwrap();
    seg.release(&[(lamp, 0)], false).unwrap();
    settles(&seg, "lamp", Value::Bool(false));
    // Releasing what is not forced is refused, and nothing of the request is done.
    let again = seg.release(&[(lamp, 0)], false).unwrap_err().to_string();
    assert!(again.contains("`lamp` is not forced"), "{again}");

    // Without a bus nothing writes the input: restored, it reads as before its force.
    seg.release_all(true).unwrap();
    assert_eq!(seg.status().forces, 0);
    assert!(seg.forces().unwrap().is_empty());
    settles(&seg, "motor_on", Value::Bool(false));
    stop.stop();
    program.join().unwrap();
}

#[test]
fn at_most_256_forces_are_held() {
    let name = unique("force_limit");
    let (stop, program) = program(&name);
    let seg = wait_for(Duration::from_secs(10), || DynSegment::attach(&name).ok());
    let speeds = seg.index_of("speeds").unwrap();
    let checked: Vec<_> = (0..257)
        .map(|e| {
            seg.check_force(Write {
                index: speeds,
                leaf: e,
                value: Value::Int(e as i64),
            })
            .unwrap()
        })
        .collect();
    for part in checked[..256].chunks(64) {
        seg.force(part).unwrap();
    }
    assert_eq!(seg.status().forces, 256);
    let over = seg.force(&checked[256..]).unwrap_err().to_string();
    assert!(over.contains("at most 256"), "{over}");
    // Forcing one held already changes its value, not the count.
    seg.force(&checked[..1]).unwrap();
    assert_eq!(seg.status().forces, 256);
    stop.stop();
    program.join().unwrap();
}

#[test]
fn a_trace_holds_every_cycle_in_order_and_every_nth_when_asked() {
    let name = unique("trace");
    let (stop, program) = program(&name);
    let seg = wait_for(Duration::from_secs(10), || DynSegment::attach(&name).ok());
    let at = |p: &str| seg.locate(p).unwrap();
    let mut every = seg.trace(&[at("counter"), at("motor_on")], 1).unwrap();
    let other = DynSegment::attach(&name).unwrap();
    let mut third = other.trace(&[at("counter")], 3).unwrap();
    let mut rows = Vec::new();
    let mut thirds = Vec::new();
    while rows.len() < 300 {
        std::thread::sleep(Duration::from_millis(20));
        every.drain(&mut rows, usize::MAX);
        third.drain(&mut thirds, usize::MAX);
    }
    let rows: Vec<_> = rows
        .into_iter()
        .map(|e| match e {
            TraceEvent::Row(r) => r,
            TraceEvent::Lost(n) => panic!("{n} rows lost"),
        })
        .collect();
    for pair in rows.windows(2) {
        assert_eq!(
            pair[1].cycle,
            pair[0].cycle + 1,
            "no cycle lost or repeated"
        );
        assert!(pair[1].time_ns > pair[0].time_ns);
    }
    for r in &rows {
        // The counter counts the program's cycles: its value is the row's cycle number.
        assert_eq!(r.values[0], Value::UInt(r.cycle));
        assert_eq!(r.values[1], Value::Bool(false));
    }
    let thirds: Vec<u64> = thirds
        .into_iter()
        .filter_map(|e| match e {
            TraceEvent::Row(r) => Some(r.cycle),
            TraceEvent::Lost(_) => None,
        })
        .collect();
    assert!(thirds.len() > 50);
    assert!(thirds.windows(2).all(|p| p[1] == p[0] + 3), "{thirds:?}");
    stop.stop();
    program.join().unwrap();
    assert!(every.ended());
}

/// A trace the owner cannot take now is refused with the owner's reason, not as waiting
/// writes: a second trace on one connection, a fifth trace on the program.
#[test]
fn a_trace_refused_for_now_says_why() {
    let name = unique("trace_busy");
    let (stop, program) = program(&name);
    let seg = wait_for(Duration::from_secs(10), || DynSegment::attach(&name).ok());
    let counter = [seg.locate("counter").unwrap()];
    let _first = seg.trace(&counter, 1).unwrap();
    let Err(again) = seg.trace(&counter, 1) else {
        panic!("a second trace on one connection was taken");
    };
    assert!(
        matches!(&again, ShmError::Busy { reason, .. } if reason.contains("one trace per connection")),
        "{again}"
    );
    let tools: Vec<DynSegment> = (0..4).map(|_| DynSegment::attach(&name).unwrap()).collect();
    let traces: Vec<_> = tools[..3]
        .iter()
        .map(|t| t.trace(&counter, 1).unwrap())
        .collect();
    let Err(fifth) = tools[3].trace(&counter, 1) else {
        panic!("a fifth trace was taken");
    };
    let text = fifth.to_string();
    assert!(
        matches!(fifth, ShmError::Busy { .. }) && text.contains("traces run already"),
        "{text}"
    );
    assert!(!text.contains("writes wait"), "{text}");
    drop(traces);
    stop.stop();
    program.join().unwrap();
}

/// Force, release and trace messages from a tool that skips every check: values the program's
/// type does not take (NaN for a REAL, a number out of an INT's range, no such variable or
/// element) are refused by the owner, random bytes with those tags are answered as
/// malformed, and the program keeps cycling.
#[test]
fn the_owner_refuses_hostile_forces_and_traces() {
    use plc_io::shm::protocol::{self, Release, WriteRequest};
    let name = unique("force_hostile");
    let (stop, program) = program(&name);
    let seg = wait_for(Duration::from_secs(10), || DynSegment::attach(&name).ok());
    let setpoint = seg.index_of("setpoint").unwrap();
    let speeds = seg.index_of("speeds").unwrap();
    let bad = [
        Write {
            index: setpoint,
            leaf: 0,
            value: Value::Real(f64::NAN),
        },
        Write {
            index: speeds,
            leaf: 3,
            value: Value::Int(1 << 40),
        },
        Write {
            index: speeds,
            leaf: 300,
            value: Value::Int(1),
        },
        Write {
            index: 99,
            leaf: 0,
            value: Value::Int(1),
        },
    ];
    for (id, w) in bad.into_iter().enumerate() {
        let bytes = protocol::encode_force(&WriteRequest {
            id: id as u64 + 1000,
            writes: vec![w],
        });
        seg.send_raw(&bytes).unwrap();
    }
    // Random bytes behind each command's tag, and traces of values that are no such thing.
    let mut noise = 0x9E37_79B9_7F4A_7C15u64;
    for _ in 0..300 {
        noise ^= noise << 13;
        noise ^= noise >> 7;
        noise ^= noise << 17;
        let len = (noise % 200) as usize;
        let mut bytes: Vec<u8> = (0..len).map(|k| (noise >> (k % 8 * 8)) as u8).collect();
        if let Some(b) = bytes.first_mut() {
            *b = 3 + (noise % 3) as u8;
        }
        seg.send_raw(&bytes).unwrap();
    }
    let trace = protocol::encode_trace(&protocol::TraceRequest {
        id: 7,
        every: 1,
        values: vec![(99, 0)],
    });
    seg.send_raw(&trace).unwrap();
    let release = protocol::encode_release(&Release {
        id: 8,
        restore: true,
        all: false,
        values: vec![(speeds, 100_000)],
    });
    seg.send_raw(&release).unwrap();
    // Still cycling, nothing forced, and a correct force still works.
    let before = seg.status().cycle_count;
    wait_for(Duration::from_secs(5), || {
        (seg.status().cycle_count > before + 10).then_some(())
    });
    assert_eq!(seg.status().forces, 0);
    assert!(
        seg.status().writes_discarded > 0,
        "random bytes are malformed"
    );
    force(&seg, "speeds", 3, Value::Int(12)).unwrap();
    assert_eq!(seg.read_element("speeds", 3).unwrap(), Value::Int(12));
    assert_eq!(seg.forces().unwrap().len(), 1);
    stop.stop();
    program.join().unwrap();
}
