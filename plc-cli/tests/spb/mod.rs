//! What the Sparkplug tests share: mosquitto on a loopback port, the Python host
//! (`tests/sparkplug_host.py`: paho-mqtt and pysparkplug, from the virtual environment
//! `scripts/test.sh` makes and names in `PLC_SPARKPLUG_PYTHON`) whose lines the tests read,
//! and `plc mqtt serve` with its log.
#![allow(dead_code)] // each test file uses its part

use crate::common::{ChildGuard, SpawnGuarded, plc, stdout, wait_until};
use serde_json::Value;
use std::io::{BufRead, BufReader, Write};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::mpsc::{Receiver, channel};
use std::time::{Duration, Instant};

/// The venv's python and mosquitto, or why the test cannot run.
pub fn parts() -> Option<(PathBuf, PathBuf)> {
    let python = match std::env::var_os("PLC_SPARKPLUG_PYTHON") {
        Some(p) if !p.is_empty() => PathBuf::from(p),
        _ => {
            eprintln!(
                "skipped: PLC_SPARKPLUG_PYTHON is not set: run the tests with scripts/test.sh, \
                 which installs the Sparkplug test host (pysparkplug) into target/sparkplug-venv"
            );
            return None;
        }
    };
    let mosquitto = std::env::var_os("PATH")
        .into_iter()
        .flat_map(|p| std::env::split_paths(&p).collect::<Vec<_>>())
        .chain([PathBuf::from("/usr/sbin")])
        .map(|d| d.join("mosquitto"))
        .find(|p| p.is_file());
    let Some(mosquitto) = mosquitto else {
        eprintln!("skipped: mosquitto is not installed: scripts/test.sh installs it");
        return None;
    };
    Some((python, mosquitto))
}

pub fn test_dir(what: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("plc-sparkplug-{what}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("test directory");
    dir
}

pub fn free_port() -> u16 {
    let listener = std::net::TcpListener::bind("127.0.0.1:0").expect("a free port");
    listener.local_addr().expect("its address").port()
}

/// mosquitto on a loopback port of its own; as root it stays root (`user root`), so it can
/// read the configuration in the test's directory.
pub fn broker(mosquitto: &Path, dir: &Path) -> (ChildGuard, u16) {
    let port = free_port();
    let conf = format!("listener {port} 127.0.0.1\nallow_anonymous true\n");
    (broker_with(mosquitto, dir, &conf, &[port]), port)
}

/// mosquitto with the configuration `conf` (after `user root`), once it listens on `ports`.
pub fn broker_with(mosquitto: &Path, dir: &Path, conf: &str, ports: &[u16]) -> ChildGuard {
    let path = dir.join("mosquitto.conf");
    std::fs::write(&path, format!("user root\n{conf}")).expect("mosquitto.conf");
    let log = std::fs::File::create(dir.join("mosquitto.log")).expect("log file");
    let child = Command::new(mosquitto)
        .arg("-c")
        .arg(&path)
        .stdout(log.try_clone().expect("log file"))
        .stderr(log)
        .spawn_guarded()
        .expect("mosquitto starts");
    for &port in ports {
        wait_until("mosquitto to listen", || {
            std::net::TcpStream::connect(("127.0.0.1", port)).is_ok()
        });
    }
    child
}

/// The Python host: its child, its stdin, and its lines.
pub struct Host {
    child: ChildGuard,
    lines: Receiver<Value>,
    /// Lines that arrived while a command was being sent, not yet looked at.
    pending: std::collections::VecDeque<Value>,
    seen: Vec<Value>,
}

impl Host {
    pub fn start(python: &Path, port: u16, group: &str, id: &str) -> Host {
        let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/sparkplug_host.py");
        let mut child = Command::new(python)
            .arg(script)
            .args(["127.0.0.1", &port.to_string(), group, id])
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .spawn_guarded()
            .expect("python starts");
        let out = child.stdout.take().expect("stdout");
        let (tx, lines) = channel();
        std::thread::spawn(move || {
            for line in BufReader::new(out).lines().map_while(Result::ok) {
                match serde_json::from_str::<Value>(&line) {
                    Ok(v) => {
                        if tx.send(v).is_err() {
                            return;
                        }
                    }
                    Err(_) => eprintln!("host: {line}"),
                }
            }
        });
        let mut host = Host {
            child,
            lines,
            pending: Default::default(),
            seen: Vec::new(),
        };
        host.expect("the host subscribed", |v| v["ready"] == true);
        host
    }

    pub fn send(&mut self, cmd: Value) {
        let stdin = self.child.stdin.as_mut().expect("stdin");
        writeln!(stdin, "{cmd}").expect("the host takes a command");
        let op = cmd["op"].clone();
        // What arrives before the host says it sent the command (a birth it caused, for
        // one) is kept for the expectations that follow.
        let deadline = Instant::now() + Duration::from_secs(30);
        loop {
            let left = deadline
                .checked_duration_since(Instant::now())
                .unwrap_or_else(|| panic!("the host never sent {cmd}"));
            let v = self
                .lines
                .recv_timeout(left)
                .unwrap_or_else(|_| panic!("the host never sent {cmd}"));
            if v["done"] == op {
                return;
            }
            self.pending.push_back(v);
        }
    }

    /// The next line that `pred` accepts (the ones before are kept in `seen`), within 30 s.
    pub fn expect(&mut self, what: &str, pred: impl Fn(&Value) -> bool) -> Value {
        match self.within(what, Duration::from_secs(30), pred) {
            Some(v) => v,
            None => {
                let tail: Vec<String> = self
                    .seen
                    .iter()
                    .rev()
                    .take(5)
                    .map(|v| {
                        let mut t = v.to_string();
                        t.truncate(300);
                        t
                    })
                    .collect();
                panic!(
                    "timed out waiting for {what}; the last lines, newest first:\n{}",
                    tail.join("\n")
                )
            }
        }
    }

    pub fn within(
        &mut self,
        what: &str,
        limit: Duration,
        pred: impl Fn(&Value) -> bool,
    ) -> Option<Value> {
        let deadline = Instant::now() + limit;
        loop {
            let v = match self.pending.pop_front() {
                Some(v) => v,
                None => {
                    let left = deadline.checked_duration_since(Instant::now())?;
                    self.lines.recv_timeout(left).ok()?
                }
            };
            assert!(
                v.get("error").is_none(),
                "{what}: the host could not decode {v}"
            );
            self.seen.push(v.clone());
            if pred(&v) {
                return Some(v);
            }
        }
    }

    /// Drops what arrived so far.
    pub fn drain(&mut self) {
        self.pending.clear();
        while self.lines.try_recv().is_ok() {}
    }
}

pub fn is(kind: &'static str) -> impl Fn(&Value) -> bool {
    move |v| v["type"] == kind
}

pub fn metric<'a>(msg: &'a Value, name: &str) -> &'a Value {
    msg["metrics"]
        .as_array()
        .and_then(|ms| ms.iter().find(|m| m["name"] == name))
        .unwrap_or_else(|| panic!("no metric {name} in {msg}"))
}

pub fn has_metric(v: &Value, name: &str, value: &Value) -> bool {
    v["metrics"]
        .as_array()
        .is_some_and(|ms| ms.iter().any(|m| m["name"] == name && m["value"] == *value))
}

/// `plc mqtt serve` for `segment` on the broker at `port`, its log in `dir/serve-N.log`.
pub fn serve(dir: &Path, n: usize, port: u16, segment: &str, extra: &[&str]) -> ChildGuard {
    serve_url(dir, n, &format!("mqtt://127.0.0.1:{port}"), segment, extra)
}

/// `plc mqtt serve` for `segment` on the broker `url`, its log in `dir/serve-N.log`.
pub fn serve_url(dir: &Path, n: usize, url: &str, segment: &str, extra: &[&str]) -> ChildGuard {
    let log = std::fs::File::create(dir.join(format!("serve-{n}.log"))).expect("log file");
    Command::new(env!("CARGO_BIN_EXE_plc"))
        .args(["mqtt", "serve", segment, "--broker", url])
        .args(["--group", "plant", "--node", "line1", "--store"])
        .arg(dir.join("store"))
        .args(extra)
        .stdout(log.try_clone().expect("log file"))
        .stderr(log)
        .spawn_guarded()
        .expect("plc mqtt serve starts")
}

pub fn log_of(dir: &Path, n: usize) -> String {
    std::fs::read_to_string(dir.join(format!("serve-{n}.log"))).unwrap_or_default()
}

pub fn wait_log(dir: &Path, n: usize, text: &str) {
    let deadline = Instant::now() + Duration::from_secs(30);
    while !log_of(dir, n).contains(text) {
        assert!(
            Instant::now() < deadline,
            "serve-{n}.log never said `{text}`:\n{}",
            log_of(dir, n)
        );
        std::thread::sleep(Duration::from_millis(50));
    }
}

/// A value as `plc get` prints it (`name = value`).
pub fn get(segment: &str, name: &str) -> String {
    let out = stdout(&plc(&["get", segment, name]));
    let line = out.trim();
    line.split_once(" = ").map_or(line, |(_, v)| v).to_string()
}
