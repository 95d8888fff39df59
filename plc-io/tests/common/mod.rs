//! Helpers for tests that need a second process: the test binary runs itself again with
//! `PLC_TEST_ROLE` set, and the test of that name plays the role.
// Each test binary uses a different subset of these helpers.
#![allow(dead_code)]

use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

pub use plc_test_support::{ChildGuard, SpawnGuarded};

/// Runs test `test` of this binary in a child process with role `role` and extra env vars; the
/// child ends with the test whatever happens.
pub fn spawn_role(test: &str, role: &str, env: &[(&str, String)]) -> ChildGuard {
    let mut cmd = Command::new(std::env::current_exe().expect("test binary path"));
    cmd.args([test, "--exact", "--nocapture", "--test-threads=1"])
        .env("PLC_TEST_ROLE", role)
        .stdout(Stdio::null())
        .stderr(Stdio::inherit());
    for (k, v) in env {
        cmd.env(k, v);
    }
    cmd.spawn_guarded().expect("spawn child test process")
}

/// The role this process plays, if it is a child.
pub fn role() -> Option<String> {
    std::env::var("PLC_TEST_ROLE").ok()
}

/// A name unique to this test run.
pub fn unique(name: &str) -> String {
    format!("t_{name}_{}", std::process::id())
}

/// Polls `f` until it returns `Some`, for at most `limit`.
pub fn wait_for<T>(limit: Duration, mut f: impl FnMut() -> Option<T>) -> T {
    let start = Instant::now();
    loop {
        if let Some(v) = f() {
            return v;
        }
        assert!(start.elapsed() < limit, "timed out after {limit:?}");
        std::thread::sleep(Duration::from_millis(2));
    }
}

/// SIGKILL, as a crash or `kill -9` would end a process.
pub fn kill9(child: &mut ChildGuard) {
    child.signal(libc::SIGKILL);
    let _ = child.wait();
}

/// Runs `f` (which writes and waits for its writes to be applied) while another thread plays
/// the owner's cycle, applying received writes to `gm`, as the runtime does at each cycle.
pub fn with_cycles<T: plc_core::GlobalMemory + Clone + Send + 'static, R>(
    owner: &mut plc_io::shm::ShmOwner<T>,
    gm: &mut T,
    f: impl FnOnce() -> R,
) -> R {
    use std::sync::atomic::{AtomicBool, Ordering::Relaxed};
    let done = AtomicBool::new(false);
    std::thread::scope(|s| {
        s.spawn(|| {
            while !done.load(Relaxed) {
                owner.apply_requests(gm);
                std::thread::sleep(Duration::from_micros(200));
            }
        });
        let r = f();
        done.store(true, Relaxed);
        r
    })
}

/// A file of this program's runtime directory (its socket `<name>.sock`, its lock file
/// `<name>.lock`).
pub fn runtime_file(file: &str) -> std::path::PathBuf {
    plc_io::shm::runtime_dir().join(file)
}

/// Runs `tick` at 1 kHz in a `Runtime` on segment `name`, on a thread of its own: its stop
/// handle, and the thread, which gives the variables as they were at the end.
pub fn run_program<T>(
    name: &str,
    mut tick: impl FnMut(&mut plc_io::Context<T>) + Send + 'static,
) -> (plc_io::StopHandle, std::thread::JoinHandle<T>)
where
    T: plc_core::GlobalMemory + Default + Clone + Send + 'static,
    T::Image: Send,
{
    let rt = plc_io::Runtime::<T>::builder()
        .period(Duration::from_millis(1))
        .segment(name)
        .handle_signals(false)
        .build()
        .unwrap();
    let stop = rt.stop_handle();
    let thread = std::thread::spawn(move || rt.run(|ctx| tick(ctx)).unwrap());
    (stop, thread)
}

/// Every new owner removes what killed owners left in the runtime directory, so a test that
/// looks at a killed owner's files runs with no other owner starting: these tests take turns.
pub fn alone() -> std::sync::MutexGuard<'static, ()> {
    static TURN: std::sync::Mutex<()> = std::sync::Mutex::new(());
    TURN.lock().unwrap_or_else(|p| p.into_inner())
}

/// The socket of segment `name`.
pub fn socket(name: &str) -> std::path::PathBuf {
    runtime_file(&format!("{name}.sock"))
}

/// The lock file of segment `name`.
pub fn lock(name: &str) -> std::path::PathBuf {
    runtime_file(&format!("{name}.lock"))
}

/// Removes the files of segment `name` on drop (a test that fails must not leave them).
pub struct Cleanup(pub String);

impl Drop for Cleanup {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(socket(&self.0));
        let _ = std::fs::remove_file(lock(&self.0));
    }
}

/// Whether this test runs as root.
pub fn is_root() -> bool {
    // SAFETY: geteuid has no preconditions.
    unsafe { libc::geteuid() == 0 }
}

/// A scratch directory, removed on drop.
pub struct Scratch(pub std::path::PathBuf);

impl Scratch {
    /// A fresh private directory for `what`.
    pub fn new(what: &str) -> Scratch {
        let dir = std::env::temp_dir().join(format!("plc-harden-{what}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir(&dir).unwrap();
        std::fs::set_permissions(&dir, std::os::unix::fs::PermissionsExt::from_mode(0o700))
            .unwrap();
        Scratch(dir)
    }
    /// A file in it.
    pub fn path(&self, name: &str) -> std::path::PathBuf {
        self.0.join(name)
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}
