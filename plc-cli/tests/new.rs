//! `plc new`: the crate it writes is the one `test-support/modules/new-program` holds (which
//! the workspace builds, so the template compiles), cargo reads its manifest, and `plc run`
//! runs what it builds on the simulated bus at once.

mod common;

use common::{SpawnGuarded, plc, stderr, stdout, wait_until};
use plc_io::BusState;
use plc_io::shm::DynSegment;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

/// The workspace's root: the checkout the new crate depends on.
fn checkout() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .unwrap()
        .to_path_buf()
}

fn fresh_dir(what: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("plc-new-{what}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn plc_in(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_plc"))
        .args(args)
        .current_dir(dir)
        .output_guarded()
        .unwrap()
}

#[test]
fn plc_new_writes_the_program_the_workspace_builds() {
    let dir = fresh_dir("writes");
    let root = checkout();
    let out = plc_in(
        &dir,
        &["new", "new-program", "--path", root.to_str().unwrap()],
    );
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(
        stdout(&out).contains("plc run target/release/libnew_program.so"),
        "{}",
        stdout(&out)
    );
    let made = dir.join("new-program");
    let fixture = root.join("test-support/modules/new-program");
    for file in ["src/lib.rs", "bus/machine.toml"] {
        assert_eq!(
            std::fs::read_to_string(made.join(file)).unwrap(),
            std::fs::read_to_string(fixture.join(file)).unwrap(),
            "{file} differs from the built fixture's: copy the template's output there"
        );
    }
    let manifest = std::fs::read_to_string(made.join("Cargo.toml")).unwrap();
    assert!(manifest.contains("name = \"new-program\""), "{manifest}");
    assert!(manifest.contains("crate-type = [\"cdylib\"]"), "{manifest}");
    assert!(
        manifest.contains(&format!("path = \"{}/plc-io\"", root.display())),
        "{manifest}"
    );
    // Cargo reads the manifest as a workspace of its own (nothing is built or fetched).
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let meta = Command::new(cargo)
        .args([
            "metadata",
            "--no-deps",
            "--offline",
            "--format-version",
            "1",
        ])
        .arg("--manifest-path")
        .arg(made.join("Cargo.toml"))
        .stdin(Stdio::null())
        .output_guarded()
        .unwrap();
    assert!(meta.status.success(), "{}", stderr(&meta));
    assert!(stdout(&meta).contains("\"crate_types\":[\"cdylib\"]"));
}

#[test]
fn plc_new_refuses_what_it_cannot_make() {
    let dir = fresh_dir("refuses");
    let root = checkout();
    let root = root.to_str().unwrap();
    let out = plc_in(&dir, &["new", "9lives", "--path", root]);
    assert!(
        stderr(&out).contains("is not a crate name"),
        "{}",
        stderr(&out)
    );
    let out = plc_in(&dir, &["new", "conveyor", "--path", "/"]);
    assert!(
        stderr(&out).contains("no plc-vars checkout"),
        "{}",
        stderr(&out)
    );
    std::fs::create_dir(dir.join("conveyor")).unwrap();
    let out = plc_in(&dir, &["new", "conveyor", "--path", root]);
    assert!(!out.status.success());
    assert!(stderr(&out).contains("exists already"), "{}", stderr(&out));
}

#[test]
fn the_new_program_runs_on_the_simulated_bus_at_once() {
    let lib = common::built_module("libnew_program.so");
    let segment = format!("new_program_{}", std::process::id());
    let _run = Command::new(env!("CARGO_BIN_EXE_plc"))
        .arg("run")
        .arg(&lib)
        .args(["--segment", &segment])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn_guarded()
        .unwrap();
    wait_until("the program to publish", || {
        DynSegment::attach(&segment).is_ok()
    });
    let seg = DynSegment::attach(&segment).unwrap();
    wait_until("the bus in OP", || seg.status().bus_state == BusState::Op);
    assert!(plc(&["set", &segment, "run_command=true"]).status.success());
    wait_until("the motor on", || {
        stdout(&plc(&["get", &segment, "motor"])).contains("motor = true")
    });
}
