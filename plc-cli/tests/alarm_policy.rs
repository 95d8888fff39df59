//! Operators' actions on alarms against a program of this test binary (`PLC_TEST_ROLE`):
//! who may act is the write policy's (a reader of the read group lists the alarms but may not
//! acknowledge them; the owner's user may), and each action is refused when the alarm's state
//! does not allow it: a latched alarm reset while still active, a shelf longer than 8 hours,
//! an acknowledgement nothing waits for; a request naming several alarms is all or none.

mod common;

use common::{SpawnGuarded, stderr, stdout, wait_until};
use plc_core::GlobalMemory;
use plc_io::Runtime;
use std::os::unix::fs::DirBuilderExt;
use std::path::Path;
use std::process::{Command, Output, Stdio};
use std::time::Duration;

#[derive(GlobalMemory, Debug, Clone)]
pub struct Gm {
    #[plc(alarm(text = "Hydraulic pressure lost", severity = 800, latched))]
    pressure_lost: bool,
    #[plc(alarm = "Door open")]
    door_open: bool,
    counter: u64,
}

/// Runs as the program when `PLC_TEST_ROLE=alarm_owner`: group `nogroup` reads.
#[test]
fn alarm_owner_role() {
    if std::env::var("PLC_TEST_ROLE").as_deref() != Ok("alarm_owner") {
        return;
    }
    let dir = std::env::var("JOURNAL_DIR").unwrap();
    Runtime::<Gm>::builder()
        .period(Duration::from_millis(2))
        .segment(std::env::var("SEGMENT").unwrap())
        .read_group("nogroup")
        .alarm_journal(Path::new(&dir).join("owner.alarms"))
        .build()
        .unwrap()
        .run(|ctx| ctx.gm.counter += 1)
        .unwrap();
}

fn ok(o: Output) -> String {
    assert!(o.status.success(), "{}", stderr(&o));
    stdout(&o)
}

fn refused(o: Output, why: &str) {
    assert!(!o.status.success(), "{}", stdout(&o));
    assert!(stderr(&o).contains(why), "wanted {why:?}: {}", stderr(&o));
}

#[test]
fn actions_follow_the_write_policy_and_the_alarm_states() {
    let id = std::process::id();
    let base = std::env::temp_dir().join(format!("plc-alarm-policy-{id}"));
    let _ = std::fs::remove_dir_all(&base);
    std::fs::DirBuilder::new()
        .mode(0o755)
        .create(&base)
        .unwrap();
    let journal = base.join("journal");
    std::fs::DirBuilder::new()
        .mode(0o700)
        .create(&journal)
        .unwrap();
    let rt = base.join("rt");
    let segment = format!("al_policy_{id}");
    let s = segment.as_str();
    let mut owner = Command::new(std::env::current_exe().unwrap())
        .args(["alarm_owner_role", "--exact", "--nocapture"])
        .env("PLC_TEST_ROLE", "alarm_owner")
        .env("SEGMENT", s)
        .env("JOURNAL_DIR", &journal)
        .env(plc_io::shm::RUNTIME_DIR_ENV, &rt)
        .stdout(Stdio::null())
        .spawn_guarded()
        .unwrap();
    let plc_here = |args: &[&str]| {
        Command::new(env!("CARGO_BIN_EXE_plc"))
            .args(args)
            .env(plc_io::shm::RUNTIME_DIR_ENV, &rt)
            .output_guarded()
            .unwrap()
    };
    wait_until("the program", || {
        plc_here(&["get", s, "counter"]).status.success()
    });

    ok(plc_here(&[
        "set",
        s,
        "pressure_lost=true",
        "door_open=true",
    ]));
    wait_until("both alarms", || {
        let l = ok(plc_here(&["alarms", s]));
        l.contains("pressure_lost") && l.contains("door_open")
    });
    let listing = ok(plc_here(&["alarms", s]));
    let first = listing.lines().nth(1).unwrap();
    assert!(
        first.starts_with("800") && first.contains("pressure_lost"),
        "most severe first: {listing}"
    );

    // A reader of the read group sees them, and may not acknowledge.
    if let Some(nobody) = Nobody::new(&base, &rt) {
        assert!(ok(nobody.plc(&["alarms", s])).contains("door_open"));
        refused(nobody.plc(&["ack", s, "door_open"]), "may not write");
    }

    // All or none: the second is refused (nothing waits on it twice), so the first stays.
    refused(
        plc_here(&["ack", s, "door_open", "door_open"]),
        "cannot acknowledge alarm `door_open`",
    );
    let listing = ok(plc_here(&["alarms", s]));
    assert!(
        listing
            .lines()
            .any(|l| l.contains("door_open") && l.contains("active unacknowledged")),
        "{listing}"
    );
    refused(plc_here(&["reset", s, "pressure_lost"]), "still active");
    refused(plc_here(&["reset", s, "door_open"]), "not latched");
    ok(plc_here(&["ack", s, "--all"]));
    refused(plc_here(&["ack", s, "--all"]), "no alarm to acknowledge");

    // The latched alarm holds after its condition clears, until reset.
    ok(plc_here(&["set", s, "pressure_lost=false"]));
    wait_until("the latch", || {
        ok(plc_here(&["alarms", s])).contains("latched acknowledged")
    });
    ok(plc_here(&[
        "reset",
        s,
        "pressure_lost",
        "--comment",
        "pump replaced",
    ]));
    assert!(!ok(plc_here(&["alarms", s])).contains("pressure_lost"));

    // Shelved for at most 8 hours; off the shelf again by hand.
    refused(
        plc_here(&["shelve", s, "door_open", "--for", "9h"]),
        "at most",
    );
    refused(
        plc_here(&["shelve", s, "door_open", "--for", "soon"]),
        "not a duration",
    );
    ok(plc_here(&[
        "shelve",
        s,
        "door_open",
        "--for",
        "1h",
        "--comment",
        "sensor repair",
    ]));
    assert!(ok(plc_here(&["alarms", s])).contains("shelved until"));
    ok(plc_here(&["unshelve", s, "door_open"]));
    refused(plc_here(&["unshelve", s, "door_open"]), "not shelved");
    // The journal has each action within a second.
    wait_until("the unshelve in the history", || {
        ok(plc_here(&["alarms", s, "--history"])).contains("unshelved")
    });
    let history = ok(plc_here(&["alarms", s, "--history"]));
    for what in [
        "reset by",
        "\"pump replaced\"",
        "shelved",
        "\"sensor repair\"",
        "unshelved",
    ] {
        assert!(history.contains(what), "{what}: {history}");
    }
    let _ = owner.terminate();
    let _ = std::fs::remove_dir_all(&base);
}

/// `plc` run as uid 65534 (in no group of the program's), when this test runs as root.
struct Nobody {
    bin: std::path::PathBuf,
    rt: std::path::PathBuf,
}

impl Nobody {
    /// `plc` installed where uid 65534 may run it (the build's directory may be closed to
    /// other users); `None` without root.
    fn new(base: &Path, rt: &Path) -> Option<Nobody> {
        // SAFETY: geteuid has no preconditions.
        if unsafe { libc::geteuid() } != 0 {
            eprintln!("the write policy's part skipped: switching to another uid needs root");
            return None;
        }
        let bin =
            plc_test_support::install_executable(env!("CARGO_BIN_EXE_plc").as_ref(), base).unwrap();
        Some(Nobody {
            bin,
            rt: rt.to_path_buf(),
        })
    }

    fn plc(&self, args: &[&str]) -> Output {
        // In `nogroup` (65534): a reader of the program, not a writer.
        common::as_nobody(
            Command::new(&self.bin)
                .args(args)
                .env(plc_io::shm::RUNTIME_DIR_ENV, &self.rt),
        )
        .output_guarded()
        .unwrap()
    }
}
