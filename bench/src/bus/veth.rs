//! The wire of the bus figures: a veth pair in a network namespace of its own (so nothing of
//! the host's network sees the frames, and the host's traffic does not reach the sockets),
//! the simulated tensile-tester bus served on one end by ethercat-sim's raw-socket server,
//! the MainDevice's raw socket (ethercrab's `tx_rx_task`) on the other, as on a real NIC.

use super::place;
use ethercat_sim::{SimBus, raw};
use std::process::Command;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::thread::JoinHandle;

/// The MainDevice's end of the pair.
pub const MAIN: &str = "plcbm0";
/// The simulator's end of the pair.
const SIM: &str = "plcbs0";
/// The namespace's name before the process id of the plc-bench that made it.
const PREFIX: &str = "plcbench";

/// A network namespace holding the veth pair [`MAIN`] - `plcbs0`; deleted (with the pair)
/// when dropped.
#[derive(Debug)]
pub struct Veth {
    namespace: String,
}

impl Veth {
    /// Makes the namespace and the pair, both ends up. The error says why not (no `ip`, no
    /// privilege), in `ip`'s own words.
    pub fn create() -> Result<Veth, String> {
        remove_stale();
        let veth = Veth {
            namespace: format!("{PREFIX}{}", std::process::id()),
        };
        ip(&["netns", "add", &veth.namespace])?;
        // From here on, dropping `veth` deletes what was made.
        let n = veth.namespace.as_str();
        ip(&[
            "-n", n, "link", "add", MAIN, "type", "veth", "peer", "name", SIM,
        ])?;
        ip(&["-n", n, "link", "set", MAIN, "up"])?;
        ip(&["-n", n, "link", "set", SIM, "up"])?;
        Ok(veth)
    }

    /// The namespace's name.
    pub fn namespace(&self) -> &str {
        &self.namespace
    }

    /// Moves the calling thread into the namespace: sockets it opens, and threads it starts,
    /// live there.
    pub fn enter(&self) -> Result<(), String> {
        enter(&self.namespace)
    }

    /// Serves `bus` on the simulator's end from a thread pinned to `cpu`, under SCHED_FIFO
    /// when `fifo` (below the cycle's priority). Returns once the socket is open.
    pub fn serve(&self, bus: SimBus, cpu: usize, fifo: bool) -> Result<Server, String> {
        let stop = Arc::new(AtomicBool::new(false));
        let flag = stop.clone();
        let (opened_tx, opened) = std::sync::mpsc::channel();
        let namespace = self.namespace.clone();
        let thread = std::thread::Builder::new()
            .name("bench-sim".into())
            .spawn(move || {
                let setup = (|| {
                    enter(&namespace)?;
                    place::pin(cpu)?;
                    if fifo {
                        place::set_fifo(place::SIM_PRIORITY)?;
                    }
                    raw::RawSocket::open(SIM).map_err(|e| format!("raw socket on {SIM}: {e}"))
                })();
                match setup {
                    Ok(socket) => {
                        let _ = opened_tx.send(Ok(()));
                        raw::serve(&socket, &bus, &flag).map_err(|e| e.to_string())
                    }
                    Err(e) => {
                        let _ = opened_tx.send(Err(e.clone()));
                        Err(e)
                    }
                }
            })
            .map_err(|e| format!("starting the simulator's thread: {e}"))?;
        let server = Server {
            stop,
            thread: Some(thread),
        };
        opened
            .recv()
            .map_err(|_| "the simulator's thread ended before opening its socket".to_string())??;
        Ok(server)
    }
}

impl Drop for Veth {
    fn drop(&mut self) {
        // Deleting the namespace deletes the pair in it.
        let _ = ip(&["netns", "del", &self.namespace]);
    }
}

/// The simulator's serving thread; stopped and joined when dropped (within its 20 ms poll).
#[derive(Debug)]
pub struct Server {
    stop: Arc<AtomicBool>,
    thread: Option<JoinHandle<Result<(), String>>>,
}

impl Server {
    /// Stops the thread; the error that ended it early, if any.
    pub fn stop(mut self) -> Result<(), String> {
        self.shutdown()
    }

    fn shutdown(&mut self) -> Result<(), String> {
        self.stop.store(true, Ordering::Release);
        match self.thread.take().map(JoinHandle::join) {
            Some(Ok(r)) => r,
            Some(Err(_)) => Err("the simulator's thread panicked".into()),
            None => Ok(()),
        }
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.shutdown();
    }
}

/// Deletes the namespaces (and their pairs) of plc-bench runs whose process is gone: one that
/// was killed never dropped its [`Veth`]. Best effort: what cannot be read or deleted stays.
fn remove_stale() {
    let Ok(entries) = std::fs::read_dir("/run/netns") else {
        return;
    };
    for entry in entries.flatten() {
        let name = entry.file_name();
        let Some(pid) = name.to_str().and_then(|n| n.strip_prefix(PREFIX)) else {
            continue;
        };
        let alive = pid.parse::<u32>().is_ok_and(|pid| {
            pid == std::process::id() || std::path::Path::new(&format!("/proc/{pid}")).exists()
        });
        if !alive && let Some(namespace) = name.to_str() {
            let _ = ip(&["netns", "del", namespace]);
        }
    }
}

/// Moves the calling thread into network namespace `namespace`.
fn enter(namespace: &str) -> Result<(), String> {
    use std::os::fd::AsRawFd;
    let path = format!("/run/netns/{namespace}");
    let file = std::fs::File::open(&path).map_err(|e| format!("{path}: {e}"))?;
    // SAFETY: a valid namespace descriptor; only the calling thread changes namespace.
    if unsafe { libc::setns(file.as_raw_fd(), libc::CLONE_NEWNET) } != 0 {
        return Err(format!(
            "entering network namespace {namespace}: {}",
            std::io::Error::last_os_error()
        ));
    }
    Ok(())
}

fn ip(args: &[&str]) -> Result<(), String> {
    let out = Command::new("ip")
        .args(args)
        .output()
        .map_err(|e| format!("iproute2's `ip` does not run: {e}"))?;
    if !out.status.success() {
        return Err(format!(
            "`ip {}`: {}",
            args.join(" "),
            String::from_utf8_lossy(&out.stderr).trim()
        ));
    }
    Ok(())
}
