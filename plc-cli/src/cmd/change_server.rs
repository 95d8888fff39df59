//! The host's side of `plc change`: a socket in the user's runtime dir, one change at a time,
//! each prepared on this thread (the module checked, tried in a child and loaded, the plans
//! both ways, the new initial image) and made by the cycle between two cycles. It answers
//! once the new program passed its probation, or came back from it.

use super::change_wire::{
    Answer, MAX_LINE, Outcome, Request, head, refused_plan, report, socket_path,
};
use plc_module::trial::Trial;
use plc_module::{AtChange, Module, ModuleMemory, prepare, prepare_back};
use plc_runtime::{Swap, SwapEvent};
use plc_shm::LayoutDescriptor;
use plc_shm::change::ChangePlan;
use std::io::{BufRead, BufReader, Write};
use std::os::fd::AsRawFd;
use std::os::unix::net::{UnixListener, UnixStream};
use std::path::PathBuf;
use std::sync::Arc;
use std::sync::mpsc::{Receiver, RecvTimeoutError, Sender};
use std::time::Duration;

/// Cycles a new program is on probation.
pub const PROBATION: u64 = 100;

/// The change socket, removed when dropped (when `plc run` ends).
pub struct ChangeServer {
    path: PathBuf,
}

impl Drop for ChangeServer {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.path);
    }
}

/// What the server knows of the running program.
struct Host {
    segment: String,
    running: LayoutDescriptor,
    /// The running module, as `plc list` shows it: name, file, build time.
    module: String,
    /// Changes made since the start (a return counts as one).
    changes: u64,
    /// The variables at the last change, and the program before it (descriptor, as shown).
    at_change: Option<(AtChange, LayoutDescriptor, String)>,
    swaps: Sender<Swap<ModuleMemory>>,
    period: Duration,
    /// Whether the program runs with a bus: one without takes no build with links.
    has_bus: bool,
}

/// Listens for changes of the program running as `segment` (its module `running`), handing
/// each to the cycle through `swaps`.
pub fn serve(
    segment: &str,
    running: &Module,
    swaps: Sender<Swap<ModuleMemory>>,
    period: Duration,
    has_bus: bool,
) -> Result<ChangeServer, super::Error> {
    let path = socket_path(segment)?;
    if UnixStream::connect(&path).is_ok() {
        return Err(format!("`{}`: another host serves this segment", path.display()).into());
    }
    let _ = std::fs::remove_file(&path);
    let listener = UnixListener::bind(&path)
        .map_err(|e| format!("cannot listen for changes at `{}`: {e}", path.display()))?;
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o600))?;
    let mut host = Host {
        segment: segment.to_string(),
        running: running.descriptor().clone(),
        module: shown(running),
        changes: 0,
        at_change: None,
        swaps,
        period,
        has_bus,
    };
    std::thread::Builder::new()
        .name("plc-change".into())
        .spawn(move || {
            plc_shm::normal_priority();
            for stream in listener.incoming().flatten() {
                let answer = host.answer(&stream);
                let mut line = serde_json::to_vec(&answer).unwrap_or_default();
                line.push(b'\n');
                let _ = (&stream).write_all(&line);
            }
        })?;
    Ok(ChangeServer { path })
}

/// A module as `plc list` shows it: its name, its file and when that was built (written).
fn shown(module: &Module) -> String {
    let built = std::fs::metadata(module.path())
        .and_then(|m| m.modified())
        .ok()
        .and_then(|t| t.duration_since(std::time::UNIX_EPOCH).ok())
        .map_or("at an unknown time".into(), |d| {
            plc_shm::utc_text(d.as_nanos() as u64)
        });
    format!(
        "`{}` ({}), built {built}",
        module.name(),
        module.path().display()
    )
}

/// The uid of the process at the other end.
fn peer_uid(stream: &UnixStream) -> Option<u32> {
    let mut cred = libc::ucred {
        pid: 0,
        uid: 0,
        gid: 0,
    };
    let mut len = size_of::<libc::ucred>() as libc::socklen_t;
    // SAFETY: SO_PEERCRED fills a ucred of the size given, on our own socket.
    let r = unsafe {
        libc::getsockopt(
            stream.as_raw_fd(),
            libc::SOL_SOCKET,
            libc::SO_PEERCRED,
            (&mut cred as *mut libc::ucred).cast(),
            &mut len,
        )
    };
    (r == 0).then_some(cred.uid)
}

fn refused(text: impl Into<String>) -> Answer {
    Answer {
        outcome: Outcome::Refused,
        text: text.into(),
    }
}

impl Host {
    fn answer(&mut self, stream: &UnixStream) -> Answer {
        let owner = plc_shm::euid();
        match peer_uid(stream) {
            Some(uid) if uid == owner => {}
            Some(uid) => {
                return refused(format!(
                    "only uid {owner}, who runs the program, may change it (you are uid {uid})"
                ));
            }
            None => return refused("the caller's credentials could not be read"),
        }
        let _ = stream.set_read_timeout(Some(Duration::from_secs(10)));
        let mut line = String::new();
        let read = BufReader::new(std::io::Read::take(stream, MAX_LINE)).read_line(&mut line);
        let request: Request = match read.ok().and_then(|_| serde_json::from_str(&line).ok()) {
            Some(r) => r,
            None => return refused("the request is not one this host reads"),
        };
        if request.info {
            return Answer {
                outcome: Outcome::Done,
                text: format!(
                    "module {}; {} online change{} since it started",
                    self.module,
                    self.changes,
                    if self.changes == 1 { "" } else { "s" }
                ),
            };
        }
        match &request.module {
            Some(path) => self.change(path, &request),
            None => self.back(request.dry_run),
        }
    }

    fn change(&mut self, path: &std::path::Path, request: &Request) -> Answer {
        let trial = match Trial::this_program() {
            Ok(t) => t,
            Err(e) => return refused(format!("cannot find this program to try the module: {e}")),
        };
        let module = match Module::load(path, &trial) {
            Ok(m) => Arc::new(m),
            Err(e) => return refused(e.to_string()),
        };
        if !self.has_bus
            && let Some(v) = module
                .descriptor()
                .variables
                .iter()
                .find(|v| v.link.is_some())
        {
            return refused(format!(
                "`{}` links `{}` to `{}`, and the running program runs without a bus: a bus \
                 needs a restart (`plc run` with the new build)",
                path.display(),
                v.name,
                v.link.as_deref().unwrap_or_default()
            ));
        }
        let new_descriptor = module.descriptor().clone();
        let info = module.info();
        let new_module = shown(&module);
        let prepared = match prepare(&self.running, module, &request.resets, PROBATION) {
            Ok(p) => p,
            Err(refusals) => return refused(refused_plan(path, &refusals)),
        };
        let head = head(
            &self.segment,
            &info.name,
            path,
            &info.fingerprint,
            request.dry_run,
        );
        if request.dry_run {
            return Answer {
                outcome: Outcome::Done,
                text: report(&head, &prepared.plan),
            };
        }
        let answer = self.make(prepared.swap, prepared.events, &head, &prepared.plan);
        if answer.outcome == Outcome::Done {
            let previous = std::mem::replace(&mut self.running, new_descriptor);
            let module = std::mem::replace(&mut self.module, new_module);
            self.at_change = Some((prepared.at_change, previous, module));
            self.changes += 1;
        }
        answer
    }

    fn back(&mut self, dry_run: bool) -> Answer {
        let Some((at_change, previous, module)) = &self.at_change else {
            return refused("no change was made since the program started: nothing to go back to");
        };
        let Some((plan, swap, events)) = prepare_back(&self.running, at_change, PROBATION) else {
            return refused("the variables before the last change are gone");
        };
        let head = format!(
            "segment `{}` {} the program it ran before the last change",
            self.segment,
            if dry_run {
                "would return to"
            } else {
                "returns to"
            }
        );
        if dry_run {
            return Answer {
                outcome: Outcome::Done,
                text: report(&head, &plan),
            };
        }
        let (previous, module) = (previous.clone(), module.clone());
        let answer = self.make(swap, events, &head, &plan);
        if answer.outcome == Outcome::Done {
            self.running = previous;
            self.module = module;
            self.at_change = None;
            self.changes += 1;
        }
        answer
    }

    /// Hands `swap` to the cycle and waits for its outcome.
    fn make(
        &self,
        swap: Swap<ModuleMemory>,
        events: Receiver<SwapEvent>,
        head: &str,
        plan: &ChangePlan,
    ) -> Answer {
        if self.swaps.send(swap).is_err() {
            return refused("the program has stopped");
        }
        let patience = self.period * (PROBATION as u32 + 10) + Duration::from_secs(30);
        let mut text = report(head, plan);
        loop {
            match events.recv_timeout(patience) {
                Ok(SwapEvent::Refused(why)) => return refused(why),
                Ok(SwapEvent::Swapped {
                    cycle,
                    took,
                    relaid,
                    released_forces,
                }) => {
                    text.push_str(&format!(
                        "swapped before cycle {cycle}, {} us on the cycle thread{}\n",
                        took.as_micros(),
                        if relaid {
                            "; the segment was made again (tools attach again)"
                        } else {
                            ""
                        }
                    ));
                    if !released_forces.is_empty() {
                        text.push_str(&format!(
                            "forces released (the new build has no such value): {}\n",
                            released_forces.join(", ")
                        ));
                    }
                }
                Ok(SwapEvent::Kept { cycle }) => {
                    text.push_str(&format!("probation passed at cycle {cycle}\n"));
                    return Answer {
                        outcome: Outcome::Done,
                        text,
                    };
                }
                Ok(SwapEvent::SwappedBack { cycle, message }) => {
                    return Answer {
                        outcome: Outcome::SwappedBack,
                        text: format!("{text}swapped back: {message} (in cycle {cycle})"),
                    };
                }
                Err(RecvTimeoutError::Timeout) => {
                    return refused(format!("{text}no word from the cycle in {patience:?}"));
                }
                Err(RecvTimeoutError::Disconnected) => return refused("the program has stopped"),
            }
        }
    }
}
