//! `plc run MODULE`: real program modules (built by `scripts/test.sh`) run by `plc` in another
//! process: the tensile tester on the simulated bus made from the description it was compiled
//! against, its drive homed, its retained values kept across a restart; the counter without
//! I/O, its panic a fault that zeroes nothing it should not and ends `plc run` with the
//! module's message.

mod common;

use common::{ChildGuard, SpawnGuarded, plc, stdout, terminate, wait_until};
use plc_io::BusState;
use plc_io::shm::DynSegment;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Duration;

fn module(name: &str) -> PathBuf {
    common::built_module(name)
}

fn test_dir(what: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("plc-run-{what}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// `plc run MODULE --segment SEGMENT --retain DIR`, its output in `DIR/plc-run.log`, once
/// its segment answers.
fn plc_run(lib: &Path, segment: &str, dir: &Path, extra: &[&str]) -> ChildGuard {
    let log = std::fs::File::create(dir.join("plc-run.log")).unwrap();
    let child = Command::new(env!("CARGO_BIN_EXE_plc"))
        .arg("run")
        .arg(lib)
        .args(["--segment", segment, "--retain"])
        .arg(dir)
        .args(extra)
        .stdout(log.try_clone().unwrap())
        .stderr(log)
        .stdin(Stdio::null())
        .spawn_guarded()
        .unwrap();
    wait_until("plc run to publish its segment", || {
        DynSegment::attach(segment).is_ok()
    });
    child
}

fn value(segment: &str, name: &str) -> String {
    let out = plc(&["get", segment, name]);
    stdout(&out)
        .trim()
        .rsplit(" = ")
        .next()
        .unwrap_or("")
        .to_string()
}

#[test]
fn the_tensile_tester_runs_as_a_module_on_its_own_simulated_bus() {
    let dir = test_dir("tensile");
    let segment = format!("run_tensile_{}", std::process::id());
    let lib = module("libtensile_tester.so");
    let mut child = plc_run(&lib, &segment, &dir, &[]);

    let seg = DynSegment::attach(&segment).unwrap();
    wait_until("the bus in OP", || seg.status().bus_state == BusState::Op);
    assert_eq!(seg.descriptor().variables.len(), 56);
    // The program powers and homes its crosshead through the simulated AKD: the drive, its
    // process data and the program's function blocks all run through the module.
    wait_until("the crosshead homed", || {
        value(&segment, "crosshead.homed") == "true"
    });
    let started = std::fs::read_to_string(dir.join("plc-run.log")).unwrap();
    assert!(
        started.contains("`tensile-tester-module`")
            && started.contains("simulated bus from `bus/tensile_tester.toml`")
            && started.contains("16 links"),
        "{started}"
    );

    // A retained value survives a stop and a start of the module.
    let set = plc(&["set", &segment, "test_speed_mm_s=3.25"]);
    assert!(set.status.success(), "{}", common::stderr(&set));
    assert!(terminate(&mut child), "plc run stops cleanly on SIGTERM");
    let _again = plc_run(&lib, &segment, &dir, &[]);
    assert_eq!(value(&segment, "test_speed_mm_s"), "3.25");
}

#[test]
fn a_panic_in_the_module_faults_the_program_with_its_message() {
    let dir = test_dir("panic");
    let segment = format!("run_panic_{}", std::process::id());
    let lib = module("libcounter.so");
    let mut child = plc_run(&lib, &segment, &dir, &["--period-us", "2000"]);
    wait_until("the counter to count", || {
        value(&segment, "count")
            .parse::<u32>()
            .is_ok_and(|n| n > 110)
    });
    // A forced input word (held through the module's memory by `set`, not by its places):
    // the module unpacks its bit 2 and packs its output bit.
    let forced = plc(&["force", &segment, "inputs=4"]);
    assert!(forced.status.success(), "{}", common::stderr(&forced));
    wait_until("the module to unpack and copy `start`", || {
        value(&segment, "outputs") == "1"
    });
    assert_eq!(value(&segment, "start"), "true");
    let cycle: u64 = value(&segment, "last_cycle").parse().unwrap();
    let at = (cycle + 200).to_string();
    assert!(
        plc(&["set", &segment, &format!("panic_at_cycle={at}")])
            .status
            .success()
    );
    let status = child
        .wait_timeout(Duration::from_secs(20))
        .unwrap()
        .expect("plc run ends after the panic");
    assert!(!status.success());
    let log = std::fs::read_to_string(dir.join("plc-run.log")).unwrap();
    assert!(
        log.contains(&format!(
            "the program panicked in cycle {at}: the program panicked: counter: asked to \
             panic in cycle {at}"
        )),
        "{log}"
    );
}

#[test]
fn a_module_that_cannot_run_is_refused_before_anything_starts() {
    let dir = test_dir("refused");
    let copy = dir.join("libcounter.so");
    std::fs::write(&copy, std::fs::read(module("libcounter.so")).unwrap()).unwrap();
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(&copy, std::fs::Permissions::from_mode(0o666)).unwrap();
    let out = plc(&["run", copy.to_str().unwrap(), "--segment", "never_made"]);
    assert!(!out.status.success());
    let err = common::stderr(&out);
    assert!(
        err.contains("is writable by its group") && err.contains("chmod go-w"),
        "{err}"
    );
    assert!(DynSegment::attach("never_made").is_err());
}
