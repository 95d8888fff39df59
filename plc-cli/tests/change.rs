//! `plc change --dry-run` against a running program: the counter test module's program runs
//! linked in another process (this test binary, `PLC_TEST_ROLE=counter`), and `plc` plans
//! changes to real modules (built by `scripts/test.sh`), trying each in a child of its own.

mod common;
mod owner;

use common::{SpawnGuarded, plc, stderr, stdout};
use owner::Owner;
use plc_io::Runtime;
use std::os::unix::fs::PermissionsExt;
use std::path::PathBuf;
use std::process::{Command, Stdio};
use std::time::Duration;

/// Runs as the control program when `PLC_TEST_ROLE=counter`: the counter module's variables
/// and tick, linked.
#[test]
fn counter_role() {
    if std::env::var("PLC_TEST_ROLE").as_deref() == Ok("counter") {
        let segment = std::env::var("SEGMENT").unwrap();
        Runtime::<counter::Gm>::builder()
            .period(Duration::from_millis(5))
            .segment(segment)
            .build()
            .expect("the runtime's settings are valid")
            .run(counter::tick)
            .unwrap();
    }
}

fn module(name: &str) -> PathBuf {
    common::built_module(name)
}

/// The counter's program, started as segment `change_<test>_<pid>`.
fn running(test: &str) -> Owner {
    let segment = format!("change_{test}_{}", std::process::id());
    let child = Command::new(std::env::current_exe().unwrap())
        .args(["counter_role", "--exact", "--nocapture"])
        .env("PLC_TEST_ROLE", "counter")
        .env("SEGMENT", &segment)
        .stdout(Stdio::null())
        .spawn_guarded()
        .unwrap();
    common::wait_until("the counter to count", || {
        plc(&["get", &segment, "count"]).status.success()
    });
    Owner { child, segment }
}

#[test]
fn a_dry_run_lists_what_happens_to_every_value() {
    let owner = running("plan");
    let v2 = module("libcounter_v2.so");
    let v2 = v2.to_str().unwrap();

    // LINT to DINT may lose the value: refused, naming it and the way out.
    let out = plc(&["change", &owner.segment, v2, "--dry-run"]);
    let err = stderr(&out);
    assert!(!out.status.success(), "{}", stdout(&out));
    assert!(err.contains("is refused, nothing changed"), "{err}");
    assert!(
        err.contains("`last_now_us`") && err.contains("--reset PATH"),
        "{err}"
    );

    let out = plc(&[
        "change",
        &owner.segment,
        v2,
        "--dry-run",
        "--reset",
        "last_now_us",
    ]);
    let text = stdout(&out);
    assert!(out.status.success(), "{}", stderr(&out));
    eprintln!("{text}");
    assert!(
        text.contains("would run `plc-test-module-counter-v2`"),
        "{text}"
    );
    assert!(text.contains("panic=unwind"), "the fingerprint: {text}");
    assert!(
        text.contains("kept           5  inputs, start, outputs, motor_on, last_cycle"),
        "{text}"
    );
    assert!(
        text.contains("converted      1  count (UDINT to ULINT)"),
        "{text}"
    );
    assert!(text.contains("added          1  speed"), "{text}");
    assert!(text.contains("reset          1  last_now_us"), "{text}");
    assert!(text.contains("removed        1  panic_at_cycle"), "{text}");

    // The same build again: the code only.
    let same = module("libcounter.so");
    let out = plc(&[
        "change",
        &owner.segment,
        same.to_str().unwrap(),
        "--dry-run",
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(
        stdout(&out).contains("swaps the code only"),
        "{}",
        stdout(&out)
    );
}

#[test]
fn a_linked_program_takes_no_change_only_a_dry_run() {
    let owner = running("linked");
    let same = module("libcounter.so");
    let out = plc(&["change", &owner.segment, same.to_str().unwrap()]);
    assert!(!out.status.success());
    let err = stderr(&out);
    assert!(
        err.contains("is not run by `plc run`") && err.contains("--dry-run"),
        "{err}"
    );
    let out = plc(&["change", &owner.segment, "--back"]);
    assert!(!out.status.success());
    assert!(
        stderr(&out).contains("is not run by `plc run`"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn a_module_others_may_write_or_that_is_no_module_is_refused() {
    let owner = running("refused");
    let dir = std::env::temp_dir().join(format!("plc-change-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let copy = dir.join("libcounter_v2.so");
    std::fs::write(&copy, std::fs::read(module("libcounter_v2.so")).unwrap()).unwrap();
    std::fs::set_permissions(&copy, std::fs::Permissions::from_mode(0o664)).unwrap();
    let out = plc(&[
        "change",
        &owner.segment,
        copy.to_str().unwrap(),
        "--dry-run",
    ]);
    assert!(!out.status.success());
    assert!(
        stderr(&out).contains("writable by its group"),
        "{}",
        stderr(&out)
    );

    let notes = dir.join("libnotes.so");
    std::fs::write(&notes, "not a library\n").unwrap();
    let out = plc(&[
        "change",
        &owner.segment,
        notes.to_str().unwrap(),
        "--dry-run",
    ]);
    assert!(!out.status.success());
    assert!(stderr(&out).contains("not an ELF file"), "{}", stderr(&out));
    std::fs::remove_dir_all(&dir).unwrap();
}
