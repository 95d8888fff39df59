//! The cycle: order of the steps, a panicking program, retained values across runs, stopping,
//! and shared memory seen from outside while it runs.

mod common;

use common::{kill9, role, spawn_role, unique, wait_for};
use plc_core::{GlobalMemory, Value};
use plc_io::retain::RetainStore;
use plc_io::shm::{DynSegment, OwnerState, RunState, SharedGlobalMemory, ShmError};
use plc_io::{BusState, Context, IoBackend, IoError, IoStatus, Runtime, RuntimeError};
use std::sync::{Arc, Mutex};
use std::time::Duration;

#[derive(GlobalMemory, Debug, Clone)]
pub struct Gm {
    #[plc(direction = "input")]
    inputs: u8,
    #[plc(source = "inputs", bit = 0)]
    start_button: bool,
    #[plc(direction = "output")]
    outputs: u8,
    #[plc(source = "outputs", bit = 1)]
    motor_on: bool,
    #[plc(direction = "output", initial = 50)]
    valve_pct: f32,
    #[plc(direction = "command", initial = 10)]
    setpoint: u16,
    #[plc(nonvolatile)]
    total_cycles: u64,
    seen_setpoint: u16,
}

/// A backend that feeds inputs and records what it was asked to do.
#[derive(Clone, Default)]
struct Recorder(Arc<Mutex<Vec<String>>>);

impl IoBackend<Gm> for Recorder {
    fn start(&mut self) -> Result<(), IoError> {
        self.0.lock().unwrap().push("start".into());
        Ok(())
    }
    fn exchange(&mut self, gm: &mut Gm) -> IoStatus {
        self.0
            .lock()
            .unwrap()
            .push(format!("exchange out={}", gm.outputs));
        gm.inputs = 1;
        IoStatus {
            inputs_valid: true,
            bus_fault: false,
            bus_state: BusState::Op,
            clocks: None,
        }
    }
    fn fault(&mut self, gm: &mut Gm) {
        self.0
            .lock()
            .unwrap()
            .push(format!("fault out={} valve={}", gm.outputs, gm.valve_pct));
    }
    fn stop(&mut self) {
        self.0.lock().unwrap().push("stop".into());
    }
}

#[test]
fn a_cycle_unpacks_inputs_runs_the_tick_and_packs_outputs() {
    let io = Recorder::default();
    let gm = Runtime::<Gm>::builder()
        .period(Duration::from_millis(1))
        .backend(io.clone())
        .max_cycles(3)
        .handle_signals(false)
        .build()
        .expect("the runtime's settings are valid")
        .run(|ctx: &mut Context<Gm>| {
            assert!(
                ctx.gm.start_button,
                "inputs arrive unpacked before the tick"
            );
            ctx.gm.motor_on = true;
        })
        .unwrap();
    assert_eq!(gm.outputs, 0b10);
    let log = io.0.lock().unwrap().clone();
    assert_eq!(
        log,
        [
            "start",
            "exchange out=0",
            "exchange out=2",
            "exchange out=2",
            "stop"
        ],
        "outputs packed in a cycle go out with the next exchange"
    );
}

#[test]
fn a_panicking_program_zeroes_outputs_and_faults_the_io() {
    let io = Recorder::default();
    let err = Runtime::<Gm>::builder()
        .period(Duration::from_millis(1))
        .backend(io.clone())
        .handle_signals(false)
        .build()
        .expect("the runtime's settings are valid")
        .run(|ctx| {
            ctx.gm.motor_on = true;
            if ctx.cycle == 3 {
                panic!("division by zero in the recipe");
            }
        })
        .unwrap_err();
    match err {
        RuntimeError::Panicked { cycle, message } => {
            assert_eq!(cycle, 3);
            assert!(message.contains("division by zero"));
        }
        other => panic!("{other}"),
    }
    let log = io.0.lock().unwrap().clone();
    assert!(log.contains(&"fault out=0 valve=0".to_string()), "{log:?}");
    assert_eq!(log.last().unwrap(), "stop");
}

#[test]
fn a_second_ctrl_c_ends_a_program_whose_cycle_never_returns() {
    if role().as_deref() == Some("hung_tick") {
        let name = std::env::var("SEGMENT").unwrap();
        let _ = Runtime::<Gm>::builder()
            .period(Duration::from_millis(1))
            .segment(&name)
            .build()
            .expect("the runtime's settings are valid")
            .run(|_| {
                loop {
                    std::thread::sleep(Duration::from_secs(1));
                }
            });
        return;
    }
    if role().is_some() {
        return;
    }
    let name = unique("hung");
    let mut child = spawn_role(
        "a_second_ctrl_c_ends_a_program_whose_cycle_never_returns",
        "hung_tick",
        &[("SEGMENT", name.clone())],
    );
    // The segment exists once the signal handlers are in place and the first cycle is due.
    wait_for(Duration::from_secs(10), || {
        SharedGlobalMemory::<Gm>::attach(&name).ok()
    });
    std::thread::sleep(Duration::from_millis(100));
    child.signal(libc::SIGINT);
    std::thread::sleep(Duration::from_millis(500));
    assert!(
        child.try_wait().unwrap().is_none(),
        "the first Ctrl-C only asks for a stop, which a hung cycle never reaches"
    );
    child.signal(libc::SIGINT);
    let status = (0..500).find_map(|_| {
        std::thread::sleep(Duration::from_millis(20));
        child.try_wait().unwrap()
    });
    let Some(status) = status else {
        kill9(&mut child);
        panic!("the second Ctrl-C did not end the program within 10 s");
    };
    assert_eq!(
        status.code(),
        Some(1),
        "the second Ctrl-C ends it: {status:?}"
    );
    // The next run takes the segment over, as after any crash (and removes it as it ends).
    drop(SharedGlobalMemory::<Gm>::create(&name).expect("the next run takes over"));
}

#[test]
fn nonvolatile_values_survive_a_restart_and_stop_works_from_outside() {
    let dir = std::env::temp_dir().join(format!("plc-rt-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("gm.retain");
    for run in 1..=2u64 {
        let gm = Runtime::<Gm>::builder()
            .period(Duration::from_millis(1))
            .retain(&path)
            .max_cycles(25)
            .handle_signals(false)
            .build()
            .expect("the runtime's settings are valid")
            .run(|ctx| ctx.gm.total_cycles += 1)
            .unwrap();
        assert_eq!(gm.total_cycles, 25 * run);
    }
    let builder = Runtime::<Gm>::builder()
        .period(Duration::from_millis(1))
        .handle_signals(false);
    let stop = builder.stop_handle();
    let t = std::thread::spawn(move || {
        builder
            .build()
            .expect("the runtime's settings are valid")
            .run(|_| {})
            .unwrap()
    });
    std::thread::sleep(Duration::from_millis(50));
    stop.stop();
    assert!(t.join().is_ok());
}

#[test]
fn tools_see_the_running_program_and_their_writes_arrive() {
    let name = unique("runtime");
    let builder = Runtime::<Gm>::builder()
        .period(Duration::from_millis(2))
        .segment(&name)
        .handle_signals(false);
    let stop = builder.stop_handle();
    let t = std::thread::spawn(move || {
        builder
            .build()
            .expect("the runtime's settings are valid")
            .run(|ctx| ctx.gm.seen_setpoint = ctx.gm.setpoint)
            .unwrap()
    });
    let seg = wait_for(Duration::from_secs(5), || DynSegment::attach(&name).ok());
    wait_for(Duration::from_secs(5), || {
        (seg.owner_state() == OwnerState::Running && seg.status().cycle_count > 2).then_some(())
    });
    seg.write("setpoint", Value::UInt(1234)).unwrap();
    let typed = SharedGlobalMemory::<Gm>::attach(&name).unwrap();
    wait_for(Duration::from_secs(5), || {
        (typed.snapshot().ok()?.seen_setpoint == 1234).then_some(())
    });
    let status = seg.status();
    assert_eq!(status.stats.period, Duration::from_millis(2));
    assert!(status.stats.max >= status.stats.min && status.writes_applied == 1);
    // Each cycle is stamped with the wall clock, for clients on other machines.
    let wall_now = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .unwrap()
        .as_nanos() as u64;
    let age = wall_now.saturating_sub(status.cycle_utc_ns);
    assert!(age < 2_000_000_000, "cycle stamped {age} ns ago");
    stop.stop();
    let gm = t.join().unwrap();
    assert_eq!(gm.setpoint, 1234);
    assert!(
        DynSegment::attach(&name).is_err(),
        "the segment is removed at stop"
    );
}

#[test]
fn context_for_test_runs_a_tick_without_bus_or_segment() {
    let mut ctx = Context::for_test(Gm::default());
    ctx.gm.start_button = true;
    ctx.gm.motor_on = ctx.gm.start_button && ctx.inputs_valid;
    assert!(ctx.gm.motor_on);
    assert_eq!(ctx.bus_state, BusState::NoBus);
}

#[test]
fn now_is_the_cycles_start_the_same_through_a_tick_and_never_going_back() {
    let mut seen: Vec<plc_core::Time> = Vec::new();
    let mut delay = plc_core::fb::Ton::default();
    let mut delay_done_at = None;
    Runtime::<Gm>::builder()
        .period(Duration::from_millis(1))
        .max_cycles(40)
        .handle_signals(false)
        .build()
        .expect("the runtime's settings are valid")
        .run(|ctx: &mut Context<Gm>| {
            let at_start = ctx.now();
            std::thread::sleep(Duration::from_micros(300));
            assert_eq!(ctx.now(), at_start, "one instant through the tick");
            if delay.call(at_start, true, plc_core::Time::from_millis(10))
                && delay_done_at.is_none()
            {
                delay_done_at = Some(at_start);
            }
            seen.push(at_start);
        })
        .unwrap();
    assert!(seen.windows(2).all(|w| w[0] < w[1]), "{seen:?}");
    // Cycles of at least 1 ms apart: 40 of them span at least 39 ms.
    let span = seen[39].saturating_sub(seen[0]);
    assert!(span >= plc_core::Time::from_millis(39), "{span}");
    let done = delay_done_at.expect("a 10 ms TON in 40 cycles of 1 ms");
    assert!(done.saturating_sub(seen[0]) >= plc_core::Time::from_millis(10));
}

#[test]
fn context_for_test_sets_and_advances_now() {
    let mut ctx = Context::for_test(Gm::default());
    assert_eq!(ctx.now(), plc_core::Time::ZERO);
    ctx.set_now(plc_core::Time::from_secs(5));
    ctx.advance(plc_core::Time::from_millis(250));
    assert_eq!(ctx.now(), plc_core::Time::from_millis(5250));
    ctx.advance(plc_core::Time::MAX);
    assert_eq!(ctx.now(), plc_core::Time::MAX, "saturates");
}

#[test]
fn a_panic_keeps_the_last_good_cycles_retained_values() {
    let dir = std::env::temp_dir().join(format!("plc-rt-panic-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("gm.retain");
    let _ = std::fs::remove_file(&path);
    let err = Runtime::<Gm>::builder()
        .period(Duration::from_millis(1))
        .retain(&path)
        .handle_signals(false)
        .build()
        .expect("the runtime's settings are valid")
        .run(|ctx| {
            ctx.gm.total_cycles += 1;
            if ctx.cycle == 3 {
                ctx.gm.total_cycles = 999; // half-way through a tick that then fails
                panic!("sensor table index out of range");
            }
        })
        .unwrap_err();
    assert!(matches!(err, RuntimeError::Panicked { cycle: 3, .. }));
    let mut gm = Gm::default();
    RetainStore::new(&path).load(&mut gm).unwrap();
    assert_eq!(
        gm.total_cycles, 2,
        "the values of the last completed cycle, not of the failed one"
    );
}

#[test]
fn after_a_panic_another_process_sees_the_owner_faulted() {
    if role().as_deref() == Some("faulting_program") {
        let err = Runtime::<Gm>::builder()
            .period(Duration::from_millis(2))
            .segment(std::env::var("SEGMENT").unwrap())
            .handle_signals(false)
            .build()
            .expect("the runtime's settings are valid")
            .run(|ctx| {
                if ctx.gm.setpoint == 4242 {
                    panic!("the operator found the bug");
                }
            })
            .unwrap_err();
        assert!(matches!(err, RuntimeError::Panicked { .. }));
        return;
    }
    if role().is_some() {
        return;
    }
    let name = unique("faulted");
    let mut child = spawn_role(
        "after_a_panic_another_process_sees_the_owner_faulted",
        "faulting_program",
        &[("SEGMENT", name.clone())],
    );
    let seg = wait_for(Duration::from_secs(10), || DynSegment::attach(&name).ok());
    wait_for(Duration::from_secs(5), || {
        (seg.owner_state() == OwnerState::Running).then_some(())
    });
    seg.write("setpoint", Value::UInt(4242)).unwrap();
    assert!(child.wait().unwrap().success());
    assert_eq!(seg.status().run_state, RunState::Faulted);
    let err = seg.snapshot_bytes().unwrap_err();
    assert_eq!(
        err,
        ShmError::Closed {
            name: name.clone(),
            faulted: true
        }
    );
    assert!(err.to_string().contains("faulted"), "{err}");
}

/// What `build` refuses, if it refuses.
fn refusal(builder: plc_io::RuntimeBuilder<Gm>) -> Option<RuntimeError> {
    builder.handle_signals(false).build().err()
}

#[test]
fn build_refuses_a_realtime_priority_outside_sched_fifos_range() {
    for priority in [0, 100, -1] {
        let err = refusal(Runtime::builder().realtime_priority(priority))
            .unwrap_or_else(|| panic!("priority {priority} was accepted"));
        let RuntimeError::Realtime(message) = &err else {
            panic!("not a priority error: {err}");
        };
        assert_eq!(
            message,
            &format!(
                "realtime priority {priority} is outside SCHED_FIFO's 1..=99; choose one in that \
                 range (higher runs first)"
            )
        );
    }
}

#[test]
fn build_refuses_an_unknown_group_naming_it_and_the_fix() {
    let name = unique("build_group");
    let err = refusal(
        Runtime::builder()
            .segment(&name)
            .write_group("no-such-group-plc"),
    )
    .expect("an unknown group was accepted");
    let RuntimeError::Shm(ShmError::Os { what, error, .. }) = &err else {
        panic!("not a group error: {err}");
    };
    assert_eq!(
        what,
        "cannot use group `no-such-group-plc` as the write group"
    );
    assert!(
        error.to_string().contains("groupadd no-such-group-plc"),
        "{error}"
    );
    // Nothing was made: no segment to attach to.
    assert!(matches!(
        DynSegment::attach(&name),
        Err(ShmError::NotFound(_))
    ));
}

#[test]
fn build_accepts_what_the_process_may_do_and_keeps_the_callers_scheduling() {
    // SAFETY: plain query of the calling thread's policy.
    let before = unsafe { libc::sched_getscheduler(0) };
    let built = Runtime::<Gm>::builder()
        .handle_signals(false)
        .realtime_priority(10)
        .build();
    match built {
        // Permitted: tried on a thread of its own, the caller stays as it was.
        Ok(_) => assert_eq!(unsafe { libc::sched_getscheduler(0) }, before),
        Err(RuntimeError::Realtime(why)) => {
            assert!(why.contains("is not permitted"), "{why}");
            assert!(why.contains("CAP_SYS_NICE"), "{why}");
        }
        Err(other) => panic!("unexpected refusal: {other}"),
    }
    assert!(Runtime::<Gm>::builder().build().is_ok());
}

#[test]
fn runtime_errors_keep_their_causes() {
    use std::error::Error;
    let io = RuntimeError::Io(IoError::new(std::io::Error::other("cable unplugged")));
    let cause = io.source().expect("the I/O error");
    assert_eq!(cause.to_string(), "cable unplugged");
    let inner = cause.source().expect("the backend's own error");
    assert!(inner.downcast_ref::<std::io::Error>().is_some());
    let shm = RuntimeError::Shm(ShmError::NotFound("press".into()));
    assert!(shm.source().unwrap().downcast_ref::<ShmError>().is_some());
    // The operating system's error stays whole under a shared-memory error.
    let os = ShmError::Os {
        name: "press".into(),
        what: "cannot listen on /run/plc-vars/press.sock".into(),
        error: plc_io::shm::Cause::system(std::io::Error::from_raw_os_error(libc::EADDRINUSE)),
    };
    let io = os
        .source()
        .unwrap()
        .downcast_ref::<std::io::Error>()
        .unwrap();
    assert_eq!(io.raw_os_error(), Some(libc::EADDRINUSE));
    assert!(
        os.to_string()
            .starts_with("segment `press`: cannot listen on"),
        "{os}"
    );
}
