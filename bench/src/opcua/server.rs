//! The server process: `plc opcua serve` on the program's segment, started on the others'
//! CPUs, waited for until it listens, stopped when dropped.

use crate::owner;
use crate::placement::Placement;
use std::path::{Path, PathBuf};
use std::process::{Child, Command};
use std::time::{Duration, Instant};

/// `plc opcua serve` on a free port of localhost; stopped with SIGTERM when dropped.
pub(super) struct Server {
    child: Child,
    pub(super) url: String,
}

impl Server {
    pub(super) fn start(
        plc: &Path,
        segment: &str,
        work: &Path,
        placement: &Placement,
    ) -> Result<Server, String> {
        std::fs::create_dir_all(work).map_err(|e| format!("{}: {e}", work.display()))?;
        let port = std::net::TcpListener::bind("127.0.0.1:0")
            .and_then(|l| l.local_addr())
            .map_err(|e| format!("no free port: {e}"))?
            .port();
        let log: PathBuf = work.join("server.log");
        let file = std::fs::File::create(&log).map_err(|e| format!("{}: {e}", log.display()))?;
        let err = file.try_clone().map_err(|e| e.to_string())?;
        let child = placement
            .others(&mut Command::new(plc))?
            .args(["opcua", "serve", segment, "--host", "127.0.0.1", "--port"])
            .arg(port.to_string())
            // Kept between runs: the server makes its key pair once.
            .arg("--pki")
            .arg(work.join("pki"))
            .stdout(file)
            .stderr(err)
            .spawn()
            .map_err(|e| format!("{}: {e}", plc.display()))?;
        let mut server = Server {
            child,
            url: format!("opc.tcp://127.0.0.1:{port}/"),
        };
        let deadline = Instant::now() + Duration::from_secs(60);
        while std::net::TcpStream::connect(("127.0.0.1", port)).is_err() {
            if Instant::now() > deadline || matches!(server.child.try_wait(), Ok(Some(_))) {
                let text = std::fs::read_to_string(&log).unwrap_or_default();
                return Err(format!(
                    "plc opcua serve did not start: {}",
                    text.lines().last().unwrap_or("no output")
                ));
            }
            std::thread::sleep(Duration::from_millis(50));
        }
        Ok(server)
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        owner::stop_child(&mut self.child);
    }
}
