//! The group's processes beside the program: mosquitto (Debian's package, as the tests use
//! it; `scripts/test.sh` installs it) on a loopback port, and the edge node `plc mqtt serve`,
//! both on the tools' CPUs, each stopped when dropped.

use crate::owner;
use crate::placement::Placement;
use std::path::{Path, PathBuf};
use std::process::{Child, Command};
use std::time::{Duration, Instant};

/// mosquitto, started again on the same port after [`Broker::stop`].
pub(super) struct Broker {
    binary: PathBuf,
    conf: PathBuf,
    log: PathBuf,
    pub(super) port: u16,
    child: Option<Child>,
}

impl Broker {
    /// mosquitto on a free loopback port, once it listens.
    pub(super) fn start(work: &Path, placement: &Placement) -> Result<Broker, String> {
        let binary = std::env::var_os("PATH")
            .into_iter()
            .flat_map(|p| std::env::split_paths(&p).collect::<Vec<_>>())
            .chain([PathBuf::from("/usr/sbin")])
            .map(|d| d.join("mosquitto"))
            .find(|p| p.is_file())
            .ok_or("mosquitto is not installed: scripts/test.sh installs it")?;
        let port = std::net::TcpListener::bind("127.0.0.1:0")
            .and_then(|l| l.local_addr())
            .map_err(|e| format!("no free port: {e}"))?
            .port();
        let conf = work.join("mosquitto.conf");
        // As root, mosquitto would drop to its own user, who cannot read this directory.
        let text = format!(
            "user root\nlistener {port} 127.0.0.1\nallow_anonymous true\nset_tcp_nodelay true\n"
        );
        std::fs::write(&conf, text).map_err(|e| format!("{}: {e}", conf.display()))?;
        let mut broker = Broker {
            binary,
            conf,
            log: work.join("mosquitto.log"),
            port,
            child: None,
        };
        broker.restart(placement)?;
        Ok(broker)
    }

    /// Starts the broker again (after [`Broker::stop`]) on its port, once it listens.
    pub(super) fn restart(&mut self, placement: &Placement) -> Result<(), String> {
        let log = std::fs::File::create(&self.log).map_err(|e| e.to_string())?;
        let child = placement
            .others(&mut Command::new(&self.binary))?
            .arg("-c")
            .arg(&self.conf)
            .stdout(log.try_clone().map_err(|e| e.to_string())?)
            .stderr(log)
            .spawn()
            .map_err(|e| format!("{}: {e}", self.binary.display()))?;
        self.child = Some(child);
        let port = self.port;
        wait_for("mosquitto to listen", || {
            std::net::TcpStream::connect(("127.0.0.1", port)).is_ok()
        })
    }

    /// Its process id, while it runs.
    pub(super) fn pid(&self) -> Option<u32> {
        self.child.as_ref().map(Child::id)
    }

    /// Stops the broker (its clients lose their connections).
    pub(super) fn stop(&mut self) {
        if let Some(mut child) = self.child.take() {
            owner::stop_child(&mut child);
        }
    }
}

impl Drop for Broker {
    fn drop(&mut self) {
        self.stop();
    }
}

/// `plc mqtt serve` of one segment, primary host `bench`; stopped cleanly when dropped.
pub(super) struct Node {
    child: Child,
    /// Its log (standard error).
    pub(super) log: PathBuf,
}

impl Node {
    /// Starts the edge node `n1` of group `bench` on `segment`, its store in `store`
    /// (`--store-max` `store_max` bytes).
    pub(super) fn start(
        plc: &Path,
        segment: &str,
        port: u16,
        store: &Path,
        store_max: u64,
        placement: &Placement,
    ) -> Result<Node, String> {
        let log = store.with_extension("log");
        let file = std::fs::File::create(&log).map_err(|e| format!("{}: {e}", log.display()))?;
        let child = placement
            .others(&mut Command::new(plc))?
            .args(["mqtt", "serve", segment, "--group", "bench", "--node", "n1"])
            .args(["--primary-host", "bench", "--broker"])
            .arg(format!("mqtt://127.0.0.1:{port}"))
            .arg("--store")
            .arg(store)
            .arg("--store-max")
            .arg(store_max.to_string())
            .stdout(file.try_clone().map_err(|e| e.to_string())?)
            .stderr(file)
            .spawn()
            .map_err(|e| format!("{}: {e}", plc.display()))?;
        Ok(Node { child, log })
    }

    /// Its process id.
    pub(super) fn pid(&self) -> u32 {
        self.child.id()
    }
}

impl Drop for Node {
    fn drop(&mut self) {
        owner::stop_child(&mut self.child);
    }
}

/// Waits up to 30 s for `ready`.
fn wait_for(what: &str, mut ready: impl FnMut() -> bool) -> Result<(), String> {
    let deadline = Instant::now() + Duration::from_secs(30);
    while !ready() {
        if Instant::now() > deadline {
            return Err(format!("timed out waiting for {what}"));
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    Ok(())
}

/// A process's peak resident memory (VmHWM), in bytes.
pub(super) fn peak_rss(pid: u32) -> Option<u64> {
    let status = std::fs::read_to_string(format!("/proc/{pid}/status")).ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib * 1024)
}

/// The CPU time a process has used so far (user and system), from `/proc/PID/stat`.
pub(super) fn cpu_time(pid: u32) -> Option<Duration> {
    let stat = std::fs::read_to_string(format!("/proc/{pid}/stat")).ok()?;
    // The name (field 2) may hold spaces: the fields after it start past its `)`.
    let (_, rest) = stat.rsplit_once(')')?;
    let fields: Vec<&str> = rest.split_whitespace().collect();
    // utime and stime are fields 14 and 15 of the line, 12 and 13 after the name.
    let ticks: u64 = fields.get(11)?.parse::<u64>().ok()? + fields.get(12)?.parse::<u64>().ok()?;
    // SAFETY: sysconf reads a constant of the system.
    let per_s = unsafe { libc::sysconf(libc::_SC_CLK_TCK) };
    (per_s > 0).then(|| Duration::from_secs_f64(ticks as f64 / per_s as f64))
}

/// The bytes of the files in `dir` (the store's data waiting to be sent).
pub(super) fn dir_bytes(dir: &Path) -> u64 {
    std::fs::read_dir(dir)
        .into_iter()
        .flatten()
        .flatten()
        .filter_map(|e| e.metadata().ok())
        .filter(|m| m.is_file())
        .map(|m| m.len())
        .sum()
}
