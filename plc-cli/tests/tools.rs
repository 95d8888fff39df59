//! `plc log`, `export`, `watch` and `import` against a real program in another process (the
//! test binary runs itself as the control program, `PLC_TEST_ROLE=owner`).

mod common;
mod owner;

use common::{SpawnGuarded, plc, stderr, stdout, wait_until};
use owner::Owner;
use plc_test_support::TmuxSession;
use std::process::{Command, Stdio};
use std::time::Duration;

/// Runs as the control program when `PLC_TEST_ROLE=owner`.
#[test]
fn owner_role() {
    if std::env::var("PLC_TEST_ROLE").as_deref() == Ok("owner") {
        owner::run();
    }
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
    // A runtime directory of its own: a program that another test starts meanwhile clears
    // killed owners' leftovers from the directory it creates its segment in.
    let dir = std::env::temp_dir().join(format!("plc-killedlist-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let segment = format!("cli_killedlist_{}", std::process::id());
    let env = plc_io::shm::RUNTIME_DIR_ENV;
    let mut child = std::process::Command::new(std::env::current_exe().unwrap())
        .args(["owner_role", "--exact", "--nocapture"])
        .env("PLC_TEST_ROLE", "owner")
        .env("SEGMENT", &segment)
        .env(env, &dir)
        .stdout(std::process::Stdio::null())
        .spawn_guarded()
        .unwrap();
    let plc_here = |args: &[&str]| {
        std::process::Command::new(env!("CARGO_BIN_EXE_plc"))
            .args(args)
            .env(env, &dir)
            .output_guarded()
            .unwrap()
    };
    wait_until("the owner to start", || {
        plc_here(&["get", &segment, "counter"]).status.success()
    });
    child.signal(libc::SIGKILL);
    let _ = child.wait();
    let o = plc_here(&["list"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    let line = out
        .lines()
        .find(|l| l.starts_with(&segment))
        .unwrap_or_else(|| panic!("not listed:\n{out}"));
    assert!(line.contains("gone"), "{out}");
    assert!(out.contains("is gone; restart it"), "{out}");
    drop(child);
    let _ = std::fs::remove_dir_all(&dir);
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
    // The program declares an alarm: the alarm columns follow the others, and its row
    // fills them.
    assert!(
        table.starts_with("name,type,direction,link,description,initial,source,bit,max_length,nonvolatile,read_only,at,dims,ux,quantity,unit,deadband,alarm,alarm_severity,"),
        "{table}"
    );
    assert!(
        table.contains("\r\nrecipe,string,command,,,none,,,16,,,,,,,,,,,,,,,,,,,\r\n"),
        "{table}"
    );
    assert!(table.contains(",rpm,50.0,Overspeed,700,"), "{table}");
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
