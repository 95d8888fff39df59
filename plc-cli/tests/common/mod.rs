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
