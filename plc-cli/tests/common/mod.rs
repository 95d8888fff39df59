//! What the `plc` tests share: running `plc`, reading its output, waiting for a condition, and
//! stopping a child program as Ctrl-C would. Every child is started through
//! `plc_test_support`, so it ends with the test that started it, whatever happens.
#![allow(dead_code)] // each test file uses its part

use std::process::{Command, Output};
use std::time::{Duration, Instant};

pub use plc_test_support::{ChildGuard, SpawnGuarded};

/// Runs `plc` with `args` and waits for it.
pub fn plc(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_plc"))
        .args(args)
        .output_guarded()
        .unwrap()
}

pub fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Waits (at most 20 s, then fails naming `what`) until `f` holds.
pub fn wait_until(what: &str, mut f: impl FnMut() -> bool) {
    let start = Instant::now();
    while !f() {
        assert!(
            start.elapsed() < Duration::from_secs(20),
            "timed out waiting for {what}"
        );
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// Stops a program with SIGTERM (a clean stop: its retained values saved, its segment
/// removed) and waits for it (killed after 20 s); whether it stopped cleanly.
pub fn terminate(child: &mut ChildGuard) -> bool {
    child.terminate().is_ok_and(|s| s.success())
}

/// Starts the main example's binary (built beside `plc` by `cargo test --workspace`) as
/// segment `segment`, its retained values in `dir/retain` and its output in
/// `dir/tensile_tester.log`, and waits until it runs.
pub fn tensile_tester(dir: &std::path::Path, segment: &str) -> ChildGuard {
    let bin = std::path::Path::new(env!("CARGO_BIN_EXE_plc")).with_file_name("tensile_tester");
    assert!(
        bin.is_file(),
        "{} is missing: run the tests with scripts/test.sh (or `cargo build -p examples --bin \
         tensile_tester` first)",
        bin.display()
    );
    let log = std::fs::File::create(dir.join("tensile_tester.log")).unwrap();
    let child = Command::new(bin)
        .args(["--segment", segment])
        .arg("--retain")
        .arg(dir.join("retain"))
        .stdout(log.try_clone().unwrap())
        .stderr(log)
        .spawn_guarded()
        .unwrap();
    wait_until("the tensile tester to start", || {
        plc(&["get", segment, "state_cycles"]).status.success()
    });
    child
}

/// Makes `cmd` run as uid and gid 65534 (`nobody`, `nogroup`) with no other groups: a user
/// outside a program's own, for the write policy's tests (the caller must be root).
pub fn as_nobody(cmd: &mut Command) -> &mut Command {
    use std::os::unix::process::CommandExt;
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
        })
    }
}

/// A program module `scripts/test.sh` builds beside `plc` (`libcounter.so`,
/// `libtensile_tester.so`, ...); the test fails naming how to build it if it is missing.
pub fn built_module(name: &str) -> std::path::PathBuf {
    let lib = std::path::Path::new(env!("CARGO_BIN_EXE_plc")).with_file_name(name);
    assert!(
        lib.is_file(),
        "{} is missing: run the tests with scripts/test.sh, which builds the test modules",
        lib.display()
    );
    lib
}
