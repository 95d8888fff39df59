//! The `plc` command against a real program in another process: the test binary runs itself
//! as the control program (`PLC_TEST_ROLE=owner`), and each test drives the `plc` binary:
//! `list`, `get`, `set` and who may write. The other commands: `tools.rs` (log, export,
//! watch, import) and `bus.rs`.

mod common;
mod owner;

use common::{SpawnGuarded, plc, stderr, stdout, wait_until};
use owner::{Gm, Owner};
use plc_core::FixedString;
use plc_io::shm::BusClocks;
use plc_io::{BusState, IoBackend, IoError, IoStatus, Runtime};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Runs as the control program when `PLC_TEST_ROLE=owner`.
#[test]
fn owner_role() {
    if std::env::var("PLC_TEST_ROLE").as_deref() == Ok("owner") {
        owner::run();
    }
}

#[test]
fn list_shows_programs_and_their_variables() {
    let owner = Owner::start("list");
    let all = stdout(&plc(&["list"]));
    assert!(
        all.contains(&owner.segment) && all.contains("running"),
        "{all}"
    );
    let vars = stdout(&plc(&["list", &owner.segment]));
    assert!(
        vars.contains("ethercat.io.inputs") && vars.contains("Digital inputs"),
        "{vars}"
    );
    assert!(
        vars.contains("└ door_closed") && vars.contains("bit 2 of inputs"),
        "{vars}"
    );
    assert!(
        vars.contains("STRING(16)") && vars.contains("INT[3]"),
        "{vars}"
    );
    let json: serde_json::Value =
        serde_json::from_str(&stdout(&plc(&["list", &owner.segment, "--json"]))).unwrap();
    assert_eq!(json["variables"].as_array().unwrap().len(), 9);
    assert!(vars.contains("LTIME"), "{vars}");
    let socket = plc_io::shm::runtime_dir().join(format!("{}.sock", owner.segment));
    assert!(
        plc(&["list", &socket.display().to_string()])
            .status
            .success(),
        "the socket's path works too"
    );
}

/// A bus whose distributed clocks agree within 3 ns, its cycle 120 us after SYNC0.
struct DcBus;

impl IoBackend<Gm> for DcBus {
    fn start(&mut self) -> Result<(), IoError> {
        Ok(())
    }
    fn stop(&mut self) {}
    fn exchange(&mut self, _: &mut Gm) -> IoStatus {
        IoStatus {
            inputs_valid: true,
            bus_fault: false,
            bus_state: BusState::Op,
            clocks: Some(BusClocks {
                sync0_period_ns: 1_000_000,
                max_time_difference_ns: Some(3),
                sync0_offset_ns: 120_000,
            }),
        }
    }
}

/// Runs as a control program on [`DcBus`] when `PLC_TEST_ROLE=dc_owner`.
#[test]
fn dc_owner_role() {
    if std::env::var("PLC_TEST_ROLE").as_deref() != Ok("dc_owner") {
        return;
    }
    Runtime::<Gm>::builder()
        .period(Duration::from_millis(5))
        .backend(DcBus)
        .segment(std::env::var("SEGMENT").unwrap())
        .build()
        .expect("the runtime's settings are valid")
        .run(|ctx| ctx.gm.counter += 1)
        .unwrap();
}

#[test]
fn list_shows_the_distributed_clocks_of_a_program_that_has_them() {
    let dc = Owner::start_as("dc", "dc_owner");
    let plain = Owner::start("nodc");
    let line = "dc: sync0 1 ms, clocks within 3 ns, cycle 120 us after SYNC0";
    let all = stdout(&plc(&["list"]));
    let after = |segment: &str| {
        let mut lines = all.lines().skip_while(|l| !l.starts_with(segment));
        lines.next();
        lines.next().unwrap_or("").trim().to_string()
    };
    assert_eq!(after(&dc.segment), line, "{all}");
    assert!(!after(&plain.segment).starts_with("dc:"), "{all}");
    let vars = stdout(&plc(&["list", &dc.segment]));
    assert!(vars.contains(&format!("\n{line}\n")), "{vars}");
    assert!(
        !stdout(&plc(&["list", &plain.segment])).contains("dc:"),
        "no clocks, no line"
    );
    let rows: serde_json::Value = serde_json::from_str(&stdout(&plc(&["list", "--json"]))).unwrap();
    let row = |segment: &str| {
        rows.as_array()
            .unwrap()
            .iter()
            .find(|r| r["name"] == segment)
            .unwrap_or_else(|| panic!("{segment} not listed: {rows}"))
            .clone()
    };
    assert_eq!(
        row(&dc.segment)["dc"],
        serde_json::json!({
            "sync0_period_ns": 1_000_000,
            "max_time_difference_ns": 3,
            "sync0_offset_ns": 120_000,
        })
    );
    assert_eq!(row(&plain.segment)["dc"], serde_json::Value::Null);
}

#[test]
fn get_and_set_reach_the_program() {
    let owner = Owner::start("getset");
    let s = owner.segment.as_str();
    let o = plc(&[
        "set",
        s,
        "speed_setpoint=1500",
        "recipe=\"steel, S235\"",
        "table[1]=-4",
        "dwell=t#2m_30.5s",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    wait_until("the write to apply", || {
        stdout(&plc(&["get", s, "speed_actual"])).contains("speed_actual = 1500")
    });
    let got = stdout(&plc(&["get", s, "recipe", "table", "table[1]", "serial"]));
    assert!(got.contains("recipe = steel, S235"), "{got}");
    assert!(
        got.contains("table = [0, -4, 0]") && got.contains("table[1] = -4"),
        "{got}"
    );
    assert!(got.contains("serial = 7"), "{got}");
    let dwell = stdout(&plc(&["get", s, "dwell"]));
    assert!(
        dwell.contains("dwell = 150.5 s"),
        "a duration in seconds: {dwell}"
    );

    // A STRING written by another tool with an escape sequence and a line end: `plc get`
    // shows it escaped, so a value cannot clear the terminal or forge an output line.
    let seg = plc_io::shm::DynSegment::attach(s).expect("attached");
    let hostile = FixedString::from_str_truncate("ok\u{1b}[2J\nx = 1");
    seg.write("recipe", plc_core::Value::Text(hostile))
        .expect("written");
    let got = stdout(&plc(&["get", s, "recipe"]));
    assert!(
        got.contains(r"recipe = ok\x1b[2J\nx = 1") && !got.contains('\u{1b}'),
        "{got:?}"
    );
    assert_eq!(got.lines().count(), 1, "{got:?}");
}

#[test]
fn set_refuses_bad_writes_and_writes_nothing() {
    let owner = Owner::start("refuse");
    let s = owner.segment.as_str();
    for (assignment, reason) in [
        ("inputs=1", "is an input"),
        ("speed_actual=1", "status variable"),
        ("serial=1", "read-only"),
        ("nope=1", "has no variable `nope`"),
        ("speed_setpoint=70000", "out of range for UINT"),
        ("speed_setpoint=fast", "whole number"),
        ("recipe=seventeen chars!!", "capacity of 16"),
        ("table[3]=1", "out of range"),
        ("dwell=5000", "a duration starts with T#"),
        ("dwell=T#1h75m", "must be below 60m"),
        ("speed_setpoint", "name=value"),
    ] {
        let o = plc(&["set", s, "speed_setpoint=999", assignment]);
        assert!(!o.status.success(), "{assignment} must be refused");
        assert!(stderr(&o).contains(reason), "{assignment}: {}", stderr(&o));
    }
    std::thread::sleep(Duration::from_millis(50));
    let got = stdout(&plc(&["get", s, "speed_setpoint"]));
    assert!(
        got.contains("speed_setpoint = 100"),
        "nothing was written: {got}"
    );
    assert!(!plc(&["get", "no_such_program", "x"]).status.success());
}

#[test]
fn a_batch_is_applied_in_one_cycle_and_a_program_that_takes_no_writes_is_reported() {
    let mut owner = Owner::start("batch");
    let s = owner.segment.as_str();
    // The program stops (as in a debugger): `plc set` waits a bounded time and says so.
    owner.child.signal(libc::SIGSTOP);
    let start = Instant::now();
    let o = plc(&["set", s, "speed_setpoint=999", "recipe=new", "table[0]=5"]);
    let waited = start.elapsed();
    owner.child.signal(libc::SIGCONT);
    assert!(!o.status.success());
    let err = stderr(&o);
    assert!(err.contains("did not answer"), "{err}");
    assert!(waited < Duration::from_secs(15), "waited {waited:?}");
    // One refused assignment and nothing of the batch is written.
    let o = plc(&["set", s, "speed_setpoint=999", "serial=1"]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("read-only"), "{}", stderr(&o));
    let got = stdout(&plc(&["get", s, "speed_setpoint"]));
    assert!(!got.contains("= 999"), "{got}");
    // A batch goes as one request, applied in one cycle.
    let o = plc(&["set", s, "speed_setpoint=5", "recipe=x", "table[1]=-2"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).contains("table[1] <- -2"), "{}", stdout(&o));
    let got = stdout(&plc(&["get", s, "speed_setpoint", "recipe", "table[1]"]));
    assert!(
        got.contains("speed_setpoint = 5") && got.contains("recipe = x") && got.contains("= -2"),
        "{got}"
    );
}

/// Runs as a control program that lets group `nogroup` read, in the runtime directory the
/// test names.
#[test]
fn shared_owner_role() {
    if std::env::var("PLC_TEST_ROLE").as_deref() != Ok("shared_owner") {
        return;
    }
    Runtime::<Gm>::builder()
        .period(Duration::from_millis(5))
        .segment(std::env::var("SEGMENT").unwrap())
        .read_group("nogroup")
        .build()
        .expect("the runtime's settings are valid")
        .run(|ctx| ctx.gm.counter += 1)
        .unwrap();
}

#[test]
fn set_by_a_user_the_program_does_not_let_write_reports_the_rule() {
    // SAFETY: geteuid has no preconditions.
    if unsafe { libc::geteuid() } != 0 {
        eprintln!("skipped: switching to another uid needs root");
        return;
    }
    let base = std::env::temp_dir().join(format!("plc-cli-policy-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&base);
    std::fs::create_dir(&base).unwrap();
    let dir = base.join("rt");
    let segment = format!("cli_policy_{}", std::process::id());
    let mut owner = Command::new(std::env::current_exe().unwrap())
        .args(["shared_owner_role", "--exact", "--nocapture"])
        .env("PLC_TEST_ROLE", "shared_owner")
        .env("SEGMENT", &segment)
        .env(plc_io::shm::RUNTIME_DIR_ENV, &dir)
        .stdout(Stdio::null())
        .spawn_guarded()
        .unwrap();
    // The `plc` binary where uid 65534 may run it: the build's own directory may be closed to
    // other users (a checkout in a private directory). Installed by a process of its own: a
    // copy written here could be held open by a child another test forks meanwhile.
    std::fs::set_permissions(&base, std::os::unix::fs::PermissionsExt::from_mode(0o755)).unwrap();
    let plc_bin =
        plc_test_support::install_executable(env!("CARGO_BIN_EXE_plc").as_ref(), &base).unwrap();
    let as_nobody = |args: &[&str]| {
        common::as_nobody(
            Command::new(&plc_bin)
                .args(args)
                .env(plc_io::shm::RUNTIME_DIR_ENV, &dir),
        )
        .output_guarded()
        .unwrap()
    };
    wait_until("the program to start", || {
        as_nobody(&["get", &segment, "counter"]).status.success()
    });
    let o = as_nobody(&["set", &segment, "speed_setpoint=1"]);
    let _ = owner.terminate();
    let _ = std::fs::remove_dir_all(&base);
    assert!(!o.status.success());
    let err = stderr(&o);
    assert!(
        err.contains("uid 65534")
            && err.contains(&format!("may not write `{segment}`"))
            && err.contains("only uid 0 may; see RuntimeBuilder::write_group"),
        "{err}"
    );
}
