//! The trial load: before a host loads a module, a short-lived child loads it from the same
//! sealed memory file, checks its entry and makes its initial image, so that a file that
//! crashes the loader (a damaged library faults with `SIGBUS`), hangs or is refused costs a
//! child, not the running program.
//!
//! The child is the host's own program run again with [`TRIAL_ARG`]: a program that loads
//! modules calls `serve_if_asked` (`trial_child`) first thing in `main`. (A `fork` without
//! `exec` of a program with threads may not call the dynamic loader.)

use super::error::ModuleError;
use super::info::ModuleInfo;
use super::sealed::SealedCopy;
use std::io::{self, Read};
use std::os::fd::AsRawFd;
use std::os::unix::process::{CommandExt, ExitStatusExt};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

/// The first argument that makes a program a trial child.
pub const TRIAL_ARG: &str = "--plc-module-trial";

/// The descriptor number the child finds the module's memory file at.
pub(super) const CHILD_FD: i32 = 3;
/// What starts the child's answer on its standard output (a module may print too).
pub(super) const MARK: &str = "plc-module-trial: ";
/// The most bytes of the child's standard output kept: its answer carries the module's
/// descriptor and bus description, which the entry's checks bound.
const MAX_OUTPUT: usize = 96 << 20;
/// The most bytes of the child's standard error kept, for the reason of a crash.
const MAX_ERRORS: usize = 64 << 10;

/// How a host tries a module: which program to run as the child, and for how long.
#[derive(Clone, Debug)]
pub struct Trial {
    program: PathBuf,
    timeout: Duration,
}

impl Trial {
    /// Runs `program`, which calls `plc_module::trial::serve_if_asked` at its start.
    pub fn with_program(program: impl Into<PathBuf>) -> Trial {
        Trial {
            program: program.into(),
            timeout: Duration::from_secs(20),
        }
    }

    /// Runs the program of this process again (it must call
    /// `plc_module::trial::serve_if_asked`).
    pub fn this_program() -> io::Result<Trial> {
        Ok(Trial::with_program(std::env::current_exe()?))
    }

    /// How long the child may take before it is killed and the module refused (20 s).
    pub fn timeout(mut self, timeout: Duration) -> Trial {
        self.timeout = timeout;
        self
    }

    /// Tries the module `path` whose bytes `sealed` holds; what it says of itself.
    pub(crate) fn run(&self, path: &Path, sealed: &SealedCopy) -> Result<ModuleInfo, ModuleError> {
        let failed = |why: String| ModuleError::Trial {
            path: path.into(),
            why,
        };
        let raw = sealed.fd().as_raw_fd();
        let mut command = Command::new(&self.program);
        command
            .arg(TRIAL_ARG)
            .arg(path)
            .stdin(Stdio::null())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped());
        // SAFETY: between fork and exec only dup2 and fcntl, which are async-signal-safe.
        unsafe {
            command.pre_exec(move || {
                let r = if raw == CHILD_FD {
                    libc::fcntl(CHILD_FD, libc::F_SETFD, 0)
                } else {
                    libc::dup2(raw, CHILD_FD)
                };
                if r < 0 {
                    return Err(io::Error::last_os_error());
                }
                Ok(())
            })
        };
        let child = command.spawn().map_err(|e| {
            failed(format!(
                "cannot start `{}` to try it: {e}",
                self.program.display()
            ))
        })?;
        let mut child = Reaped(child);
        let out = drain(child.0.stdout.take(), MAX_OUTPUT);
        let err = drain(child.0.stderr.take(), MAX_ERRORS);
        let deadline = Instant::now() + self.timeout;
        let status = loop {
            match child.0.try_wait() {
                Ok(Some(status)) => break status,
                Ok(None) if Instant::now() < deadline => {
                    std::thread::sleep(Duration::from_millis(5))
                }
                Ok(None) => {
                    return Err(failed(format!(
                        "it did not finish loading within {:?}",
                        self.timeout
                    )));
                }
                Err(e) => return Err(failed(format!("cannot wait for the child: {e}"))),
            }
        };
        let out = out.join().unwrap_or_default();
        let err = err.join().unwrap_or_default();
        let answer = out.lines().rev().find_map(|l| l.strip_prefix(MARK));
        match (answer, status.signal()) {
            (Some(info), None) if status.success() => info
                .strip_prefix("ok ")
                .and_then(|json| serde_json::from_str(json).ok())
                .ok_or_else(|| failed("the child's answer is not one this host reads".into())),
            (Some(refusal), None) => Err(from_wire(path, refusal)),
            (_, Some(signal)) => Err(failed(format!(
                "it crashed the child that loaded it ({}){}",
                signal_name(signal),
                stderr_tail(&err)
            ))),
            (None, None) => Err(failed(format!(
                "the child ended with {status} and no answer{}",
                stderr_tail(&err)
            ))),
        }
    }
}

/// A refusal as one line: its kind, a tab, its reason.
pub(super) fn to_wire(e: &ModuleError) -> String {
    let (kind, why) = match e {
        ModuleError::NotALibrary { why, .. } => ("not-a-library", why.clone()),
        ModuleError::NotAProgram { why, .. } => ("not-a-program", why.clone()),
        ModuleError::Fingerprint { why, .. } => ("fingerprint", why.clone()),
        ModuleError::Trial { why, .. } => ("trial", why.clone()),
        other => ("trial", other.to_string()),
    };
    format!("{kind}\t{}", why.replace('\n', " "))
}

/// The refusal a child's line names, about `path`.
fn from_wire(path: &Path, line: &str) -> ModuleError {
    let (kind, why) = line.split_once('\t').unwrap_or(("trial", line));
    let (path, why) = (path.into(), why.to_string());
    match kind {
        "not-a-library" => ModuleError::NotALibrary { path, why },
        "not-a-program" => ModuleError::NotAProgram { path, why },
        "fingerprint" => ModuleError::Fingerprint { path, why },
        _ => ModuleError::Trial { path, why },
    }
}

/// A child killed and reaped when dropped, whatever happened.
struct Reaped(Child);

impl Drop for Reaped {
    fn drop(&mut self) {
        if let Ok(None) = self.0.try_wait() {
            let _ = self.0.kill();
        }
        let _ = self.0.wait();
    }
}

/// Reads a pipe to its end on a thread, keeping its last `max` bytes (the answer comes last,
/// whatever a module printed before it).
fn drain(pipe: Option<impl Read + Send + 'static>, max: usize) -> std::thread::JoinHandle<String> {
    std::thread::spawn(move || {
        let mut kept = Vec::new();
        let mut chunk = [0u8; 8192];
        if let Some(mut pipe) = pipe {
            loop {
                match pipe.read(&mut chunk) {
                    Ok(0) | Err(_) => break,
                    Ok(n) => {
                        kept.extend_from_slice(&chunk[..n]);
                        if kept.len() > max {
                            kept.drain(..kept.len() - max);
                        }
                    }
                }
            }
        }
        String::from_utf8_lossy(&kept).into_owned()
    })
}

fn stderr_tail(err: &str) -> String {
    let tail: Vec<&str> = err.lines().rev().take(3).collect();
    if tail.is_empty() {
        String::new()
    } else {
        let lines: Vec<&str> = tail.into_iter().rev().collect();
        format!("; it said: {}", lines.join(" / "))
    }
}

fn signal_name(signal: i32) -> String {
    let name = match signal {
        libc::SIGBUS => "SIGBUS",
        libc::SIGSEGV => "SIGSEGV",
        libc::SIGILL => "SIGILL",
        libc::SIGABRT => "SIGABRT",
        libc::SIGKILL => "SIGKILL",
        libc::SIGFPE => "SIGFPE",
        _ => "a signal",
    };
    format!("signal {signal}, {name}")
}
