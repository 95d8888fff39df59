//! Commissioning with real processes: `plc force`, `plc unforce`, `plc forces`, `plc trace`
//! and the alarm count of `plc list` against the main example and against a counting program
//! of this test binary (`PLC_TEST_ROLE=counter`) at 1 kHz and 4 kHz.

mod common;

use common::{ChildGuard, SpawnGuarded, plc, stderr, stdout, terminate, wait_until};
use plc_core::GlobalMemory;
use plc_io::Runtime;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Duration;

#[derive(GlobalMemory, Debug, Clone)]
pub struct Counter {
    /// Cycles run: after each tick, the cycle's number.
    #[plc(direction = "status")]
    counter: u64,
    /// On during every other second of cycles.
    #[plc(direction = "output")]
    blink: bool,
    #[plc(direction = "command", quantity = "velocity")]
    speed: f32,
}

/// Runs as the counting program when `PLC_TEST_ROLE=counter`, at `PERIOD_US`.
#[test]
fn counter_role() {
    if std::env::var("PLC_TEST_ROLE").as_deref() != Ok("counter") {
        return;
    }
    let segment = std::env::var("SEGMENT").unwrap();
    let period_us: u64 = std::env::var("PERIOD_US").unwrap().parse().unwrap();
    let per_second = 1_000_000 / period_us;
    Runtime::<Counter>::builder()
        .period(Duration::from_micros(period_us))
        .segment(segment)
        .build()
        .unwrap()
        .run(|ctx| {
            ctx.gm.counter += 1;
            ctx.gm.blink = (ctx.gm.counter / per_second) % 2 == 1;
        })
        .unwrap();
}

/// A program in another process, stopped (as Ctrl-C would) when dropped.
struct Program(ChildGuard);

impl Drop for Program {
    fn drop(&mut self) {
        terminate(&mut self.0);
    }
}

fn counter(segment: &str, period_us: u64) -> Program {
    let child = Command::new(std::env::current_exe().unwrap())
        .args(["counter_role", "--exact", "--nocapture"])
        .env("PLC_TEST_ROLE", "counter")
        .env("SEGMENT", segment)
        .env("PERIOD_US", period_us.to_string())
        .stdout(Stdio::null())
        .spawn_guarded()
        .unwrap();
    let p = Program(child);
    wait_until("the program to start", || {
        plc(&["get", segment, "counter"]).status.success()
    });
    p
}

/// The main example, stopped as Ctrl-C would when dropped, and its log.
fn tensile_tester(dir: &Path, segment: &str) -> (Program, PathBuf) {
    (
        Program(common::tensile_tester(dir, segment)),
        dir.join("tensile_tester.log"),
    )
}

fn scratch(test: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("plc-commissioning-{test}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn get(segment: &str, name: &str) -> String {
    let out = plc(&["get", segment, name]);
    assert!(out.status.success(), "{}", stderr(&out));
    stdout(&out)
        .trim()
        .split_once(" = ")
        .map(|(_, v)| v.to_string())
        .unwrap_or_default()
}

/// The last status line of the tensile tester's that shows its signal tower.
fn tower(log: &Path) -> Option<String> {
    let text = std::fs::read_to_string(log).ok()?;
    let line = text.lines().rev().find(|l| l.contains("| tower "))?;
    let tower = line.split("| tower ").nth(1)?;
    Some(tower.split(" |").next()?.trim().to_string())
}

#[test]
fn a_forced_lamp_lights_the_simulated_tower_and_a_forced_input_drives_the_program() {
    let dir = scratch("tower");
    let segment = format!("cm_tower_{}", std::process::id());
    let (program, log) = tensile_tester(&dir, &segment);
    // The program writes `lamp_red` FALSE every cycle (no fault): forced, the EL2004 shows it on.
    let out = plc(&["force", &segment, "lamp_red=true"]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert_eq!(stdout(&out).trim(), "lamp_red forced to true");
    wait_until("the tower's red lamp", || {
        tower(&log).is_some_and(|t| t.split(' ').nth(2) == Some("R"))
    });
    assert_eq!(get(&segment, "lamp_red"), "true");
    assert_eq!(
        get(&segment, "fault_text"),
        "",
        "no fault: the program writes it off"
    );
    // A write to it is refused, naming the force and who holds it.
    let refused = plc(&["set", &segment, "lamp_red=false"]);
    assert!(!refused.status.success());
    let why = stderr(&refused);
    assert!(why.contains("`lamp_red` is forced (by uid"), "{why}");
    let listed = stdout(&plc(&["forces", &segment]));
    assert!(
        listed.contains("lamp_red") && listed.contains("true"),
        "{listed}"
    );
    let list = stdout(&plc(&["list", &segment]));
    assert!(list.contains("1 value forced"), "{list}");

    // A forced input the logic reacts to: with the break detector forced on, the next test is
    // over in its first cycle of pulling, at almost no force.
    let before: u64 = get(&segment, "tests_completed").parse().unwrap();
    let out = plc(&["force", &segment, "specimen_broken=true"]);
    assert!(out.status.success(), "{}", stderr(&out));
    wait_until("a test with the break detector forced", || {
        get(&segment, "tests_completed").parse::<u64>().unwrap() > before
    });
    let max: f64 = get(&segment, "max_force_kn").parse().unwrap();
    assert!(
        max < 0.5,
        "the test ended at {max} kN: the forced break was not seen"
    );

    // Released: without --restore the program's next value stands; --all ends the rest.
    let out = plc(&["unforce", &segment, "lamp_red"]);
    assert!(out.status.success(), "{}", stderr(&out));
    wait_until("the tower's red lamp off", || {
        tower(&log).is_some_and(|t| t.split(' ').nth(2) == Some("r"))
    });
    let out = plc(&["unforce", &segment, "--all", "--restore"]);
    assert_eq!(
        stdout(&out).trim(),
        "1 force released (restored to the value before the force)"
    );
    assert!(stdout(&plc(&["forces", &segment])).contains("no forces held"));

    // Each force and release is in the program's log with its uid; a stop says what it ends.
    assert!(
        plc(&["force", &segment, "lamp_green=true"])
            .status
            .success()
    );
    let mut program = program;
    assert!(terminate(&mut program.0), "a clean stop");
    let text = std::fs::read_to_string(&log).unwrap();
    let uid = plc_io::shm::euid();
    for line in [
        format!("uid {uid} forces `lamp_red` = true"),
        format!("uid {uid} releases `lamp_red` (forced by uid {uid})"),
        format!("uid {uid} releases `specimen_broken` (forced by uid {uid}, false restored)"),
        "the program stops with 1 force held, which ends with it: `lamp_green` = true".into(),
    ] {
        assert!(text.contains(&line), "`{line}` in the log:\n{text}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_forced_guard_door_raises_the_tensile_testers_alarm_and_plc_list_counts_it() {
    let dir = scratch("door");
    let segment = format!("cm_door_{}", std::process::id());
    let (program, _log) = tensile_tester(&dir, &segment);
    let list = || stdout(&plc(&["list", &segment]));
    // Running normally, the machine has no alarm, so `plc list` prints no alarm line.
    let before = list();
    assert!(!before.contains("alarms:"), "{before}");
    let out = plc(&["force", &segment, "guard_door_open=true"]);
    assert!(out.status.success(), "{}", stderr(&out));
    wait_until("the guard door alarm in `plc list`", || {
        list().contains("alarms: 1 unacknowledged, 1 active")
    });
    // Closed again, the alarm goes but waits for an operator's acknowledgement.
    assert!(plc(&["unforce", &segment, "--all"]).status.success());
    wait_until("the alarm returned to normal, unacknowledged", || {
        list().contains("alarms: 1 unacknowledged, 0 active")
    });
    drop(program);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn unforce_with_restore_puts_back_the_value_from_before_the_force() {
    let segment = format!("cm_restore_{}", std::process::id());
    let _program = counter(&segment, 1000);
    assert!(plc(&["set", &segment, "speed=1.25"]).status.success());
    assert!(plc(&["force", &segment, "speed=9.5"]).status.success());
    assert_eq!(get(&segment, "speed"), "9.5");
    let out = plc(&["unforce", &segment, "speed", "--restore"]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert_eq!(get(&segment, "speed"), "1.25");
    // Not forced any more: a second release is refused, naming the value.
    let again = plc(&["unforce", &segment, "speed"]);
    assert!(
        stderr(&again).contains("`speed` is not forced"),
        "{}",
        stderr(&again)
    );
}

/// The rows of a trace CSV: (cycle, time_s, values...).
fn rows(csv: &Path) -> (Vec<String>, Vec<Vec<String>>) {
    let text = std::fs::read_to_string(csv).unwrap();
    let mut lines = text.lines();
    let header = lines
        .next()
        .unwrap()
        .split(',')
        .map(str::to_string)
        .collect();
    let rows = lines
        .map(|l| l.split(',').map(str::to_string).collect())
        .collect();
    (header, rows)
}

/// Every cycle, none lost or repeated, each row's counter its cycle number, time going on.
fn check_every_cycle(csv: &Path) {
    let (header, rows) = rows(csv);
    assert_eq!(header, ["cycle", "time_s", "counter", "blink"]);
    assert!(rows.len() > 1000, "{} rows", rows.len());
    let cycle = |r: &Vec<String>| r[0].parse::<u64>().unwrap();
    let time = |r: &Vec<String>| r[1].parse::<f64>().unwrap();
    for pair in rows.windows(2) {
        assert_eq!(cycle(&pair[1]), cycle(&pair[0]) + 1, "rows {pair:?}");
        assert!(time(&pair[1]) > time(&pair[0]), "time goes on: {pair:?}");
    }
    for r in &rows {
        assert_eq!(r[2], r[0], "the counter is the cycle's number: {r:?}");
    }
}

#[test]
fn a_trace_at_1_khz_and_4_khz_holds_every_cycle() {
    let dir = scratch("every");
    for period_us in [1000, 250] {
        let segment = format!("cm_trace_{period_us}_{}", std::process::id());
        let _program = counter(&segment, period_us);
        let csv = dir.join(format!("trace_{period_us}.csv"));
        let out = plc(&[
            "trace",
            &segment,
            "counter",
            "blink",
            "--for",
            "2s",
            "--out",
            csv.to_str().unwrap(),
        ]);
        assert!(out.status.success(), "{}", stderr(&out));
        assert!(stderr(&out).contains("rows written to"), "{}", stderr(&out));
        check_every_cycle(&csv);
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_trigger_keeps_exactly_pre_and_post_rows_and_the_plot_shows_them() {
    let dir = scratch("trigger");
    let segment = format!("cm_trigger_{}", std::process::id());
    let _program = counter(&segment, 1000);
    let now: u64 = get(&segment, "counter").parse().unwrap();
    let at = now + 1500;
    let csv = dir.join("trigger.csv");
    let svg = dir.join("trigger.svg");
    let out = plc(&[
        "trace",
        &segment,
        "counter",
        "blink",
        "--trigger",
        &format!("counter > {at}"),
        "--pre",
        "100",
        "--post",
        "250",
        "--for",
        "30s",
        "--out",
        csv.to_str().unwrap(),
        "--plot",
        svg.to_str().unwrap(),
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let (_, rows) = rows(&csv);
    assert_eq!(rows.len(), 100 + 1 + 250);
    let fired = (at + 1).to_string();
    assert_eq!(
        rows[100][0], fired,
        "the trigger row is the first with counter > {at}"
    );
    assert_eq!(rows[100][1], "0.000000000", "time zero is the trigger");
    assert!(
        rows[0][1].starts_with('-'),
        "rows before the trigger have negative times"
    );
    assert_eq!(rows[0][0], (at + 1 - 100).to_string());
    assert_eq!(rows[350][0], (at + 1 + 250).to_string());
    assert!(stderr(&out).contains(&format!("triggered at cycle {fired}")));

    // The picture, read as a program would: a line for the number, a lane for the bool, the
    // legend with the quantity, the trigger marked, time on the x axis.
    let text = std::fs::read_to_string(&svg).unwrap();
    let doc = roxmltree::Document::parse(&text).expect("the plot is well-formed SVG");
    let texts: Vec<&str> = doc
        .descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| n.text())
        .map(str::trim)
        .collect();
    for want in ["counter", "blink", "trigger", "time from trigger (s)"] {
        assert!(
            texts.iter().any(|t| t.contains(want)),
            "{want} in {texts:?}"
        );
    }
    let lines = doc
        .descendants()
        .filter(|n| n.has_tag_name("polyline") || n.has_tag_name("path"))
        .count();
    assert!(lines >= 2, "a line per variable");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn trace_refuses_unknown_values_bad_triggers_and_every_zero() {
    let segment = format!("cm_refuse_{}", std::process::id());
    let _program = counter(&segment, 1000);
    let bad = |args: &[&str], want: &str| {
        let mut all = vec!["trace", segment.as_str()];
        all.extend_from_slice(args);
        all.extend_from_slice(&["--out", "/tmp/never-written.csv", "--for", "1s"]);
        let out = plc(&all);
        assert!(!out.status.success(), "{args:?} was accepted");
        assert!(stderr(&out).contains(want), "{args:?}: {}", stderr(&out));
    };
    bad(&["counter", "--trigger", "counter >= 3"], "--trigger");
    bad(&["counter", "--trigger", "speed rising"], "rising");
    bad(&["nothing_like_it"], "nothing_like_it");
    bad(&["counter", "--every", "0"], "--every");
}

/// A trace whose trigger never fires recorded nothing: the CSV and plot of an earlier trace
/// stay as they were, with their permissions; a trace that does record keeps a private file
/// private.
#[test]
fn a_trace_whose_trigger_never_fires_leaves_the_earlier_files_as_they_were() {
    use std::os::unix::fs::PermissionsExt;
    let dir = scratch("unfired");
    let segment = format!("cm_unfired_{}", std::process::id());
    let _program = counter(&segment, 1000);
    let (csv, svg) = (dir.join("earlier.csv"), dir.join("earlier.svg"));
    for (file, text) in [(&csv, "cycle,time_s,counter\n1,0,1\n"), (&svg, "<svg/>")] {
        std::fs::write(file, text).unwrap();
        std::fs::set_permissions(file, std::fs::Permissions::from_mode(0o600)).unwrap();
    }
    let trace = |trigger: Option<&str>| {
        let (csv, svg) = (csv.to_str().unwrap(), svg.to_str().unwrap());
        let mut args = vec!["trace", &segment, "counter", "--for", "300ms"];
        if let Some(t) = trigger {
            args.extend(["--trigger", t]);
        }
        args.extend(["--out", csv, "--plot", svg]);
        plc(&args)
    };
    let out = trace(Some("counter > 1000000000000"));
    assert!(!out.status.success());
    assert!(stderr(&out).contains("did not fire"), "{}", stderr(&out));
    assert_eq!(
        std::fs::read_to_string(&csv).unwrap(),
        "cycle,time_s,counter\n1,0,1\n"
    );
    assert_eq!(std::fs::read_to_string(&svg).unwrap(), "<svg/>");
    let mode = |f: &Path| std::fs::metadata(f).unwrap().permissions().mode() & 0o777;
    assert_eq!((mode(&csv), mode(&svg)), (0o600, 0o600));
    let left: Vec<_> = std::fs::read_dir(&dir).unwrap().flatten().collect();
    assert_eq!(left.len(), 2, "no temporary file left: {left:?}");

    let out = trace(None);
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(std::fs::read_to_string(&csv).unwrap().lines().count() > 100);
    assert_eq!(
        (mode(&csv), mode(&svg)),
        (0o600, 0o600),
        "private files stay private"
    );
}
