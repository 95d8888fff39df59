//! The `plc` command against a real program in another process: the test binary runs itself
//! as the control program (`PLC_TEST_ROLE=owner`), and each test drives the `plc` binary.

use plc_core::{FixedString, GlobalMemory, Time};
mod common;

use common::{ChildGuard, SpawnGuarded, plc, stderr, stdout, terminate, wait_until};
use plc_io::shm::BusClocks;
use plc_io::{BusState, IoBackend, IoError, IoStatus, Runtime};
use plc_test_support::TmuxSession;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

#[derive(GlobalMemory, Debug, Clone)]
pub struct Gm {
    /// Digital inputs
    #[plc(link = "ethercat.io.inputs", direction = "input")]
    inputs: u16,
    #[plc(source = "inputs", bit = 2)]
    door_closed: bool,
    #[plc(direction = "command", initial = 100)]
    speed_setpoint: u16,
    #[plc(direction = "status")]
    speed_actual: u16,
    #[plc(read_only, initial = 7)]
    serial: u32,
    #[plc(direction = "command", initial = "none")]
    recipe: FixedString<16>,
    counter: u64,
    table: [i16; 3],
    #[plc(direction = "command", initial = "T#1.5s")]
    dwell: Time,
}

/// Runs as the control program when `PLC_TEST_ROLE=owner`.
#[test]
fn owner_role() {
    if std::env::var("PLC_TEST_ROLE").as_deref() != Ok("owner") {
        return;
    }
    let segment = std::env::var("SEGMENT").unwrap();
    Runtime::<Gm>::builder()
        .period(Duration::from_millis(5))
        .segment(segment)
        .build()
        .expect("the runtime's settings are valid")
        .run(|ctx| {
            ctx.gm.counter += 1;
            ctx.gm.speed_actual = ctx.gm.speed_setpoint;
        })
        .unwrap();
}

struct Owner {
    child: ChildGuard,
    segment: String,
}

impl Owner {
    fn start(test: &str) -> Owner {
        Owner::start_as(test, "owner")
    }

    /// Starts the program of `<role>_role`.
    fn start_as(test: &str, role: &str) -> Owner {
        let segment = format!("cli_{test}_{}", std::process::id());
        let child = Command::new(std::env::current_exe().unwrap())
            .args([&format!("{role}_role"), "--exact", "--nocapture"])
            .env("PLC_TEST_ROLE", role)
            .env("SEGMENT", &segment)
            .stdout(Stdio::null())
            .spawn_guarded()
            .unwrap();
        let owner = Owner { child, segment };
        wait_until("the owner to start", || {
            plc(&["get", &owner.segment, "counter"]).status.success()
        });
        owner
    }
}

impl Drop for Owner {
    fn drop(&mut self) {
        terminate(&mut self.child);
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
    use std::os::unix::process::CommandExt;
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
        let mut cmd = Command::new(&plc_bin);
        cmd.args(args).env(plc_io::shm::RUNTIME_DIR_ENV, &dir);
        // SAFETY: only async-signal-safe calls between fork and exec.
        unsafe {
            cmd.pre_exec(|| {
                if libc::setgroups(0, std::ptr::null()) != 0
                    || libc::setgid(65534) != 0
                    || libc::setuid(65534) != 0
                {
                    return Err(std::io::Error::last_os_error());
                }
                Ok(())
            });
        }
        cmd.output_guarded().unwrap()
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

#[test]
fn log_stopped_with_ctrl_c_keeps_its_rows() {
    let owner = Owner::start("logint");
    let file = std::env::temp_dir().join(format!("plc-logint-{}.csv", std::process::id()));
    let _ = std::fs::remove_file(&file);
    let mut child = Command::new(env!("CARGO_BIN_EXE_plc"))
        .args(["log", &owner.segment, "counter", "--csv"])
        .arg(&file)
        .args(["--rate", "50"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn_guarded()
        .unwrap();
    wait_until("the CSV header", || {
        std::fs::read_to_string(&file).is_ok_and(|c| c.starts_with("time_s,cycle,counter\n"))
    });
    // Well under the once-a-second flush: only the signal handling can save these rows.
    std::thread::sleep(Duration::from_millis(300));
    child.signal(libc::SIGINT);
    let o = child.into_output().unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    let csv = std::fs::read_to_string(&file).unwrap();
    let rows = csv.lines().count() - 1;
    assert!(rows >= 3, "{csv}");
    assert!(
        stderr(&o).contains(&format!("{rows} rows written")),
        "{}",
        stderr(&o)
    );
}

#[test]
fn a_rate_too_small_for_a_period_is_refused_not_a_panic() {
    let owner = Owner::start("tinyrate");
    let file = std::env::temp_dir().join(format!("plc-tinyrate-{}.csv", std::process::id()));
    for command in ["log", "watch"] {
        let mut args = vec![command, &owner.segment];
        if command == "log" {
            args.extend(["counter", "--csv", file.to_str().unwrap()]);
        }
        args.extend(["--rate", "1e-300"]);
        let o = plc(&args);
        assert_eq!(o.status.code(), Some(1), "{command}: {}", stderr(&o));
        assert!(
            stderr(&o).contains("--rate must be between"),
            "{}",
            stderr(&o)
        );
    }
    let _ = std::fs::remove_file(&file);
}

#[test]
fn list_shows_a_killed_programs_leftover_instead_of_hiding_it() {
    let mut owner = Owner::start("killedlist");
    owner.child.signal(libc::SIGKILL);
    let _ = owner.child.wait();
    let o = plc(&["list"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    let line = out
        .lines()
        .find(|l| l.starts_with(&owner.segment))
        .unwrap_or_else(|| panic!("not listed:\n{out}"));
    assert!(line.contains("gone"), "{out}");
    assert!(out.contains("is gone; restart it"), "{out}");
}

#[test]
fn log_records_values_to_csv() {
    let owner = Owner::start("log");
    let file = std::env::temp_dir().join(format!("plc-log-{}.csv", std::process::id()));
    let o = plc(&[
        "log",
        &owner.segment,
        "counter",
        "recipe",
        "--csv",
        file.to_str().unwrap(),
        "--rate",
        "50",
        "--seconds",
        "0.5",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let csv = std::fs::read_to_string(&file).unwrap();
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(lines[0], "time_s,cycle,counter,recipe");
    assert!(lines.len() > 10, "{csv}");
    let counters: Vec<u64> = lines[1..]
        .iter()
        .map(|l| l.split(',').nth(2).unwrap().parse().unwrap())
        .collect();
    assert!(counters.windows(2).all(|w| w[0] <= w[1]) && counters.last() > counters.first());
}

#[test]
fn export_prints_the_declaration_as_json() {
    let owner = Owner::start("export");
    let json: serde_json::Value =
        serde_json::from_str(&stdout(&plc(&["export", &owner.segment]))).unwrap();
    let v = &json["variables"];
    assert_eq!(v["inputs"]["type"], "u16");
    assert_eq!(v["inputs"]["link"], "ethercat.io.inputs");
    assert_eq!(v["door_closed"]["source"], "inputs");
    assert_eq!(v["door_closed"]["bit"], 2);
    assert_eq!(v["recipe"]["max_length"], 16);
    assert_eq!(v["recipe"]["initial"], "none");
    assert_eq!(v["serial"]["read_only"], true);
    assert_eq!(v["table"]["dims"], serde_json::json!([3]));
    assert_eq!(v["dwell"]["type"], "LTIME");
    assert_eq!(v["dwell"]["initial"], "T#1.5s");
}

#[test]
fn watch_shows_live_values_filters_and_writes_in_tmux() {
    if !TmuxSession::available() {
        eprintln!("SKIPPED: tmux is not installed (scripts/test.sh installs it)");
        return;
    }
    let owner = Owner::start("watch");
    let cmd = format!(
        "{} watch {} --rate 20",
        env!("CARGO_BIN_EXE_plc"),
        owner.segment
    );
    let session = TmuxSession::start("plcwatch", 150, 30, &cmd).unwrap();
    let screen = || session.screen();
    let counter_value = |s: &str| -> Option<u64> {
        s.lines()
            .find(|l| l.contains("│counter"))?
            .split_whitespace()
            .nth(3)?
            .parse()
            .ok()
    };
    wait_until("the watch window", || screen().contains("speed_setpoint"));
    let first = counter_value(&screen());
    wait_until("the counter to change on screen", || {
        counter_value(&screen()) != first
    });
    assert!(
        screen().contains("└ door_closed"),
        "bools under their word:\n{}",
        screen()
    );
    let header = screen();
    assert!(
        header.contains("owner running (pid")
            && header.contains("cycle time last/min/mean/max")
            && header.contains("overruns"),
        "owner state and cycle statistics in the header:\n{header}"
    );

    session.send_keys(&["/", "speed_set", "Enter"]);
    assert!(header.contains("1.5 s"), "a duration in seconds:\n{header}");
    wait_until("the filter", || screen().contains("1 of 9 variables"));
    assert!(!screen().contains("│counter"));
    session.send_keys(&["Enter", "2500", "Enter"]);
    wait_until("the write to reach the program", || {
        stdout(&plc(&["get", &owner.segment, "speed_actual"])).contains("= 2500")
    });
    // The window says so once the program applied it (the write waits for its answer).
    wait_until("the window to confirm the write", || {
        screen().contains("wrote speed_setpoint = 2500")
    });
    // A forced value is marked, and the header counts the forces.
    assert!(
        plc(&["force", &owner.segment, "speed_setpoint=3000"])
            .status
            .success()
    );
    wait_until("the force marked", || {
        let s = screen();
        s.contains("F 3000") && s.contains("1 forced (F)")
    });
    assert!(plc(&["unforce", &owner.segment, "--all"]).status.success());
    wait_until("the mark gone", || !screen().contains("F 3000"));
    session.send_keys(&["q"]);
    wait_until("watch to quit", || !session.is_running());
}

#[test]
fn import_writes_the_struct_or_nothing() {
    let dir = std::env::temp_dir().join(format!("plc-import-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let good = dir.join("good.json");
    std::fs::write(
        &good,
        r#"{ "variables": { "speed": { "type": "u16", "initial": 3 } } }"#,
    )
    .unwrap();
    let out = dir.join("gm.rs");
    let o = plc(&[
        "import",
        good.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "--struct",
        "Line",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let code = std::fs::read_to_string(&out).unwrap();
    assert!(
        code.contains("pub struct Line")
            && code.contains("#[plc(initial = 3, description = \"\")]"),
        "{code}"
    );

    let bad = dir.join("bad.json");
    std::fs::write(&bad, r#"{ "variables": { "speed": { "type": "u16", "initial": -3 }, "ton": { "type": "bool" } } }"#).unwrap();
    let o = plc(&["import", bad.to_str().unwrap(), "-o", out.to_str().unwrap()]);
    assert!(!o.status.success());
    let err = stderr(&o);
    assert!(
        err.contains("variables.speed.initial") && err.contains("variables.ton"),
        "{err}"
    );
    assert_eq!(
        std::fs::read_to_string(&out).unwrap(),
        code,
        "nothing was written"
    );
}

/// `plc export --csv` and `plc import --csv` are the JSON pair's equals: the CSV export of a
/// running program imports to the struct its JSON export imports to, and a bad table is refused
/// with its lines named and nothing written.
#[test]
fn csv_export_and_import_agree_with_json() {
    let owner = Owner::start("export_csv");
    let dir = std::env::temp_dir().join(format!("plc-import-csv-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let csv = plc(&["export", &owner.segment, "--csv"]);
    assert!(csv.status.success(), "{}", stderr(&csv));
    let table = stdout(&csv);
    assert!(
        table.starts_with("name,type,direction,link,description,initial,source,bit,max_length,nonvolatile,read_only,at,dims,ux,quantity\r\n"),
        "{table}"
    );
    assert!(
        table.contains("\r\nrecipe,string,command,,,none,,,16,,,,,,\r\n"),
        "{table}"
    );
    let json = plc(&["export", &owner.segment]);
    // One file name in two folders, so the generated comments are the same too; no `.csv`
    // ending, so `--csv` is what makes it read as CSV.
    let (csv_file, json_file) = (dir.join("csv/vars"), dir.join("json/vars"));
    std::fs::create_dir_all(dir.join("csv")).unwrap();
    std::fs::create_dir_all(dir.join("json")).unwrap();
    std::fs::write(&csv_file, &csv.stdout).unwrap();
    std::fs::write(&json_file, &json.stdout).unwrap();
    let from_csv = plc(&["import", "--csv", csv_file.to_str().unwrap()]);
    let from_json = plc(&["import", json_file.to_str().unwrap()]);
    assert!(from_csv.status.success(), "{}", stderr(&from_csv));
    assert_eq!(stdout(&from_csv), stdout(&from_json));

    let out = dir.join("gm.rs");
    std::fs::write(&out, "// old\n").unwrap();
    let bad = dir.join("bad.csv");
    std::fs::write(&bad, "name,type,bit\nspeed,u16,\nton,bool,x\n").unwrap();
    let o = plc(&["import", bad.to_str().unwrap(), "-o", out.to_str().unwrap()]);
    assert!(!o.status.success());
    let err = stderr(&o);
    assert!(
        err.contains("line 3, variable ton: invalid variable name")
            && err.contains("line 3, variable ton, column bit: needs `source`"),
        "{err}"
    );
    assert_eq!(std::fs::read_to_string(&out).unwrap(), "// old\n");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `plc bus show` prints the process image of the main example's bus description, and names
/// the file and the problem of one it cannot use.
#[test]
fn bus_show_prints_the_process_image_and_refuses_a_bad_file() {
    let file = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../examples/bus/tensile_tester.toml"
    );
    let o = plc(&["bus", "show", file]);
    assert!(o.status.success(), "{}", stderr(&o));
    let table = stdout(&o);
    let rows: Vec<Vec<&str>> = table
        .lines()
        .map(|l| l.split_whitespace().collect())
        .collect();
    assert_eq!(
        rows[0],
        [
            "pos",
            "device",
            "entry",
            "direction",
            "byte.bit",
            "bits",
            "type"
        ]
    );
    assert!(
        rows.contains(&vec!["0", "coupler", "(no", "process", "data)"]),
        "{table}"
    );
    assert!(
        rows.contains(&vec![
            "1",
            "impact67_0",
            "digital_inputs",
            "input",
            "0.0",
            "4",
            "UINT"
        ]),
        "{table}"
    );
    assert!(
        rows.contains(&vec![
            "2",
            "impact67_0",
            "digital_outputs",
            "output",
            "0.0",
            "16",
            "UINT"
        ]),
        "{table}"
    );
    assert!(
        rows.contains(&vec!["3", "lamps", "horn", "output", "0.3", "1", "BOOL"]),
        "{table}"
    );

    let dir = std::env::temp_dir().join(format!("plc-bus-show-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let bad = dir.join("bad.toml");
    std::fs::write(
        &bad,
        "[[devices]]\nname = \"1st\"\nidentity = { vendor = 2, product = 3 }\n",
    )
    .unwrap();
    let o = plc(&["bus", "show", bad.to_str().unwrap()]);
    assert!(!o.status.success());
    let err = stderr(&o);
    assert!(
        err.contains("bad.toml") && err.contains("`1st` is not an identifier"),
        "{err}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `plc bus show` lists the distributed clocks of a description whose devices take SYNC0.
#[test]
fn bus_show_lists_the_devices_sync0_and_shift() {
    let dir = std::env::temp_dir().join(format!("plc-bus-show-dc-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("dc.toml");
    let mut bus = plc_rules::bus::BusConfig {
        devices: vec![
            plc_rules::bus::devices::ek1100("coupler"),
            plc_rules::bus::devices::el2004("lamps"),
        ],
    };
    bus.devices[1].dc = Some(plc_rules::bus::DcConfig {
        sync0: plc_rules::time::Time::from_millis(2),
        shift: plc_rules::time::Time::from_micros(300),
    });
    std::fs::write(&file, bus.to_toml_string()).unwrap();
    let o = plc(&["bus", "show", file.to_str().unwrap()]);
    std::fs::remove_dir_all(&dir).unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    let clocks: Vec<Vec<&str>> = text
        .lines()
        .skip_while(|l| *l != "distributed clocks:")
        .map(|l| l.split_whitespace().collect())
        .collect();
    assert!(clocks.len() >= 3, "{text}");
    assert_eq!(clocks[1], ["pos", "device", "sync0", "shift"], "{text}");
    assert_eq!(clocks[2], ["1", "lamps", "2ms", "300us"], "{text}");
}

/// `plc bus scan --sim` names the entries a CoE device's EEPROM leaves unnamed from its object
/// dictionary (SDO information service): the EL3004's values and the AKD's CiA 402 objects.
#[test]
fn bus_scan_names_coe_entries_from_the_object_dictionary() {
    let o = plc(&["bus", "scan", "--sim", "EK1100,EL3004,AKD"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    let bus = plc_rules::bus::BusConfig::from_toml_str(&text).unwrap();
    let value = &bus.devices[1].entries[9];
    assert_eq!(
        (value.name.as_str(), value.iec_type.as_str()),
        ("value_1", "INT")
    );
    assert_eq!(
        bus.devices[2].entries,
        plc_rules::bus::devices::akd("").entries,
        "{text}"
    );
    assert!(
        !text.contains("name = \"x"),
        "no entry named by its object index: {text}"
    );
}

/// `plc bus scan --sim` scans a simulated bus in its own process: the TOML it prints is a bus
/// description of those terminals that `BusConfig` reads, `--out` writes the same text (a
/// symlink in its place is replaced, not followed) and `plc bus show` takes the file.
#[test]
fn bus_scan_of_a_simulated_bus_prints_a_description_that_reads_back() {
    let o = plc(&["bus", "scan", "--sim", "EK1100,el1004,EL2889,EL2004"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    let bus = plc_rules::bus::BusConfig::from_toml_str(&text).unwrap();
    let names: Vec<_> = bus.devices.iter().map(|d| d.name.as_str()).collect();
    assert_eq!(names, ["ek1100", "el1004", "el2889", "el2004"]);
    assert_eq!(bus.devices[2].entries.len(), 16);
    assert_eq!(bus.devices[1].identity.product, 0x03ec_3052);

    let dir = std::env::temp_dir().join(format!("plc-bus-scan-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let elsewhere = dir.join("elsewhere.toml");
    std::fs::write(&elsewhere, "keep me").unwrap();
    let out = dir.join("scanned.toml");
    std::os::unix::fs::symlink(&elsewhere, &out).unwrap();
    let o = plc(&[
        "bus",
        "scan",
        "--sim",
        "EK1100,EL1004,EL2889,EL2004",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(std::fs::read_to_string(&out).unwrap(), text);
    assert!(!std::fs::symlink_metadata(&out).unwrap().is_symlink());
    assert_eq!(std::fs::read_to_string(&elsewhere).unwrap(), "keep me");
    let o = plc(&["bus", "show", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let table = stdout(&o);
    assert!(
        table
            .lines()
            .any(|l| l.split_whitespace().collect::<Vec<_>>()
                == ["2", "el2889", "output_16", "output", "1.7", "1", "BOOL"]),
        "{table}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A terminal the simulator does not model, or no bus at all, is refused with what to write.
#[test]
fn bus_scan_refuses_an_unknown_terminal_and_a_missing_bus() {
    let o = plc(&["bus", "scan", "--sim", "EK1100,EL9999"]);
    assert!(!o.status.success());
    let err = stderr(&o);
    assert!(
        err.contains("`EL9999` is not a simulated terminal")
            && err.contains("EK1100, EL1004, EL2004, EL2828, EL2889, EL3004"),
        "{err}"
    );
    let o = plc(&["bus", "scan"]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("--interface"), "{}", stderr(&o));
}
