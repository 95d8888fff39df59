//! The tensile tester's alarms in the real runtime, on the simulated bus with the machine's
//! model: a normal test raises none, an open guard door raises its alarm and holds the
//! machine, and the status block counts it.

use examples::tensile::{self, Gm, TickInfo, process_tick};
use plc_core::alarm::AlarmState;
use plc_io::Runtime;
use plc_io::ethercat::{BusConfig, EtherCatBackend, Options, Transport};
use plc_io::shm::DynSegment;
use std::os::unix::fs::DirBuilderExt;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// What the test sets and what the tick saw.
#[derive(Default, Debug)]
struct Probe {
    /// The tick opens the guard door before the program runs, as a force of the input would.
    door_open: bool,
    /// The most alarms active at once so far.
    most_active: usize,
    /// The door alarm's state and the unacknowledged count after the last cycle.
    door: Option<AlarmState>,
    unacknowledged: usize,
    tests_completed: u32,
    max_force_kn: f64,
    machine_state: u8,
    cycles: u64,
    /// Why the runtime did not start or stopped.
    error: Option<String>,
}

/// Polls `done` on the probe every 10 ms for up to 60 s (the first test takes about 6 s).
fn wait_until(probe: &Mutex<Probe>, what: &str, done: impl Fn(&Probe) -> bool) {
    let start = Instant::now();
    while !done(&probe.lock().unwrap()) {
        let error = probe.lock().unwrap().error.clone();
        assert!(error.is_none(), "the runtime ended: {error:?}");
        assert!(
            start.elapsed() < Duration::from_secs(60),
            "no {what} in 60 s: {:?}",
            probe.lock().unwrap()
        );
        std::thread::sleep(Duration::from_millis(10));
    }
}

#[test]
fn a_normal_test_raises_no_alarm_and_an_open_guard_door_raises_one_and_holds_the_machine() {
    let id = std::process::id();
    let segment = format!("tt_alarms_{id}");
    // The journal's directory must be private (the runtime refuses one others may write).
    let dir = std::env::temp_dir().join(format!("tensile-alarms-{id}"));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::DirBuilder::new().mode(0o700).create(&dir).unwrap();
    let config = BusConfig::from_toml_str(tensile::BUS_TOML).unwrap();
    let (transport, sim) = Transport::simulated(&config).unwrap();
    let _plant = tensile::plant::Plant::spawn(sim).unwrap();
    let backend = EtherCatBackend::<Gm>::new(config, transport, Options::simulated()).unwrap();
    let period = Duration::from_millis(1);
    let builder = Runtime::<Gm>::builder()
        .period(period)
        .segment(&segment)
        .alarm_journal(dir.join("tensile_tester.alarms"))
        .backend(backend);
    let stop = builder.stop_handle();
    let probe = Arc::new(Mutex::new(Probe::default()));
    let (seen, ended) = (probe.clone(), probe.clone());
    let runtime = std::thread::spawn(move || {
        let result = builder.build().and_then(|runtime| {
            runtime.run(|ctx| {
                let mut p = seen.lock().unwrap();
                if p.door_open {
                    ctx.gm.guard_door_open = true;
                }
                let info = TickInfo {
                    period,
                    inputs_valid: ctx.inputs_valid,
                    now: ctx.now(),
                };
                process_tick(&mut ctx.gm, info);
                let alarms = ctx.alarms();
                p.most_active = p.most_active.max(alarms.active());
                p.unacknowledged = alarms.unacknowledged();
                p.door = alarms.state("guard_door_open");
                p.tests_completed = ctx.gm.tests_completed;
                p.max_force_kn = ctx.gm.max_force_kn;
                p.machine_state = ctx.gm.machine_state;
                p.cycles += 1;
            })
        });
        if let Err(e) = &result {
            ended.lock().unwrap().error = Some(e.to_string());
        }
        result
    });

    wait_until(&probe, "test completed", |p| p.tests_completed >= 1);
    {
        let p = probe.lock().unwrap();
        assert_eq!(p.most_active, 0, "a normal test raised an alarm");
        assert!(
            p.max_force_kn > 5.0,
            "the test pulled: {} kN",
            p.max_force_kn
        );
    }

    probe.lock().unwrap().door_open = true;
    wait_until(&probe, "guard door alarm", |p| {
        p.door == Some(AlarmState::ActiveUnacknowledged) && p.unacknowledged == 1
    });
    // Any tool sees it: the status block counts the alarm.
    let seg = DynSegment::attach(&segment).unwrap();
    let start = Instant::now();
    while seg.status().alarms_unacknowledged != 1 {
        assert!(
            start.elapsed() < Duration::from_secs(20),
            "not in the status block"
        );
        std::thread::sleep(Duration::from_millis(10));
    }
    assert_eq!(seg.status().alarms_active, 1);
    // With the door open, no test starts (auto start asks every second).
    let completed = probe.lock().unwrap().tests_completed;
    std::thread::sleep(Duration::from_millis(1500));
    {
        let p = probe.lock().unwrap();
        assert_eq!(p.tests_completed, completed);
        assert!(
            matches!(p.machine_state, 0 | 4 | 5),
            "idle, done or fault, not running: {}",
            p.machine_state
        );
        assert_eq!(p.most_active, 1, "only the door alarm");
    }

    stop.stop();
    runtime.join().unwrap().unwrap();
    let _ = std::fs::remove_dir_all(&dir);
}
