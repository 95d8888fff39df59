//! `RuntimeBuilder::cpu`: the cycle and the threads its I/O starts on the CPU asked for, the
//! runtime's helper threads (tools' server, retain writer) on the others, the caller's CPUs
//! given back at the end, and a CPU the process may not use refused with its number.
//!
//! The tests look at every thread of the process by name, so they take turns.

mod common;

use common::unique;
use plc_core::GlobalMemory;
use plc_io::{BusState, IoBackend, IoError, IoStatus, Runtime, RuntimeError};
use std::sync::{Arc, Mutex};
use std::time::Duration;

#[derive(GlobalMemory, Debug, Clone)]
pub struct Gm {
    #[plc(direction = "output")]
    count: u32,
    #[plc(nonvolatile)]
    kept: u32,
}

static ONE_AT_A_TIME: Mutex<()> = Mutex::new(());

/// The calling thread's CPUs, ascending.
fn own_cpus() -> Vec<usize> {
    // SAFETY: cpu_set_t is plain data; all-zero is the empty set.
    let mut set: libc::cpu_set_t = unsafe { std::mem::zeroed() };
    // SAFETY: `set` is a valid cpu_set_t of the size passed; pid 0 is the calling thread.
    let rc = unsafe { libc::sched_getaffinity(0, size_of::<libc::cpu_set_t>(), &mut set) };
    assert_eq!(rc, 0, "sched_getaffinity");
    (0..libc::CPU_SETSIZE as usize)
        // SAFETY: below CPU_SETSIZE.
        .filter(|&c| unsafe { libc::CPU_ISSET(c, &set) })
        .collect()
}

fn pin_self(cpus: &[usize]) {
    // SAFETY: as above.
    let mut set: libc::cpu_set_t = unsafe { std::mem::zeroed() };
    for &c in cpus {
        // SAFETY: the CPUs come from `own_cpus`, below CPU_SETSIZE.
        unsafe { libc::CPU_SET(c, &mut set) };
    }
    // SAFETY: `set` is a valid cpu_set_t of the size passed.
    let rc = unsafe { libc::sched_setaffinity(0, size_of::<libc::cpu_set_t>(), &set) };
    assert_eq!(rc, 0, "sched_setaffinity");
}

/// Each thread of this process whose name starts with `prefix`: its CPUs, as the kernel
/// lists them (`Cpus_allowed_list`, e.g. "0-1" or "3").
fn threads_cpus(prefix: &str) -> Vec<String> {
    let mut found = Vec::new();
    for task in std::fs::read_dir("/proc/self/task").unwrap() {
        let task = task.unwrap().path();
        let Ok(name) = std::fs::read_to_string(task.join("comm")) else {
            continue; // the thread ended meanwhile
        };
        if !name.starts_with(prefix) {
            continue;
        }
        let Ok(status) = std::fs::read_to_string(task.join("status")) else {
            continue;
        };
        let line = status
            .lines()
            .find_map(|l| l.strip_prefix("Cpus_allowed_list:"))
            .unwrap();
        found.push(line.trim().to_string());
    }
    found
}

/// `cpus` as the kernel lists them, for sets of one CPU or of a run of CPUs.
fn kernel_list(cpus: &[usize]) -> String {
    match cpus {
        [one] => one.to_string(),
        [first, .., last] if last - first + 1 == cpus.len() => format!("{first}-{last}"),
        _ => panic!("the test expects a contiguous run of CPUs, not {cpus:?}"),
    }
}

/// An I/O backend whose start starts a thread, as EtherCAT's does: the CPUs that thread got.
#[derive(Clone, Default)]
struct ThreadedIo {
    io_thread_cpus: Arc<Mutex<Option<Vec<usize>>>>,
}

impl IoBackend<Gm> for ThreadedIo {
    fn start(&mut self) -> Result<(), IoError> {
        let seen = self.io_thread_cpus.clone();
        std::thread::spawn(move || *seen.lock().unwrap() = Some(own_cpus()))
            .join()
            .unwrap();
        Ok(())
    }
    fn exchange(&mut self, _: &mut Gm) -> IoStatus {
        IoStatus {
            inputs_valid: true,
            bus_fault: false,
            bus_state: BusState::Op,
        }
    }
    fn stop(&mut self) {}
}

/// What the first tick of a run on `cpu` saw.
struct Seen {
    cycle_cpus: Vec<usize>,
    running_on: usize,
    io_thread: Vec<usize>,
    server: Vec<String>,
    retain_writer: Vec<String>,
}

fn run_on(cpu: usize, name: &str) -> Seen {
    let dir = std::env::temp_dir().join(unique(name));
    std::fs::create_dir_all(&dir).unwrap();
    let io = ThreadedIo::default();
    let seen = Arc::new(Mutex::new(None));
    let record = seen.clone();
    let io_thread = io.io_thread_cpus.clone();
    Runtime::<Gm>::builder()
        .period(Duration::from_millis(1))
        .segment(unique(name))
        .retain(dir.join("gm.retain"))
        .backend(io)
        .cpu(cpu)
        .max_cycles(3)
        .handle_signals(false)
        .build()
        .run(move |ctx| {
            ctx.gm.count += 1;
            let mut seen = record.lock().unwrap();
            if seen.is_none() {
                // SAFETY: no arguments; returns the CPU this thread runs on.
                let running_on = unsafe { libc::sched_getcpu() } as usize;
                *seen = Some(Seen {
                    cycle_cpus: own_cpus(),
                    running_on,
                    io_thread: io_thread.lock().unwrap().clone().unwrap(),
                    server: threads_cpus("plc-shm-"),
                    retain_writer: threads_cpus("plc-retain"),
                });
            }
        })
        .unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
    let seen = seen.lock().unwrap().take();
    seen.expect("the program ran a cycle")
}

#[test]
fn the_cycle_and_its_io_run_on_the_cpu_asked_for_and_the_helpers_on_the_others() {
    let _turn = ONE_AT_A_TIME.lock().unwrap_or_else(|p| p.into_inner());
    let allowed = own_cpus();
    let cpu = *allowed.last().unwrap();
    let seen = run_on(cpu, "cpu_last");
    assert_eq!(seen.cycle_cpus, [cpu]);
    assert_eq!(seen.running_on, cpu);
    assert_eq!(
        seen.io_thread,
        [cpu],
        "the I/O's threads run with the cycle"
    );
    let others: Vec<usize> = allowed.iter().copied().filter(|&c| c != cpu).collect();
    let helpers = kernel_list(if others.is_empty() { &allowed } else { &others });
    assert!(!seen.server.is_empty() && !seen.retain_writer.is_empty());
    for place in seen.server.iter().chain(&seen.retain_writer) {
        assert_eq!(place, &helpers, "a helper thread shares the cycle's CPU");
    }
    assert_eq!(own_cpus(), allowed, "the caller's CPUs are given back");
}

#[test]
fn with_one_cpu_allowed_the_helpers_share_it() {
    let _turn = ONE_AT_A_TIME.lock().unwrap_or_else(|p| p.into_inner());
    let cpu = own_cpus()[0];
    pin_self(&[cpu]);
    let seen = run_on(cpu, "cpu_only");
    assert_eq!(seen.cycle_cpus, [cpu]);
    for place in seen.server.iter().chain(&seen.retain_writer) {
        assert_eq!(place, &cpu.to_string());
    }
    assert_eq!(own_cpus(), [cpu]);
}

#[test]
fn a_cpu_the_process_may_not_use_is_refused_before_anything_starts() {
    let _turn = ONE_AT_A_TIME.lock().unwrap_or_else(|p| p.into_inner());
    let allowed = own_cpus();
    let list: Vec<String> = allowed.iter().map(usize::to_string).collect();
    for cpu in [allowed.last().unwrap() + 1, usize::MAX] {
        let dir = std::env::temp_dir().join(unique("cpu_refused"));
        let err = Runtime::<Gm>::builder()
            .segment(unique("cpu_refused"))
            .retain(dir.join("gm.retain"))
            .cpu(cpu)
            .handle_signals(false)
            .build()
            .run(|_| panic!("no cycle runs"))
            .unwrap_err();
        let RuntimeError::Cpu(message) = &err else {
            panic!("not a CPU error: {err}");
        };
        assert_eq!(
            message,
            &format!(
                "the cycle cannot run on CPU {cpu}: this process may run on CPUs {} only \
                 (its affinity or cgroup's cpuset); choose one of those",
                list.join(", ")
            )
        );
        assert!(!dir.exists(), "the retain file's directory was not made");
        assert!(
            plc_io::shm::DynSegment::attach(&unique("cpu_refused")).is_err(),
            "no segment was created"
        );
        assert_eq!(own_cpus(), allowed);
    }
}
