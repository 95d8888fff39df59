//! The simulated bus behind a veth pair in a network namespace, with ethercrab's own raw
//! socket transport (`tx_rx_task`) on the other end: the path a program takes on hardware.
//!
//! Needs CAP_SYS_ADMIN (`ip netns add`, `setns`), CAP_NET_ADMIN (the veth pair) and
//! CAP_NET_RAW (the raw sockets), which root has, and iproute2's `ip`. Without the privileges
//! the test skips, saying so on the terminal (not in the captured output). In CI (`CI` set)
//! a privileged run never skips: CI runs as root and `.ci/run` installs iproute2, so a
//! missing `ip` there fails the test instead of hiding it. The namespace (and with it the
//! veth pair) is deleted at the end.
#![cfg(target_os = "linux")]

#[macro_use]
mod common;

use common::{bench, maindevice, timeouts};
use ethercat_sim::{al, raw};
use futures_lite::future::block_on;
use plc_test_support::SpawnGuarded;
use std::io::Write;
use std::process::Command;
use std::time::{Duration, Instant};

/// A network namespace holding a veth pair `ecm0` (MainDevice) - `ecs0` (simulation).
struct Namespace {
    name: String,
}

/// Capability bits (linux/capability.h) the test needs.
const CAP_NET_ADMIN: u32 = 12;
const CAP_NET_RAW: u32 = 13;
const CAP_SYS_ADMIN: u32 = 21;

/// The capabilities the test lacks, by name, from the effective set in /proc/self/status
/// (root normally has all; a container may drop some).
fn missing_capabilities() -> Vec<&'static str> {
    let status = std::fs::read_to_string("/proc/self/status").unwrap_or_default();
    let effective = status
        .lines()
        .find_map(|l| l.strip_prefix("CapEff:"))
        .and_then(|v| u64::from_str_radix(v.trim(), 16).ok())
        .unwrap_or(0);
    [
        (CAP_SYS_ADMIN, "CAP_SYS_ADMIN"),
        (CAP_NET_ADMIN, "CAP_NET_ADMIN"),
        (CAP_NET_RAW, "CAP_NET_RAW"),
    ]
    .into_iter()
    .filter(|(bit, _)| effective >> bit & 1 == 0)
    .map(|(_, name)| name)
    .collect()
}

/// Why the test cannot run here, if it cannot: a lack of privilege, or no `ip` outside CI.
/// Panics in CI when privileged but `ip` is missing.
fn reason_to_skip() -> Option<String> {
    let missing = missing_capabilities();
    if !missing.is_empty() {
        return Some(format!(
            "lacks {} (run as root, or grant CAP_SYS_ADMIN, CAP_NET_ADMIN and CAP_NET_RAW)",
            missing.join(", ")
        ));
    }
    let ip_works = Command::new("ip")
        .arg("-V")
        .output_guarded()
        .is_ok_and(|o| o.status.success());
    if ip_works {
        return None;
    }
    assert!(
        std::env::var_os("CI").is_none(),
        "CI is set and the test is privileged, but iproute2's `ip` does not run: .ci/run \
         installs iproute2, so this is a broken CI image, not a reason to skip"
    );
    Some("iproute2's `ip` is not installed (apt-get install iproute2)".into())
}

impl Namespace {
    fn create() -> Result<Namespace, String> {
        let ns = Namespace {
            name: format!("ecsim{}", std::process::id()),
        };
        ns.ip(&["netns", "add", &ns.name])?;
        let n = ns.name.clone();
        ns.ip(&[
            "-n", &n, "link", "add", "ecm0", "type", "veth", "peer", "name", "ecs0",
        ])?;
        ns.ip(&["-n", &n, "link", "set", "ecm0", "up"])?;
        ns.ip(&["-n", &n, "link", "set", "ecs0", "up"])?;
        Ok(ns)
    }

    fn ip(&self, args: &[&str]) -> Result<(), String> {
        let out = Command::new("ip")
            .args(args)
            .output_guarded()
            .map_err(|e| format!("ip {args:?}: {e}"))?;
        if !out.status.success() {
            return Err(format!(
                "ip {args:?}: {}",
                String::from_utf8_lossy(&out.stderr).trim()
            ));
        }
        Ok(())
    }

    /// Moves the calling thread into the namespace (sockets it opens then live there).
    fn enter(&self) -> std::io::Result<()> {
        let file = std::fs::File::open(format!("/run/netns/{}", self.name))?;
        use std::os::fd::AsRawFd;
        // SAFETY: a valid namespace descriptor; only the calling thread changes namespace.
        if unsafe { libc::setns(file.as_raw_fd(), libc::CLONE_NEWNET) } != 0 {
            return Err(std::io::Error::last_os_error());
        }
        Ok(())
    }
}

impl Drop for Namespace {
    fn drop(&mut self) {
        // Deleting the namespace deletes the veth pair in it.
        let _ = self.ip(&["netns", "del", &self.name]);
    }
}

/// Waits for a thread at most `limit`, so a stuck transport fails the test instead of
/// hanging it.
fn join_within<T>(handle: std::thread::JoinHandle<T>, limit: Duration) -> Option<T> {
    let start = Instant::now();
    while !handle.is_finished() {
        if start.elapsed() > limit {
            return None;
        }
        std::thread::sleep(Duration::from_millis(10));
    }
    handle.join().ok()
}

#[test]
fn ethercrab_over_a_veth_pair_reaches_op_and_exchanges_data() {
    if let Some(why) = reason_to_skip() {
        // Straight to the terminal: the test harness captures `println!` of passing tests.
        let _ = writeln!(
            std::io::stderr(),
            "SKIPPED ethercrab_over_a_veth_pair_reaches_op_and_exchanges_data: {why}"
        );
        return;
    }
    // Privileged: from here on every failure is the test's.
    let ns = Namespace::create().unwrap_or_else(|e| panic!("setting up the veth pair: {e}"));
    let bus = bench();

    // The simulation's socket, opened inside the namespace by a short-lived thread.
    let socket = {
        let ns_name = ns.name.clone();
        std::thread::scope(|s| {
            s.spawn(|| {
                ns.enter()?;
                raw::RawSocket::open("ecs0")
            })
            .join()
            .expect("socket thread")
        })
        .unwrap_or_else(|e| panic!("raw socket on ecs0 in {ns_name}: {e}"))
    };
    let server = raw::spawn(socket, bus.clone()).unwrap();

    // ethercrab's own raw-socket transport on the other end, in the namespace too.
    let (tx, rx, pdu_loop) = storage!();
    let (opened_tx, opened) = std::sync::mpsc::channel();
    let ns_path = ns.name.clone();
    let crab = std::thread::spawn(move || {
        let file = std::fs::File::open(format!("/run/netns/{ns_path}")).unwrap();
        use std::os::fd::AsRawFd;
        // SAFETY: a valid namespace descriptor; only this thread changes namespace.
        assert_eq!(
            unsafe { libc::setns(file.as_raw_fd(), libc::CLONE_NEWNET) },
            0
        );
        match ethercrab::std::tx_rx_task("ecm0", tx, rx) {
            Ok(task) => {
                opened_tx.send(Ok(())).unwrap();
                block_on(task).map(|_| ())
            }
            Err(e) => {
                opened_tx.send(Err(e.to_string())).unwrap();
                Ok(())
            }
        }
    });
    opened.recv().unwrap().expect("ethercrab opens ecm0");

    let md = maindevice(pdu_loop, timeouts());
    let group = block_on(md.init_single_group::<8, 64>(ethercrab::std::ethercat_now)).unwrap();
    let group = block_on(group.into_op(&md)).unwrap();
    let names: Vec<String> = (0..4)
        .map(|i| group.subdevice(&md, i).unwrap().name().to_string())
        .collect();
    assert_eq!(names, ["EK1100", "EL1004", "EL2004", "EL2889"]);
    assert_eq!(bus.al_state(3), al::OP);

    bus.set_input_bit(1, 2, true);
    group.subdevice(&md, 3).unwrap().outputs_raw_mut()[1] = 0xA5;
    let response = block_on(group.tx_rx(&md)).unwrap();
    assert_eq!(response.working_counter, 5);
    assert_eq!(group.subdevice(&md, 1).unwrap().inputs_raw()[0], 0b100);
    assert_eq!(bus.outputs(3), [0x00, 0xA5]);
    println!(
        "veth: {} frames answered over ecm0-ecs0 in namespace {}",
        bus.frames(),
        ns.name
    );

    drop(group);
    // SAFETY: the group is gone and no frame is in flight; this tells tx_rx_task to exit.
    let _ = unsafe { md.release_all() };
    let ended = join_within(crab, Duration::from_secs(5));
    assert!(matches!(ended, Some(Ok(()))), "tx_rx_task ended: {ended:?}");
    server.stop().unwrap();
}
