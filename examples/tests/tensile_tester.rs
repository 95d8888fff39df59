//! The main example as a user runs it: `tensile_tester --cycles N` on the simulated bus, as a
//! real process, with its own segment and retain directory.

use std::path::PathBuf;
use std::process::{Command, Output};

use plc_test_support::{ChildGuard, SpawnGuarded};

/// Runs `tensile_tester` with `args` to its end, on a segment and a retain directory of its
/// own named after `test`; returns its output and that directory.
fn run_to_end(test: &str, args: &[&str]) -> (Output, PathBuf) {
    let id = std::process::id();
    let retain = std::env::temp_dir().join(format!("tensile-{test}-{id}"));
    let out = Command::new(env!("CARGO_BIN_EXE_tensile_tester"))
        .args(args)
        .args(["--segment", &format!("tt_{test}_{id}")])
        .arg("--retain")
        .arg(&retain)
        .output_guarded()
        .expect("tensile_tester starts");
    (out, retain)
}

#[test]
fn tensile_tester_runs_n_cycles_on_the_simulated_bus_and_exits_0() {
    let (out, retain) = run_to_end("test", &["--cycles", "300"]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        out.status.success(),
        "exit {:?}\nstdout:\n{stdout}\nstderr:\n{stderr}",
        out.status
    );
    assert!(
        stdout.contains("tensile_tester: simulated bus with"),
        "{stdout}"
    );
    assert!(
        stdout.contains("tensile_tester: stopped,") && stdout.contains("bus back in INIT"),
        "{stdout}"
    );
    assert!(
        retain.join("tensile_tester.retain").is_file(),
        "retained values saved in {}",
        retain.display()
    );
    let _ = std::fs::remove_dir_all(&retain);
}

#[test]
fn tensile_tester_refuses_an_unknown_option_with_its_usage_and_exit_1() {
    let out = Command::new(env!("CARGO_BIN_EXE_tensile_tester"))
        .arg("--cycle")
        .output_guarded()
        .expect("tensile_tester starts");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains("unknown option `--cycle`") && stderr.contains("usage: tensile_tester"),
        "{stderr}"
    );
}

#[test]
fn tensile_tester_refuses_a_cpu_the_process_may_not_use_before_the_bus_starts() {
    let (out, retain) = run_to_end("cpu", &["--cpu", "100000"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains("the cycle cannot run on CPU 100000: this process may run on CPUs"),
        "{stderr}"
    );
    assert!(!retain.exists(), "nothing was made: {}", retain.display());
}

/// A running `tensile_tester`, killed if the test fails before stopping it.
struct Program(ChildGuard);

/// Starts `tensile_tester` on segment `segment` with retain directory `retain`, until stopped.
fn start(segment: &str, retain: &std::path::Path) -> Program {
    let child = Command::new(env!("CARGO_BIN_EXE_tensile_tester"))
        .args(["--segment", segment])
        .arg("--retain")
        .arg(retain)
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn_guarded()
        .expect("tensile_tester starts");
    Program(child)
}

/// The program's segment once it runs (the bus comes up first: allow a busy machine time).
fn attach(segment: &str) -> plc_io::shm::DynSegment {
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(60);
    loop {
        if let Ok(seg) = plc_io::shm::DynSegment::attach(segment) {
            return seg;
        }
        assert!(std::time::Instant::now() < deadline, "no segment {segment}");
        std::thread::sleep(std::time::Duration::from_millis(50));
    }
}

/// SIGTERM, as a service manager stops it; returns its exit status and what it printed.
fn terminate(program: Program) -> (std::process::ExitStatus, String) {
    let mut child = program.0;
    child.signal(libc::SIGTERM);
    let out = child.into_output().expect("tensile_tester exits");
    (
        out.status,
        String::from_utf8_lossy(&out.stdout).into_owned(),
    )
}

#[test]
fn a_setpoint_written_by_the_hmi_reader_is_applied_retained_and_restored_after_sigterm() {
    let id = std::process::id();
    let segment = format!("tt_hmi_{id}");
    let retain = std::env::temp_dir().join(format!("tensile-hmi-{id}"));
    let program = start(&segment, &retain);
    let seg = attach(&segment);
    let hmi = Command::new(env!("CARGO_BIN_EXE_hmi_reader"))
        .args([&segment, "test_speed_mm_s=3.5", "--seconds", "1"])
        .output_guarded()
        .expect("hmi_reader starts");
    assert!(
        hmi.status.success(),
        "hmi_reader: {}",
        String::from_utf8_lossy(&hmi.stderr)
    );
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(10);
    while seg.read("test_speed_mm_s").unwrap() != plc_core::Value::Real(3.5) {
        assert!(
            std::time::Instant::now() < deadline,
            "the setpoint never arrived"
        );
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    // The step timers are function blocks that tools reach by path: the test step's runs
    // while the machine is testing.
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(20);
    loop {
        let image = seg.snapshot_bytes().unwrap();
        let value = |path: &str| seg.locate(path).unwrap().var.value_in(&image, 0);
        let running = value("test_timeout.IN") == Some(plc_core::Value::Bool(true));
        let elapsed = matches!(value("test_timeout.ET"), Some(plc_core::Value::Time(t)) if t > plc_core::Time::ZERO);
        if running && elapsed {
            break;
        }
        assert!(
            std::time::Instant::now() < deadline,
            "the test step's timer never ran"
        );
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    drop(seg);

    let (status, stdout) = terminate(program);
    assert!(status.success(), "exit {status:?} after SIGTERM\n{stdout}");
    assert!(stdout.contains("tensile_tester: stopped,"), "{stdout}");
    assert!(
        plc_io::shm::DynSegment::attach(&segment).is_err(),
        "the segment is removed at a clean stop"
    );

    // The setpoint is nonvolatile: the next start restores it from the retain file.
    let program = start(&segment, &retain);
    let seg = attach(&segment);
    assert_eq!(
        seg.read("test_speed_mm_s").unwrap(),
        plc_core::Value::Real(3.5)
    );
    drop(seg);
    let (status, stdout) = terminate(program);
    assert!(status.success(), "exit {status:?}\n{stdout}");
    let _ = std::fs::remove_dir_all(&retain);
}

#[test]
fn a_final_save_that_fails_makes_tensile_tester_exit_1_and_say_so() {
    let id = std::process::id();
    let segment = format!("tt_lost_{id}");
    let retain = std::env::temp_dir().join(format!("tensile-lost-{id}"));
    let Program(mut child) = start(&segment, &retain);
    drop(attach(&segment));
    // The retain directory disappears under the running program (a failed disk does the same).
    std::fs::remove_dir_all(&retain).expect("the program created its retain directory");
    child.signal(libc::SIGTERM);
    let out = child.into_output().expect("tensile_tester exits");
    let (stdout, stderr) = (
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr),
    );
    assert_eq!(out.status.code(), Some(1), "{stdout}\n{stderr}");
    assert!(stderr.contains("not saved at stop"), "{stderr}");
    assert!(!stdout.contains("retained values saved"), "{stdout}");
    let _ = std::fs::remove_dir_all(&retain);
}

#[test]
fn the_crosshead_pulls_during_a_test_and_stops_when_the_specimen_breaks() {
    use plc_core::Value;
    let id = std::process::id();
    let segment = format!("tt_axis_{id}");
    let retain = std::env::temp_dir().join(format!("tensile-axis-{id}"));
    let program = start(&segment, &retain);
    let seg = attach(&segment);
    // One image per look, so the values read together belong to one cycle.
    let seg = &seg;
    let look = || {
        let image = seg.snapshot_bytes().unwrap();
        move |path: &str| {
            seg.locate(path)
                .unwrap()
                .var
                .value_in(&image, 0)
                .unwrap_or_else(|| panic!("{path} has no value"))
        }
    };
    let real = |v: Value| match v {
        Value::Real(r) => r,
        v => panic!("not a REAL: {v:?}"),
    };
    const TESTING: Value = Value::UInt(3);
    const DONE: Value = Value::UInt(4);
    const CONTINUOUS_MOTION: Value = Value::UInt(4);
    const STOPPING: Value = Value::UInt(5);

    // A test: the crosshead runs at the test speed (2 mm/s) and the elongation follows it.
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(30);
    let (mut first, mut last) = (None, 0.0);
    loop {
        let at = look();
        if at("machine_state") == TESTING && at("crosshead.state") == CONTINUOUS_MOTION {
            let position = real(at("crosshead.actual_position"));
            let elongation = real(at("elongation_mm"));
            let start = real(at("test_start_mm"));
            assert!(
                (position - start - elongation).abs() < 0.05,
                "elongation {elongation} mm at {position} mm from {start} mm"
            );
            assert!(
                position >= last,
                "the crosshead went back: {position} < {last}"
            );
            first.get_or_insert(position);
            last = position;
        } else if first.is_some() {
            break;
        }
        assert!(
            std::time::Instant::now() < deadline,
            "no test pulled (crosshead at {last} mm)"
        );
        std::thread::sleep(std::time::Duration::from_millis(10));
    }
    let pulled = last - first.unwrap();
    assert!(pulled > 2.0, "the crosshead pulled {pulled} mm");

    // The break ends the test with MC_Stop: the crosshead comes to rest and is held there.
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(2);
    loop {
        let at = look();
        if at("machine_state") == DONE && at("stop.Done") == Value::Bool(true) {
            assert_eq!(at("crosshead.state"), STOPPING);
            assert_eq!(at("cr_test_drive"), Value::Bool(false));
            assert_eq!(real(at("crosshead.set_velocity")), 0.0);
            break;
        }
        assert!(
            std::time::Instant::now() < deadline,
            "the crosshead did not stop"
        );
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
    // The drive follows its set point to rest within a few cycles.
    std::thread::sleep(std::time::Duration::from_millis(150));
    let at = look();
    let rest = real(at("crosshead.actual_position"));
    assert!(
        rest >= last && rest < last + 0.5,
        "stopped at {rest} mm after {last} mm"
    );
    assert!(real(at("crosshead.actual_velocity")).abs() < 0.01);
    std::thread::sleep(std::time::Duration::from_millis(150));
    let at = look();
    assert_eq!(at("machine_state"), DONE);
    let now = real(at("crosshead.actual_position"));
    assert!(
        (now - rest).abs() < 1e-3,
        "held where it stopped: {now} mm, {rest} mm"
    );

    let (status, stdout) = terminate(program);
    assert!(status.success(), "exit {status:?}\n{stdout}");
    assert!(
        stdout.contains(" testing | crosshead ") && stdout.contains(" mm continuous motion |"),
        "the status line shows the crosshead pulling:\n{stdout}"
    );
    let _ = std::fs::remove_dir_all(&retain);
}

#[test]
fn a_drive_fault_faults_the_machine_and_cmd_reset_resets_the_drive() {
    use plc_core::Value;
    let id = std::process::id();
    let segment = format!("tt_fault_{id}");
    let retain = std::env::temp_dir().join(format!("tensile-fault-{id}"));
    let program = start(&segment, &retain);
    let seg = attach(&segment);
    let wait = |what: &str, f: &dyn Fn() -> bool| {
        let deadline = std::time::Instant::now() + std::time::Duration::from_secs(20);
        while !f() {
            assert!(std::time::Instant::now() < deadline, "{what}");
            std::thread::sleep(std::time::Duration::from_millis(20));
        }
    };
    wait("the crosshead powered", &|| {
        let image = seg.snapshot_bytes().unwrap();
        seg.locate("power.Status").unwrap().var.value_in(&image, 0) == Some(Value::Bool(true))
    });
    // The drive's target forced 190 mm away: the drive lags it by more than its following
    // error window and faults (16#8611), the program stops the machine.
    let target = seg.index_of("crosshead_target_position").unwrap();
    let far = seg
        .check_force(plc_core::write::Write {
            index: target,
            leaf: 0,
            value: Value::Int(20_000_000),
        })
        .unwrap();
    seg.force(&[far]).unwrap();
    wait("a fault", &|| {
        seg.read("machine_state").unwrap() == Value::UInt(5)
    });
    seg.release(&[(target, 0)], false).unwrap();
    assert_eq!(
        seg.read("fault_text").unwrap().to_string(),
        "crosshead drive fault 16#8611: reset to go on"
    );
    assert_eq!(seg.read("lamp_red").unwrap(), Value::Bool(true));
    std::thread::sleep(std::time::Duration::from_millis(300));
    assert_eq!(
        seg.read("machine_state").unwrap(),
        Value::UInt(5),
        "a fault waits for the operator"
    );
    // The operator's reset runs MC_Reset: the drive leaves its fault, the machine is idle.
    seg.write("cmd_reset", Value::Bool(true)).unwrap();
    wait("idle after the reset", &|| {
        seg.read("machine_state").unwrap() == Value::UInt(0)
    });
    assert_eq!(seg.read("fault_text").unwrap().to_string(), "");
    assert_eq!(seg.read("crosshead_error_code").unwrap(), Value::UInt(0));
    drop(seg);
    let (status, stdout) = terminate(program);
    assert!(status.success(), "exit {status:?}\n{stdout}");
    let _ = std::fs::remove_dir_all(&retain);
}
