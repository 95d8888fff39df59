//! The main example as a user runs it: `tensile_tester --cycles N` on the simulated bus, as a
//! real process, with its own segment and retain directory.

use std::process::Command;

#[test]
fn tensile_tester_runs_n_cycles_on_the_simulated_bus_and_exits_0() {
    let id = std::process::id();
    let retain = std::env::temp_dir().join(format!("tensile-test-{id}"));
    let out = Command::new(env!("CARGO_BIN_EXE_tensile_tester"))
        .args(["--cycles", "300", "--segment", &format!("tt_test_{id}")])
        .arg("--retain")
        .arg(&retain)
        .output()
        .expect("tensile_tester starts");
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
