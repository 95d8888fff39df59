//! Durations as tools see them: a running program's `LTIME` variables read through the segment
//! without the Rust type (as `plc get` reads them), written through the mailbox from a typed
//! duration literal (as `plc set` writes them), and named `LTIME` in the descriptor.

mod common;

use common::{unique, wait_for};
use plc_core::fb::Ton;
use plc_core::{GlobalMemory, IecType, Time, Value};
use plc_io::shm::{DynSegment, LayoutDescriptor, OwnerState};
use plc_io::{Context, Runtime};
use std::time::Duration;

#[derive(GlobalMemory, Debug, Clone)]
pub struct Gm {
    /// How long the clamp must be closed before the test starts.
    #[plc(direction = "command", initial = "T#1.5s")]
    settle_time: Time,
    #[plc(direction = "input")]
    clamp_closed: bool,
    #[plc(direction = "status")]
    settle_elapsed: Time,
    #[plc(direction = "status")]
    settled: bool,
}

#[test]
fn a_tool_reads_and_writes_durations_of_a_running_program() {
    let name = unique("durations");
    let builder = Runtime::<Gm>::builder()
        .period(Duration::from_millis(2))
        .segment(&name)
        .handle_signals(false);
    let stop = builder.stop_handle();
    let program = std::thread::spawn(move || {
        let mut settle = Ton::default();
        builder
            .build()
            .expect("the runtime's settings are valid")
            .run(move |ctx: &mut Context<Gm>| {
                ctx.gm.clamp_closed = true;
                ctx.gm.settled = settle.call(ctx.now(), ctx.gm.clamp_closed, ctx.gm.settle_time);
                ctx.gm.settle_elapsed = settle.ET;
            })
            .unwrap()
    });
    let seg = wait_for(Duration::from_secs(5), || DynSegment::attach(&name).ok());
    wait_for(Duration::from_secs(5), || {
        (seg.owner_state() == OwnerState::Running && seg.status().cycle_count > 2).then_some(())
    });
    let settle = &seg.descriptor().variables[0];
    assert_eq!((settle.iec_type, settle.size), (IecType::Ltime, 8));
    let json = serde_json::to_string(seg.descriptor()).unwrap();
    assert!(json.contains("\"LTIME\""), "{json}");
    assert_eq!(
        seg.read("settle_time").unwrap().to_string(),
        "LTIME#1s500ms",
        "as `plc get` prints it"
    );
    let elapsed = seg.read("settle_elapsed").unwrap();
    assert!(
        matches!(elapsed, Value::Time(t) if t > Time::ZERO && t < Time::from_millis(1500)),
        "{elapsed}"
    );
    // `plc set dwell=T#10ms`: the text typed, parsed for the variable's type, then written.
    let typed = Value::parse("T#10ms", IecType::Ltime).unwrap();
    seg.write("settle_time", typed).unwrap();
    wait_for(Duration::from_secs(5), || {
        (seg.read("settled").ok()? == Value::Bool(true)).then_some(())
    });
    assert_eq!(
        seg.read("settle_elapsed").unwrap(),
        Value::Time(Time::from_millis(10))
    );
    assert!(
        seg.write("settle_time", Value::Int(10)).is_err(),
        "a bare number is refused"
    );
    stop.stop();
    let gm = program.join().unwrap();
    assert_eq!(gm.settle_time, Time::from_millis(10));
    assert_eq!(
        LayoutDescriptor::of::<Gm>().variables[2].iec_type,
        IecType::Ltime
    );
}
