//! Alarms from the command line against real processes: the main example's guard door
//! forced open shows in `plc alarms` and `plc watch`, is acknowledged with `plc ack`, and its
//! history survives a kill -9 and a restart; a damaged journal line is reported and the
//! others read. The write policy and the other actions are in `alarm_policy.rs`.

mod common;

use common::{plc, stderr, stdout, tensile_tester, wait_until};
use plc_test_support::TmuxSession;
use std::path::PathBuf;

fn scratch(test: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("plc-alarms-{test}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// `plc alarms` (with `args`), which must succeed.
fn alarms(segment: &str, args: &[&str]) -> String {
    let out = plc(&[&["alarms", segment][..], args].concat());
    assert!(out.status.success(), "{}", stderr(&out));
    stdout(&out)
}

/// The line of `plc alarms` about `path`, if it lists it.
fn line_of(listing: &str, path: &str) -> Option<String> {
    listing
        .lines()
        .find(|l| l.split_whitespace().nth(1) == Some(path))
        .map(str::to_string)
}

#[test]
fn a_forced_guard_door_is_listed_watched_acknowledged_and_kept_across_a_kill() {
    let dir = scratch("door");
    let segment = format!("al_door_{}", std::process::id());
    let mut program = tensile_tester(&dir, &segment);
    let quiet = alarms(&segment, &[]);
    assert!(
        quiet.contains("no alarm active") && quiet.contains("5 declared"),
        "{quiet}"
    );
    let all = alarms(&segment, &["--all"]);
    let door = line_of(&all, "guard_door_open").expect("declared");
    assert!(door.contains("900") && door.contains("normal") && door.contains("Guard door open"));
    // The running program's declaration exports its alarms, as `plc import` reads them.
    let export = stdout(&plc(&["export", &segment]));
    let list: serde_json::Value = serde_json::from_str(&export).unwrap();
    assert_eq!(
        list["variables"]["guard_door_open"]["alarm"]["text"], "Guard door open",
        "{export}"
    );
    assert_eq!(list["variables"]["force_kn"]["alarm"]["high_high"], 16.0);
    let csv = stdout(&plc(&["export", &segment, "--csv"]));
    assert!(csv.lines().next().unwrap().contains("alarm"), "{csv}");

    assert!(
        plc(&["force", &segment, "guard_door_open=true"])
            .status
            .success()
    );
    wait_until("the door alarm in `plc alarms`", || {
        line_of(&alarms(&segment, &[]), "guard_door_open")
            .is_some_and(|l| l.contains("active unacknowledged") && l.contains(" UTC"))
    });

    // `plc watch` counts it and marks the value the alarm watches.
    if TmuxSession::available() {
        let cmd = format!("{} watch {segment} --rate 20", env!("CARGO_BIN_EXE_plc"));
        let session =
            TmuxSession::start(&format!("alarms{}", std::process::id()), 200, 50, &cmd).unwrap();
        wait_until("the alarm count in plc watch", || {
            let screen = session.screen();
            screen.contains("alarms: 1 unacknowledged, 1 active")
                && screen.contains("guard_door_open !")
        });
        session.send_keys(&["q"]);
    }

    // Paths that name no alarm are refused by name, before anything is sent.
    let o = plc(&["ack", &segment, "no_such_thing"]);
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains("has no alarm `no_such_thing`"),
        "{}",
        stderr(&o)
    );
    let o = plc(&["ack", &segment, "state_cycles"]);
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains("`state_cycles` is a variable without an alarm"),
        "{}",
        stderr(&o)
    );

    let o = plc(&[
        "ack",
        &segment,
        "guard_door_open",
        "--comment",
        "door checked",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).contains("acknowledged: guard_door_open"));
    // Answered once the program took it: the table says so at once.
    let after = alarms(&segment, &[]);
    assert!(
        line_of(&after, "guard_door_open")
            .unwrap()
            .contains("active acknowledged"),
        "{after}"
    );
    let o = plc(&["ack", &segment, "guard_door_open"]);
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains("waits for no acknowledgement"),
        "{}",
        stderr(&o)
    );

    // Closed, then opened again and left unacknowledged: killed meanwhile, the program
    // comes back with the alarm still waiting for an operator.
    assert!(plc(&["unforce", &segment, "--all"]).status.success());
    wait_until("the alarm to clear", || {
        alarms(&segment, &[]).contains("no alarm active")
    });
    assert!(
        plc(&["force", &segment, "guard_door_open=true"])
            .status
            .success()
    );
    wait_until("the alarm raised again", || {
        line_of(&alarms(&segment, &[]), "guard_door_open")
            .is_some_and(|l| l.contains("active unacknowledged"))
    });
    // Each transition is on disk within a second.
    std::thread::sleep(std::time::Duration::from_millis(1500));
    program.signal(libc::SIGKILL);
    drop(program);
    let _program = tensile_tester(&dir, &segment);
    // The door is closed now (the force went with the process): returned to normal, but
    // still unacknowledged.
    wait_until("the restored alarm", || {
        line_of(&alarms(&segment, &[]), "guard_door_open")
            .is_some_and(|l| l.contains("returned to normal unacknowledged"))
    });
    // The return, in this run, reaches the journal within a second too.
    wait_until("the return in the history", || {
        alarms(&segment, &["--history"])
            .lines()
            .last()
            .is_some_and(|l| l.contains("returned to normal"))
    });
    let history = alarms(&segment, &["--history"]);
    let events: Vec<&str> = history
        .lines()
        .filter(|l| l.contains("guard_door_open:"))
        .collect();
    assert!(events.len() >= 5, "{history}");
    assert!(events[0].contains("raised active"), "{history}");
    assert!(events[1].contains("acknowledged by") && events[1].contains("\"door checked\""));
    assert!(events[2].contains("returned to normal"), "{history}");
    assert!(events[3].contains("raised active"), "{history}");
    assert!(
        history
            .lines()
            .last()
            .unwrap()
            .contains("returned to normal"),
        "{history}"
    );
    // --since a time after everything: nothing; a bad one: refused with the forms it takes.
    let later = alarms(&segment, &["--history", "--since", "2250-01-01"]);
    assert!(
        later.contains("no alarm transition since 2250-01-01"),
        "{later}"
    );
    let o = plc(&["alarms", &segment, "--history", "--since", "yesterday"]);
    assert!(
        !o.status.success() && stderr(&o).contains("neither a UTC time"),
        "{}",
        stderr(&o)
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_damaged_journal_line_is_reported_and_the_other_records_are_read() {
    let dir = scratch("damage");
    let segment = format!("al_damage_{}", std::process::id());
    let program = tensile_tester(&dir, &segment);
    assert!(
        plc(&["force", &segment, "guard_door_open=true"])
            .status
            .success()
    );
    wait_until("the alarm", || {
        !alarms(&segment, &[]).contains("no alarm active")
    });
    assert!(
        plc(&["ack", &segment, "--all", "--comment", "seen"])
            .status
            .success()
    );
    assert!(plc(&["unforce", &segment, "--all"]).status.success());
    wait_until("the alarm to clear", || {
        alarms(&segment, &[]).contains("no alarm active")
    });
    common::terminate(&mut { program });
    // The acknowledgement's line loses a character: its checksum no longer holds.
    let journal = dir.join("retain").join("tensile_tester.alarms");
    let text = std::fs::read_to_string(&journal).unwrap();
    let damaged = text.replacen("\"seen\"", "\"sen\"", 1);
    assert_ne!(damaged, text, "the comment is in the journal: {text}");
    std::fs::write(&journal, damaged).unwrap();
    let _program = tensile_tester(&dir, &segment);
    let out = plc(&["alarms", &segment, "--history"]);
    assert!(out.status.success(), "{}", stderr(&out));
    let (history, warning) = (stdout(&out), stderr(&out));
    assert!(
        warning.contains("is damaged") && warning.contains("skipped"),
        "{warning}"
    );
    assert!(history.contains("raised active") && history.contains("returned to normal"));
    assert!(!history.contains("acknowledged by"), "{history}");
    let _ = std::fs::remove_dir_all(&dir);
}
