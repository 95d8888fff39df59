//! Where the runtime's threads run. `RuntimeBuilder::cpu`: the cycle and the threads its I/O
//! starts on the CPU asked for, the runtime's helper threads (tools' server, retain writer) on
//! the others, the caller's CPUs given back at the end, and a CPU the process may not use
//! refused with its number. Under `realtime_priority` the helpers run at normal priority.
//!
//! The tests look at every thread of the process by name, so they take turns.

mod common;

use common::unique;
use plc_core::GlobalMemory;
use plc_io::{BusState, IoBackend, IoError, IoStatus, Runtime, RuntimeBuilder, RuntimeError};
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

/// Cycles (of 1 ms) for the helper threads to be found by name.
const LOOKS: u64 = 2000;

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

/// A thread of this process: its id and its CPUs as the kernel lists them
/// (`Cpus_allowed_list`, e.g. "0-1" or "3").
struct Thread {
    tid: libc::pid_t,
    cpus: String,
}

/// Each thread of this process whose name starts with `prefix`.
fn threads(prefix: &str) -> Vec<Thread> {
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
        let cpus = status
            .lines()
            .find_map(|l| l.strip_prefix("Cpus_allowed_list:"))
            .unwrap();
        let tid = task.file_name().unwrap().to_str().unwrap().parse().unwrap();
        found.push(Thread {
            tid,
            cpus: cpus.trim().to_string(),
        });
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
            clocks: None,
        }
    }
    fn stop(&mut self) {}
}

/// Runs a program with a segment and a retain file, its builder finished by `configure`. At
/// the first cycle by which both helper threads have named themselves (a new thread does so
/// once it runs), calls `look` on the cycle's thread with them (the socket server's, the
/// retain writer's) and stops. Returns what `look` returned.
fn look_at_helpers<R>(
    name: &str,
    configure: impl FnOnce(RuntimeBuilder<Gm>) -> RuntimeBuilder<Gm>,
    mut look: impl FnMut(Vec<Thread>, Vec<Thread>) -> R,
) -> Result<R, RuntimeError> {
    let dir = std::env::temp_dir().join(unique(name));
    std::fs::create_dir_all(&dir).unwrap();
    let builder = configure(
        Runtime::<Gm>::builder()
            .period(Duration::from_millis(1))
            .segment(unique(name))
            .retain(dir.join("gm.retain"))
            .max_cycles(LOOKS)
            .handle_signals(false),
    );
    let stop = builder.stop_handle();
    let mut seen = None;
    let run = builder.build().and_then(|runtime| {
        runtime.run(|ctx| {
            ctx.gm.count += 1;
            let (server, retain_writer) = (threads("plc-shm-"), threads("plc-retain"));
            if seen.is_none() && !server.is_empty() && !retain_writer.is_empty() {
                seen = Some(look(server, retain_writer));
                stop.stop();
            }
        })
    });
    std::fs::remove_dir_all(&dir).unwrap();
    run?;
    Ok(seen.expect("both helper threads were found by name"))
}

/// What a run on `cpu` saw in its cycle.
struct Seen {
    cycle_cpus: Vec<usize>,
    running_on: usize,
    io_thread: Vec<usize>,
    helpers: Vec<String>,
}

fn run_on(cpu: usize, name: &str) -> Seen {
    let io = ThreadedIo::default();
    let io_thread = io.io_thread_cpus.clone();
    look_at_helpers(
        name,
        |builder| builder.backend(io).cpu(cpu),
        |server, retain_writer| Seen {
            cycle_cpus: own_cpus(),
            // SAFETY: no arguments; returns the CPU this thread runs on.
            running_on: unsafe { libc::sched_getcpu() } as usize,
            io_thread: io_thread.lock().unwrap().clone().unwrap(),
            helpers: server
                .into_iter()
                .chain(retain_writer)
                .map(|t| t.cpus)
                .collect(),
        },
    )
    .unwrap()
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
    for place in &seen.helpers {
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
    for place in &seen.helpers {
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
        // Refused when built, before the program could run a cycle.
        let Err(err) = Runtime::<Gm>::builder()
            .segment(unique("cpu_refused"))
            .retain(dir.join("gm.retain"))
            .cpu(cpu)
            .handle_signals(false)
            .build()
        else {
            panic!("CPU {cpu} was accepted");
        };
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

#[test]
fn under_a_realtime_cycle_the_helper_threads_run_at_normal_priority() {
    let _turn = ONE_AT_A_TIME.lock().unwrap_or_else(|p| p.into_inner());
    // SAFETY: plain calls with thread ids of this process (0: the calling one).
    let policy = |tid| unsafe { libc::sched_getscheduler(tid) };
    let run = look_at_helpers(
        "cpu_priority",
        |builder| builder.realtime_priority(10),
        |server, retain_writer| {
            let helpers: Vec<(&str, i32)> = (server.iter().map(|t| ("plc-shm-", t.tid)))
                .chain(retain_writer.iter().map(|t| ("plc-retain", t.tid)))
                .map(|(name, tid)| (name, policy(tid)))
                .collect();
            (policy(0), helpers)
        },
    );
    let (cycle, helpers) = match run {
        Err(RuntimeError::Realtime(why)) => {
            eprintln!("skipped: SCHED_FIFO is not permitted here ({why})");
            return;
        }
        other => other.unwrap(),
    };
    assert_eq!(cycle, libc::SCHED_FIFO);
    for (name, policy) in &helpers {
        assert_eq!(
            *policy,
            libc::SCHED_OTHER,
            "thread {name}* runs at the cycle's priority"
        );
    }
}
