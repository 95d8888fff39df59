//! Children that end with the test that started them.

use std::io;
use std::ops::{Deref, DerefMut};
use std::os::unix::process::CommandExt;
use std::process::{Child, Command, ExitStatus, Output, Stdio};
use std::time::{Duration, Instant};

/// How long [`ChildGuard::terminate`] waits for a clean stop before it kills.
const CLEAN_STOP: Duration = Duration::from_secs(20);

/// Starting a [`Command`] so that its process cannot outlive the test.
pub trait SpawnGuarded {
    /// Spawns the command as [`Command::spawn`] does, in a process group of its own, with the
    /// kernel set to kill it when the spawning thread ends.
    ///
    /// The death signal follows the *thread*: spawn from the test's own thread (not from a
    /// helper thread that ends first), as a test does anyway.
    fn spawn_guarded(&mut self) -> io::Result<ChildGuard>;

    /// Runs the command to its end as [`Command::output`] does (standard output and error
    /// captured), killed with the test if the test ends first.
    fn output_guarded(&mut self) -> io::Result<Output>;
}

impl SpawnGuarded for Command {
    fn spawn_guarded(&mut self) -> io::Result<ChildGuard> {
        // SAFETY: getpid has no preconditions.
        let parent = unsafe { libc::getpid() };
        // SAFETY: between fork and exec the closure calls only async-signal-safe functions
        // (prctl, getppid) and allocates nothing.
        unsafe {
            self.pre_exec(move || {
                if libc::prctl(
                    libc::PR_SET_PDEATHSIG,
                    libc::SIGKILL as libc::c_ulong,
                    0,
                    0,
                    0,
                ) != 0
                {
                    return Err(io::Error::last_os_error());
                }
                // The parent may have died before the death signal was armed: then nobody
                // would ever send it.
                if libc::getppid() != parent {
                    return Err(io::Error::other("the test ended before its child started"));
                }
                Ok(())
            });
        }
        self.process_group(0);
        Ok(ChildGuard {
            child: Some(self.spawn()?),
        })
    }

    fn output_guarded(&mut self) -> io::Result<Output> {
        self.stdin(Stdio::null())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn_guarded()?
            .into_output()
    }
}

/// A child process that is killed and reaped, with its process group, when dropped.
///
/// It dereferences to the [`Child`], so `id`, `wait`, `try_wait` and the pipes work as usual.
///
/// ```
/// use plc_test_support::SpawnGuarded;
/// let sleeper = std::process::Command::new("sleep").arg("600").spawn_guarded().unwrap();
/// let pid = sleeper.id();
/// drop(sleeper); // killed and reaped here
/// assert!(!std::path::Path::new(&format!("/proc/{pid}")).exists());
/// ```
#[derive(Debug)]
pub struct ChildGuard {
    /// `None` only once [`ChildGuard::into_output`] took it.
    child: Option<Child>,
}

impl ChildGuard {
    /// Sends `signal` to the child (not to its group), unless it has already ended.
    pub fn signal(&mut self, signal: libc::c_int) {
        if let Ok(None) = self.try_wait() {
            // SAFETY: the child is not reaped (try_wait saw it run), so its pid names no other
            // process.
            unsafe { libc::kill(self.id() as libc::pid_t, signal) };
        }
    }

    /// Waits up to `limit` for the child to end by itself.
    pub fn wait_timeout(&mut self, limit: Duration) -> io::Result<Option<ExitStatus>> {
        let start = Instant::now();
        loop {
            if let Some(status) = self.try_wait()? {
                return Ok(Some(status));
            }
            if start.elapsed() >= limit {
                return Ok(None);
            }
            std::thread::sleep(Duration::from_millis(10));
        }
    }

    /// Stops the child as a service manager would: SIGTERM (a clean stop), then SIGKILL if it
    /// is still running after 20 s; its exit status.
    pub fn terminate(&mut self) -> io::Result<ExitStatus> {
        self.signal(libc::SIGTERM);
        match self.wait_timeout(CLEAN_STOP)? {
            Some(status) => Ok(status),
            None => {
                self.kill_group();
                self.wait()
            }
        }
    }

    /// Waits for the child to end, collecting its piped output, as [`Child::wait_with_output`].
    pub fn into_output(mut self) -> io::Result<Output> {
        let child = self.child.take().expect("the child is taken only here");
        // If reading or waiting fails half-way, the child must still end with the test.
        let pid = child.id();
        let result = child.wait_with_output();
        if result.is_err() {
            // SAFETY: the child is not reaped (waiting failed): its pid is still its own.
            unsafe { libc::kill(-(pid as libc::pid_t), libc::SIGKILL) };
        }
        result
    }

    fn kill_group(&mut self) {
        // SAFETY: called only while the child is unreaped, so its pid, which is also its
        // process group's id (`process_group(0)`), names no other process.
        unsafe { libc::kill(-(self.id() as libc::pid_t), libc::SIGKILL) };
    }
}

impl Deref for ChildGuard {
    type Target = Child;
    fn deref(&self) -> &Child {
        self.child
            .as_ref()
            .expect("the child is taken only by into_output")
    }
}

impl DerefMut for ChildGuard {
    fn deref_mut(&mut self) -> &mut Child {
        self.child
            .as_mut()
            .expect("the child is taken only by into_output")
    }
}

impl Drop for ChildGuard {
    fn drop(&mut self) {
        let Some(child) = self.child.as_mut() else {
            return;
        };
        if let Ok(None) = child.try_wait() {
            self.kill_group();
            let _ = self.wait();
        }
    }
}
