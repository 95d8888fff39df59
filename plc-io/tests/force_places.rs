//! Forces written where the values lie (`GlobalMemory::struct_places`) through a running
//! `Runtime` whose program overwrites every forced value each cycle: a bit-mapped bool with
//! its bit of the source word, a source word with its bools, a structure's member in an
//! array, a string. The program reads the forced values, and publishes them whatever it
//! wrote; forces apply in the order given, as `set` would.

mod common;

use common::{run_program, unique, wait_for};
use plc_core::write::Write;
use plc_core::{FixedString, GlobalMemory, PlcStruct, Value};
use plc_io::shm::{DynSegment, SharedGlobalMemory};
use std::time::Duration;

#[derive(PlcStruct, Debug, Clone)]
pub struct Axis {
    enable: bool,
    position: f64,
    tag: FixedString<12>,
}

#[derive(GlobalMemory, Debug, Clone)]
pub struct Gm {
    flags: u16,
    #[plc(source = "flags", bit = 3)]
    ready: bool,
    lights: u8,
    #[plc(source = "lights", bit = 0)]
    red: bool,
    #[plc(source = "lights", bit = 7)]
    green: bool,
    axes: [Axis; 2],
    label: FixedString<20>,
    /// What the program read of the forced values, before it overwrote them.
    #[plc(direction = "status")]
    seen_ready: bool,
    #[plc(direction = "status")]
    seen_lights: u8,
    #[plc(direction = "status")]
    seen_position: f64,
    #[plc(direction = "status")]
    seen_label: FixedString<20>,
}

/// A program that records what it reads, then writes every forced value over.
fn program(name: &str) -> (plc_io::StopHandle, std::thread::JoinHandle<Gm>) {
    run_program(name, |ctx: &mut plc_io::Context<Gm>| {
        let gm = &mut ctx.gm;
        gm.seen_ready = gm.ready;
        gm.seen_lights = gm.lights;
        gm.seen_position = gm.axes[1].position;
        gm.seen_label = gm.label;
        gm.flags = 0;
        gm.ready = false;
        gm.lights = 0x7e;
        gm.red = false;
        gm.green = false;
        gm.axes[1].position = -1.0;
        gm.axes[1].tag.set("program");
        gm.label.set("the program's");
    })
}

fn force(seg: &DynSegment, path: &str, value: Value) {
    let at = seg.locate(path).unwrap();
    let checked = seg
        .check_force(Write {
            index: at.index,
            leaf: at.leaf,
            value,
        })
        .unwrap();
    seg.force(&[checked]).unwrap();
}

/// Waits until the published values satisfy `ok` (a force applies at the owner's next cycle).
fn settles(name: &str, ok: impl Fn(&Gm) -> bool) -> Gm {
    let reader = SharedGlobalMemory::<Gm>::attach(name).unwrap();
    wait_for(Duration::from_secs(5), || {
        let gm = reader.snapshot().ok()?;
        ok(&gm).then_some(gm)
    })
}

fn text(s: &str) -> Value {
    Value::Text(FixedString::from_str_truncate(s))
}

#[test]
fn forces_hold_where_the_values_lie_whatever_the_program_writes() {
    let name = unique("force_places");
    let (stop, program) = program(&name);
    let seg = wait_for(Duration::from_secs(10), || DynSegment::attach(&name).ok());
    force(&seg, "ready", Value::Bool(true));
    force(&seg, "lights", Value::UInt(0x81));
    force(&seg, "axes[1].position", Value::Real(2.5));
    force(&seg, "axes[1].tag", text("forced"));
    force(&seg, "label", text("held label"));
    let gm = settles(&name, |gm| gm.seen_label == "held label");
    // Published: the forced values and what they imply of their words and bools.
    assert_eq!(gm.flags, 1 << 3, "the bool's bit of its word");
    assert!(gm.ready);
    assert_eq!(gm.lights, 0x81);
    assert!(gm.red && gm.green, "the word's bools");
    assert_eq!(gm.axes[1].position, 2.5);
    assert_eq!(gm.axes[1].tag, "forced");
    assert_eq!(gm.axes[0].position, 0.0, "the other axis is the program's");
    assert_eq!(gm.label, "held label");
    // Read by the program: the forces applied before its tick too.
    assert!(gm.seen_ready);
    assert_eq!(gm.seen_lights, 0x81);
    assert_eq!(gm.seen_position, 2.5);

    // A bool forced after its forced word takes its bit from it, as a `set` would; released,
    // the word's force gives it back.
    force(&seg, "green", Value::Bool(false));
    let gm = settles(&name, |gm| !gm.green);
    assert_eq!((gm.lights, gm.seen_lights), (0x01, 0x01));
    assert!(gm.red);
    let green = seg.locate("green").unwrap();
    seg.release(&[(green.index, green.leaf)], false).unwrap();
    let gm = settles(&name, |gm| gm.green);
    assert_eq!(gm.lights, 0x81);

    // Released, the program's values stand.
    seg.release_all(false).unwrap();
    let gm = settles(&name, |gm| gm.label == "the program's");
    assert_eq!((gm.flags, gm.lights), (0, 0x7e));
    assert_eq!(gm.axes[1].position, -1.0);
    stop.stop();
    program.join().unwrap();
}
