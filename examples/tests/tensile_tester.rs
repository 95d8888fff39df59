//! The main example as a user runs it: `tensile_tester --cycles N` on the simulated bus, as a
//! real process, with its own segment and retain directory.

use std::path::PathBuf;
use std::process::{Command, Output};

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
        .output()
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
        .output()
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
struct Program(Option<std::process::Child>);

impl Drop for Program {
    fn drop(&mut self) {
        if let Some(mut child) = self.0.take() {
            let _ = child.kill();
            let _ = child.wait();
        }
    }
}

/// Starts `tensile_tester` on segment `segment` with retain directory `retain`, until stopped.
fn start(segment: &str, retain: &std::path::Path) -> Program {
    let child = Command::new(env!("CARGO_BIN_EXE_tensile_tester"))
        .args(["--segment", segment])
        .arg("--retain")
        .arg(retain)
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("tensile_tester starts");
    Program(Some(child))
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
fn terminate(mut program: Program) -> (std::process::ExitStatus, String) {
    let child = program.0.take().expect("running");
    // SAFETY: kill(2) on the pid of a child we spawned and have not reaped.
    assert_eq!(unsafe { libc::kill(child.id() as i32, libc::SIGTERM) }, 0);
    let out = child.wait_with_output().expect("tensile_tester exits");
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
        .output()
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
        let value = |path: &str| seg.value_at_location(&image, &seg.locate(path).unwrap());
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
    let mut program = start(&segment, &retain);
    drop(attach(&segment));
    // The retain directory disappears under the running program (a failed disk does the same).
    std::fs::remove_dir_all(&retain).expect("the program created its retain directory");
    let child = program.0.take().expect("running");
    // SAFETY: kill(2) on the pid of a child we spawned and have not reaped.
    assert_eq!(unsafe { libc::kill(child.id() as i32, libc::SIGTERM) }, 0);
    let out = child.wait_with_output().expect("tensile_tester exits");
    let (stdout, stderr) = (
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr),
    );
    assert_eq!(out.status.code(), Some(1), "{stdout}\n{stderr}");
    assert!(stderr.contains("not saved at stop"), "{stderr}");
    assert!(!stdout.contains("retained values saved"), "{stdout}");
    let _ = std::fs::remove_dir_all(&retain);
}
