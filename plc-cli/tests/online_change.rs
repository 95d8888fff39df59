//! Online changes of programs `plc run` hosts, in real processes: `plc change` asks the host,
//! which checks and tries the new module, plans the conversion, and the cycle swaps between
//! two cycles; the new code's effect, every kept value, the way back, the refusals (the
//! running program untouched), the probation, and the tensile tester changed while its bus is
//! in OP.

mod common;

use common::{ChildGuard, SpawnGuarded, plc, stderr, stdout, wait_until};
use plc_io::BusState;
use plc_io::shm::DynSegment;
use std::path::PathBuf;
use std::process::{Command, Output, Stdio};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

fn module(name: &str) -> PathBuf {
    common::built_module(name)
}

fn host(lib: &str, segment: &str) -> ChildGuard {
    host_with(lib, segment, &[])
}

/// `plc run` of module `lib` as `segment`, with `extra` arguments, once it takes changes.
fn host_with(lib: &str, segment: &str, extra: &[&str]) -> ChildGuard {
    let child = Command::new(env!("CARGO_BIN_EXE_plc"))
        .arg("run")
        .arg(module(lib))
        .args(["--segment", segment])
        .args(extra)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn_guarded()
        .unwrap();
    wait_until("the host to publish", || {
        DynSegment::attach(segment).is_ok()
    });
    wait_until("the change socket", || {
        plc(&["change", segment, "--back"]).status.code() == Some(1)
            && stderr(&plc(&["change", segment, "--back"])).contains("nothing to go back to")
    });
    child
}

fn value(segment: &str, name: &str) -> String {
    let out = stdout(&plc(&["get", segment, name]));
    out.trim().rsplit(" = ").next().unwrap_or("").to_string()
}

fn number(segment: &str, name: &str) -> i64 {
    value(segment, name).parse().unwrap()
}

fn change(segment: &str, lib: &str, extra: &[&str]) -> Output {
    let lib = module(lib);
    let mut args = vec!["change", segment, lib.to_str().unwrap()];
    args.extend_from_slice(extra);
    plc(&args)
}

#[test]
fn a_change_runs_the_new_code_with_every_value_kept_and_goes_back() {
    let segment = format!("chg_values_{}", std::process::id());
    let _host = host("libcounter.so", &segment);
    wait_until("some cycles", || number(&segment, "count") > 300);
    // Two forces: one on a value the next build keeps, one on a value it removes.
    assert!(
        plc(&["force", &segment, "inputs=4", "panic_at_cycle=0"])
            .status
            .success()
    );
    wait_until("the forced input's output", || {
        value(&segment, "outputs") == "1"
    });

    let out = change(&segment, "libcounter_v2.so", &["--reset", "last_now_us"]);
    let report = stdout(&out);
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(
        report.contains("forces released (the new build has no such value): panic_at_cycle"),
        "{report}"
    );
    // The kept force is held by the new segment, and the new build sees it.
    let forces = stdout(&plc(&["forces", &segment]));
    assert!(
        forces.contains("inputs") && !forces.contains("panic_at_cycle"),
        "{forces}"
    );
    assert_eq!(value(&segment, "outputs"), "1");
    assert!(
        report.contains("converted      1  count (UDINT to ULINT)"),
        "{report}"
    );
    assert!(
        report.contains("removed        1  panic_at_cycle"),
        "{report}"
    );
    assert!(report.contains("swapped before cycle"), "{report}");
    assert!(report.contains("probation passed"), "{report}");

    // The new code counts by two, from where the old one was; `speed` starts at its initial
    // value. Read together in one `get`, so the same cycle.
    let pair = || {
        let out = stdout(&plc(&["get", &segment, "count", "last_cycle"]));
        let nums: Vec<i64> = out
            .lines()
            .map(|l| l.rsplit(" = ").next().unwrap().parse().unwrap())
            .collect();
        (nums[0], nums[1])
    };
    let (c1, k1) = pair();
    std::thread::sleep(std::time::Duration::from_millis(50));
    let (c2, k2) = pair();
    assert_eq!(
        c2 - c1,
        2 * (k2 - k1),
        "two a cycle: {c1}@{k1} then {c2}@{k2}"
    );
    assert_eq!(value(&segment, "speed"), "2.5");
    let listed = stdout(&plc(&["list", &segment]));
    assert!(
        listed.contains("module `plc-test-module-counter-v2` (")
            && listed.contains("libcounter_v2.so), built 20")
            && listed.contains("; 1 online change since it started"),
        "{listed}"
    );

    // Back: the count narrows back (it fits), `panic_at_cycle` returns with its value at the
    // change, `speed` goes.
    let out = plc(&["change", &segment, "--back"]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(stdout(&out).contains("narrowed       1  count (ULINT to UDINT)"));
    assert_eq!(value(&segment, "panic_at_cycle"), "0");
    assert!(!plc(&["get", &segment, "speed"]).status.success());
    let (c1, k1) = pair();
    std::thread::sleep(std::time::Duration::from_millis(50));
    let (c2, k2) = pair();
    assert_eq!(c2 - c1, k2 - k1, "one a cycle again");
    let listed = stdout(&plc(&["list", &segment]));
    assert!(
        listed.contains("module `plc-test-module-counter` (")
            && listed.contains("; 2 online changes since it started"),
        "{listed}"
    );
}

#[test]
fn retained_values_follow_a_change_and_survive_a_restart_after_it() {
    let segment = format!("chg_retain_{}", std::process::id());
    let dir = std::env::temp_dir().join(format!("plc-chg-retain-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let retain = ["--retain", dir.to_str().unwrap()];
    let mut first = host_with("libcounter.so", &segment, &retain);
    let out = change(&segment, "libcounter_v2.so", &["--reset", "last_now_us"]);
    assert!(out.status.success(), "{}", stderr(&out));
    // `speed` is new and retained: the retain file follows the new declaration.
    assert!(plc(&["set", &segment, "speed=7.5"]).status.success());
    let file = dir.join(format!("{segment}.retain"));
    wait_until("the retain file to hold the new value", || {
        std::fs::read_to_string(&file).is_ok_and(|t| t.contains("\"speed\"") && t.contains("7.5"))
    });
    assert!(common::terminate(&mut first), "plc run stops cleanly");
    // The new build again, from the file: its retained value is back.
    let _again = host_with("libcounter_v2.so", &segment, &retain);
    assert_eq!(value(&segment, "speed"), "7.5");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn refused_changes_leave_the_running_program_untouched() {
    let segment = format!("chg_refused_{}", std::process::id());
    let _host = host("libcounter.so", &segment);
    let before = DynSegment::attach(&segment).unwrap().descriptor().clone();

    let out = change(&segment, "libcounter_v2.so", &[]);
    assert!(!out.status.success());
    assert!(stderr(&out).contains("`last_now_us`"), "{}", stderr(&out));

    let out = change(&segment, "libforeign.so", &[]);
    assert!(stderr(&out).contains("rustc 1.80.0"), "{}", stderr(&out));

    let dir = std::env::temp_dir().join(format!("plc-chg-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let writable = dir.join("libcounter_v2.so");
    std::fs::write(
        &writable,
        std::fs::read(module("libcounter_v2.so")).unwrap(),
    )
    .unwrap();
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(&writable, std::fs::Permissions::from_mode(0o664)).unwrap();
    let out = plc(&["change", &segment, writable.to_str().unwrap()]);
    assert!(stderr(&out).contains("writable"), "{}", stderr(&out));
    let link = dir.join("libcurrent.so");
    std::os::unix::fs::symlink(module("libcounter.so"), &link).unwrap();
    let out = plc(&["change", &segment, link.to_str().unwrap()]);
    assert!(stderr(&out).contains("symbolic link"), "{}", stderr(&out));
    let text = dir.join("libtext.so");
    std::fs::write(&text, "no module\n").unwrap();
    let out = plc(&["change", &segment, text.to_str().unwrap()]);
    assert!(stderr(&out).contains("not an ELF file"), "{}", stderr(&out));
    std::fs::remove_dir_all(&dir).unwrap();

    let seg = DynSegment::attach(&segment).unwrap();
    assert_eq!(seg.descriptor(), &before, "the same program runs");
    let n = number(&segment, "count");
    wait_until("it counts on", || number(&segment, "count") > n);
}

#[test]
fn a_module_that_panics_on_probation_is_swapped_back_outputs_untouched() {
    let segment = format!("chg_panics_{}", std::process::id());
    let _host = host("libcounter.so", &segment);
    assert!(plc(&["force", &segment, "inputs=4"]).status.success());
    wait_until("the output on", || value(&segment, "outputs") == "1");

    let out = change(&segment, "libpanics.so", &[]);
    assert!(!out.status.success());
    let err = stderr(&out);
    assert!(
        err.contains("swapped back: the program panicked: this build panics in its third cycle"),
        "{err}"
    );
    // The previous program runs on, as it was, and its output was never zeroed.
    let seg = DynSegment::attach(&segment).unwrap();
    assert!(seg.index_of("new_ticks").is_none());
    assert_eq!(value(&segment, "outputs"), "1");
    let n = number(&segment, "count");
    wait_until("it counts on", || number(&segment, "count") > n);
}

#[test]
fn the_tensile_tester_takes_a_new_build_with_its_bus_in_op() {
    let segment = format!("chg_tensile_{}", std::process::id());
    let _host = host("libtensile_tester.so", &segment);
    let seg = DynSegment::attach(&segment).unwrap();
    wait_until("the bus in OP", || seg.status().bus_state == BusState::Op);
    wait_until("the crosshead homed", || {
        value(&segment, "crosshead.homed") == "true"
    });

    // Watch the bus state through the change, every half millisecond.
    let watching = Arc::new(AtomicBool::new(true));
    let watcher = {
        let watching = watching.clone();
        let name = segment.clone();
        std::thread::spawn(move || {
            let seg = DynSegment::attach(&name).unwrap();
            let mut states = Vec::new();
            while watching.load(Ordering::Relaxed) {
                states.push(seg.status().bus_state);
                std::thread::sleep(std::time::Duration::from_micros(500));
            }
            states
        })
    };
    let out = change(&segment, "libtensile_tester.so", &[]);
    watching.store(false, Ordering::Relaxed);
    let states = watcher.join().unwrap();
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(
        stdout(&out).contains("swaps the code only"),
        "{}",
        stdout(&out)
    );
    assert!(
        !stdout(&out).contains("made again"),
        "the same layout keeps its segment: {}",
        stdout(&out)
    );
    assert!(states.len() > 10);
    assert!(
        states.iter().all(|s| *s == BusState::Op),
        "the bus left OP: {states:?}"
    );
    assert_eq!(value(&segment, "crosshead.homed"), "true");
    assert_eq!(seg.status().bus_state, BusState::Op);

    // A build linked to devices the running bus does not have needs a restart: refused, the
    // program and its bus untouched.
    let out = change(&segment, "libnew_program.so", &[]);
    assert!(!out.status.success());
    let err = stderr(&out);
    assert!(
        err.contains("links do not fit the running bus (a new device or PDO needs a restart)"),
        "{err}"
    );
    assert!(err.contains("el1004"), "{err}");
    let seg = DynSegment::attach(&segment).unwrap();
    assert!(seg.index_of("crosshead_position").is_some());
    assert_eq!(seg.status().bus_state, BusState::Op);
}

/// One sample of the moving crosshead, read from one image.
#[derive(Clone, Copy, Debug)]
struct Sample {
    bus: BusState,
    /// The program's count of its cycles in this state, from the same image.
    cycles: i64,
    position: i64,
    statusword: i64,
    following_error: i64,
}

#[test]
fn a_change_while_the_axis_moves_keeps_its_profile_and_the_drive_enabled() {
    let segment = format!("chg_moving_{}", std::process::id());
    let _host = host("libtensile_tester.so", &segment);
    let seg = DynSegment::attach(&segment).unwrap();
    wait_until("the bus in OP", || seg.status().bus_state == BusState::Op);
    wait_until("the crosshead homed", || {
        value(&segment, "crosshead.homed") == "true"
    });
    // The specimen centred and lifted, as the sensors would say: the machine goes on to its
    // test, the crosshead pulling at the test speed.
    let forced = plc(&["force", &segment, "impact67_0_digital_inputs=3"]);
    assert!(forced.status.success(), "{}", stderr(&forced));
    wait_until("the test running", || {
        value(&segment, "machine_state_name") == "testing"
    });
    wait_until("the crosshead moving", || {
        number(&segment, "crosshead_velocity") != 0
    });

    let watching = Arc::new(AtomicBool::new(true));
    let watcher = {
        let watching = watching.clone();
        let name = segment.clone();
        std::thread::spawn(move || {
            let seg = DynSegment::attach(&name).unwrap();
            let at = |path: &str| seg.locate(path).unwrap().var;
            let (cycles, pos, sw, fe) = (
                at("state_cycles"),
                at("crosshead_position"),
                at("crosshead_statusword"),
                at("crosshead_following_error"),
            );
            let int = |v: Option<plc_core::Value>| match v {
                Some(plc_core::Value::Int(i)) => i,
                Some(plc_core::Value::UInt(u)) => u as i64,
                other => panic!("not an integer: {other:?}"),
            };
            let mut samples = Vec::new();
            while watching.load(Ordering::Relaxed) {
                let image = seg.snapshot_bytes().unwrap();
                samples.push(Sample {
                    bus: seg.status().bus_state,
                    cycles: int(cycles.value_in(&image, 0)),
                    position: int(pos.value_in(&image, 0)),
                    statusword: int(sw.value_in(&image, 0)),
                    following_error: int(fe.value_in(&image, 0)),
                });
                std::thread::sleep(std::time::Duration::from_micros(500));
            }
            samples
        })
    };
    std::thread::sleep(std::time::Duration::from_millis(200));
    let out = change(&segment, "libtensile_tester.so", &[]);
    std::thread::sleep(std::time::Duration::from_millis(200));
    watching.store(false, Ordering::Relaxed);
    let samples = watcher.join().unwrap();
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(samples.len() > 100, "{} samples", samples.len());
    for s in &samples {
        assert_eq!(s.bus, BusState::Op, "the bus left OP: {s:?}");
        assert_eq!(
            s.statusword & 0x6F,
            0x27,
            "the drive left operation enabled: {s:?}"
        );
        assert!(s.following_error.abs() < 1_000, "following error: {s:?}");
    }
    // The profile goes on without a jump: the crosshead moves one way, and its speed per
    // cycle (from pairs of samples, each position with the program's cycle count of the same
    // image) changes smoothly, the swap's cycles included.
    let way = (samples[samples.len() - 1].position - samples[0].position).signum();
    assert_ne!(way, 0, "the crosshead did not move");
    let speeds: Vec<f64> = samples
        .windows(2)
        .filter(|w| w[1].cycles > w[0].cycles)
        .map(|w| {
            let moved = way * (w[1].position - w[0].position);
            assert!(moved >= 0, "it moved back: {w:?}");
            moved as f64 / (w[1].cycles - w[0].cycles) as f64
        })
        .collect();
    // A single pair can read a position one exchange late and the next one early (the
    // simulated drive's frame), a dip and a rise that cancel: the speed is taken over three
    // pairs, and no pair may be far above the test speed.
    let smooth: Vec<f64> = speeds
        .windows(3)
        .map(|w| w.iter().sum::<f64>() / 3.0)
        .collect();
    let mut sorted = speeds.clone();
    sorted.sort_by(f64::total_cmp);
    let usual = sorted[sorted.len() / 2];
    for pair in smooth.windows(2) {
        assert!(
            (pair[1] - pair[0]).abs() <= 0.3 * usual + 2.0,
            "the speed jumped from {} to {} increments a cycle: {speeds:?}",
            pair[0],
            pair[1]
        );
    }
    assert!(
        speeds.iter().all(|&v| v <= 1.5 * usual + 2.0),
        "a step far above the test speed ({usual} a cycle): {speeds:?}"
    );
    assert_eq!(value(&segment, "machine_state_name"), "testing");
    let fault = stdout(&plc(&["get", &segment, "fault_text"]));
    assert_eq!(fault.trim(), "fault_text =", "no fault");
}

#[test]
fn a_program_without_a_bus_takes_no_build_with_links() {
    let segment = format!("chg_nobus_{}", std::process::id());
    let _host = host("libcounter.so", &segment);
    let out = change(&segment, "libnew_program.so", &[]);
    assert!(!out.status.success());
    let err = stderr(&out);
    assert!(
        err.contains("runs without a bus") && err.contains("ethercat.el1004.input_1"),
        "{err}"
    );
    assert!(
        DynSegment::attach(&segment)
            .unwrap()
            .index_of("count")
            .is_some()
    );
}

#[test]
fn another_user_may_not_change_the_program() {
    // SAFETY: geteuid has no preconditions.
    if unsafe { libc::geteuid() } != 0 {
        eprintln!("skipped: switching to another uid needs root");
        return;
    }
    let base = std::env::temp_dir().join(format!("plc-chg-uid-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&base);
    let rt = base.join("rt");
    std::fs::create_dir_all(&rt).unwrap();
    use std::os::unix::fs::PermissionsExt;
    // `plc` where nobody may run it; the runtime dir private, as a program's is.
    std::fs::set_permissions(&base, std::fs::Permissions::from_mode(0o755)).unwrap();
    std::fs::set_permissions(&rt, std::fs::Permissions::from_mode(0o700)).unwrap();
    let segment = format!("chg_uid_{}", std::process::id());
    let _host = Command::new(env!("CARGO_BIN_EXE_plc"))
        .arg("run")
        .arg(module("libcounter.so"))
        .args(["--segment", &segment])
        .env(plc_io::shm::RUNTIME_DIR_ENV, &rt)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn_guarded()
        .unwrap();
    wait_until("the change socket", || {
        rt.join(format!("{segment}.change")).exists()
    });
    let bin =
        plc_test_support::install_executable(env!("CARGO_BIN_EXE_plc").as_ref(), &base).unwrap();
    let lib = module("libcounter_v2.so");
    let out = common::as_nobody(
        Command::new(&bin)
            .args([
                "change",
                &segment,
                lib.to_str().unwrap(),
                "--reset",
                "last_now_us",
            ])
            .env(plc_io::shm::RUNTIME_DIR_ENV, &rt),
    )
    .output_guarded()
    .unwrap();
    assert!(!out.status.success());
    let err = stderr(&out);
    assert!(err.contains("is run by another user"), "{err}");
    // The program is the same one, counting on.
    let mut get = Command::new(env!("CARGO_BIN_EXE_plc"));
    get.args(["get", &segment, "panic_at_cycle"])
        .env(plc_io::shm::RUNTIME_DIR_ENV, &rt);
    assert!(
        get.output_guarded().unwrap().status.success(),
        "v1's variable is there"
    );
    std::fs::remove_dir_all(&base).unwrap();
}
