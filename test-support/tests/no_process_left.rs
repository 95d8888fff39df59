//! Every child a test starts ends with the test: when the test fails, when it is killed, and
//! what the child itself started. Checked in the process table (`/proc`).

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use plc_test_support::{SpawnGuarded, install_executable};

const ROLE: &str = "PLC_TEST_SUPPORT_ROLE";
const PID_FILE: &str = "PLC_TEST_SUPPORT_PID_FILE";

/// Whether `pid` is a live `sleep` process (not gone, not a zombie waiting to be reaped).
fn sleeper_alive(pid: u32) -> bool {
    let Ok(stat) = std::fs::read_to_string(format!("/proc/{pid}/stat")) else {
        return false;
    };
    // The state follows the command name in parentheses, which may itself hold spaces.
    let state = stat.rsplit_once(')').map(|(_, rest)| rest.trim_start());
    let zombie = state.is_some_and(|s| s.starts_with('Z'));
    let cmdline = std::fs::read(format!("/proc/{pid}/cmdline")).unwrap_or_default();
    !zombie && cmdline.starts_with(b"sleep\0")
}

/// Waits up to 5 s for `pid` to be gone.
fn gone_soon(pid: u32) -> bool {
    let start = Instant::now();
    while sleeper_alive(pid) {
        if start.elapsed() > Duration::from_secs(5) {
            return false;
        }
        std::thread::sleep(Duration::from_millis(10));
    }
    true
}

fn pid_file(test: &str) -> PathBuf {
    std::env::temp_dir().join(format!("plc-test-support-{test}-{}", std::process::id()))
}

/// Waits (at most 20 s) for the role process to write its sleeper's pid.
fn read_pid(file: &Path) -> u32 {
    let start = Instant::now();
    loop {
        if let Some(pid) = std::fs::read_to_string(file)
            .ok()
            .and_then(|s| s.trim().parse().ok())
        {
            return pid;
        }
        assert!(
            start.elapsed() < Duration::from_secs(20),
            "no pid in {file:?}"
        );
        std::thread::sleep(Duration::from_millis(10));
    }
}

/// In a role process: starts a guarded `sleep`, writes its pid, then does `then`.
fn play_role(then: impl FnOnce()) {
    let sleeper = Command::new("sleep").arg("600").spawn_guarded().unwrap();
    let file = std::env::var(PID_FILE).unwrap();
    std::fs::write(format!("{file}.tmp"), sleeper.id().to_string()).unwrap();
    std::fs::rename(format!("{file}.tmp"), &file).unwrap();
    then();
    drop(sleeper);
}

/// Runs this binary's test `test` as a role process; returns it and the pid file.
fn start_role(test: &str) -> (plc_test_support::ChildGuard, PathBuf) {
    let file = pid_file(test);
    let _ = std::fs::remove_file(&file);
    let child = Command::new(std::env::current_exe().unwrap())
        .args([test, "--exact", "--nocapture", "--test-threads=1"])
        .env(ROLE, test)
        .env(PID_FILE, &file)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn_guarded()
        .unwrap();
    (child, file)
}

#[test]
fn a_test_that_panics_after_spawning_leaves_no_process() {
    const TEST: &str = "a_test_that_panics_after_spawning_leaves_no_process";
    if std::env::var(ROLE).as_deref() == Ok(TEST) {
        play_role(|| panic!("a failed assertion after spawning"));
        return;
    }
    let (mut role, file) = start_role(TEST);
    let sleeper = read_pid(&file);
    let status = role.wait_timeout(Duration::from_secs(20)).unwrap();
    let _ = std::fs::remove_file(&file);
    assert!(
        status.is_some_and(|s| !s.success()),
        "the role test must fail"
    );
    assert!(
        gone_soon(sleeper),
        "sleep {sleeper} outlived the failed test"
    );
}

#[test]
fn a_test_killed_by_a_timeout_leaves_no_process() {
    const TEST: &str = "a_test_killed_by_a_timeout_leaves_no_process";
    if std::env::var(ROLE).as_deref() == Ok(TEST) {
        play_role(|| std::thread::sleep(Duration::from_secs(600)));
        return;
    }
    let (mut role, file) = start_role(TEST);
    let sleeper = read_pid(&file);
    let _ = std::fs::remove_file(&file);
    assert!(sleeper_alive(sleeper));
    // As a harness's timeout would: no chance to clean up.
    role.signal(libc::SIGKILL);
    assert!(
        gone_soon(sleeper),
        "sleep {sleeper} outlived the killed test"
    );
}

#[test]
fn dropping_the_guard_ends_what_the_child_started_too() {
    let mut shell = Command::new("sh")
        .args(["-c", "sleep 600 & echo $!; wait"])
        .stdout(Stdio::piped())
        .spawn_guarded()
        .unwrap();
    let mut line = String::new();
    std::io::BufRead::read_line(
        &mut std::io::BufReader::new(shell.stdout.take().unwrap()),
        &mut line,
    )
    .unwrap();
    let grandchild: u32 = line.trim().parse().unwrap();
    // The shell prints the pid when it forks, before the fork has become `sleep`.
    let start = Instant::now();
    while !sleeper_alive(grandchild) {
        assert!(
            start.elapsed() < Duration::from_secs(5),
            "no sleep {grandchild}"
        );
        std::thread::sleep(Duration::from_millis(5));
    }
    drop(shell);
    assert!(
        gone_soon(grandchild),
        "sleep {grandchild} outlived its guard"
    );
}

#[test]
fn terminate_stops_cleanly_and_reports_the_status() {
    let mut sleeper = Command::new("sleep").arg("600").spawn_guarded().unwrap();
    let status = sleeper.terminate().unwrap();
    assert_eq!(
        std::os::unix::process::ExitStatusExt::signal(&status),
        Some(libc::SIGTERM)
    );
}

/// The race behind `Text file busy`: other threads fork children all the time while this one
/// writes an executable and runs it.
#[test]
fn an_installed_executable_runs_while_other_threads_fork() {
    let dir = std::env::temp_dir().join(format!("plc-test-support-exe-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir(&dir).unwrap();
    let stop = std::sync::atomic::AtomicBool::new(false);
    let failed = std::thread::scope(|s| {
        for _ in 0..4 {
            s.spawn(|| {
                while !stop.load(std::sync::atomic::Ordering::Relaxed) {
                    let _ = Command::new("true").output_guarded();
                }
            });
        }
        let failed = (0..100).find_map(|round| {
            let round_dir = dir.join(round.to_string());
            std::fs::create_dir(&round_dir).unwrap();
            let copy = install_executable(Path::new("/bin/true"), &round_dir).unwrap();
            let ran = Command::new(&copy).output_guarded();
            let ok = ran.as_ref().is_ok_and(|o| o.status.success());
            (!ok).then(|| format!("round {round}: {ran:?}"))
        });
        // The forking threads stop before any assertion: a failure must not hang the scope.
        stop.store(true, std::sync::atomic::Ordering::Relaxed);
        failed
    });
    let _ = std::fs::remove_dir_all(&dir);
    assert_eq!(failed, None);
}
