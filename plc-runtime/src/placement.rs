//! Where the runtime's threads run and at what priority. The cycle
//! ([`RuntimeBuilder::cpu`](super::RuntimeBuilder::cpu)): its thread, and the I/O threads that
//! take part in each bus exchange, on one CPU; the runtime's other threads (the shared-memory
//! server answering tools, the retain writer) on the CPUs left, so they never run on the
//! cycle's CPU between cycles and evict its caches, and at normal priority
//! ([`normal_priority`]) even when the cycle is realtime.
//!
//! Threads inherit the CPUs of the thread that starts them, so the placement is made in two
//! steps around their start: [`CpuPlacement::keep_free`] before the helpers start,
//! [`CpuPlacement::pin_cycle`] after, before the I/O starts. Dropping it puts the calling
//! thread back on the CPUs it had.

use super::RuntimeError;
use std::mem::{size_of, zeroed};

/// The calling thread's CPUs before the runtime moved it, and the cycle's CPU.
pub(super) struct CpuPlacement {
    original: libc::cpu_set_t,
    cycle: usize,
}

impl CpuPlacement {
    /// Checks that the process may run on `cpu` and moves the calling thread, so the threads
    /// it starts next, to the other CPUs it may use (if it may use only `cpu`, they share it).
    pub(super) fn keep_free(cpu: usize) -> Result<Self, RuntimeError> {
        let original = current()?;
        let allowed = allowed_for(cpu, &original)?;
        let others: Vec<usize> = allowed.iter().copied().filter(|&c| c != cpu).collect();
        if others.is_empty() {
            log::warn!(target: "plc_io::runtime",
                "CPU {cpu} is the only one this process may use: the runtime's helper threads \
                 (tools' server, retain writer) share it with the cycle"
            );
        } else {
            set(&set_of(&others), "the runtime's helper threads", &others)?;
        }
        Ok(CpuPlacement {
            original,
            cycle: cpu,
        })
    }

    /// The calling thread (the cycle's) on its CPU alone; threads it starts from now on (the
    /// I/O's) run there too.
    pub(super) fn pin_cycle(&self) -> Result<(), RuntimeError> {
        set(&set_of(&[self.cycle]), "the cycle", &[self.cycle])
    }
}

impl Drop for CpuPlacement {
    fn drop(&mut self) {
        // The thread goes on with the caller's program after the runtime: give it back the
        // CPUs it came with. A failure leaves it pinned, which is harmless.
        // SAFETY: `original` is a valid cpu_set_t of the size passed; pid 0 is this thread.
        unsafe { libc::sched_setaffinity(0, size_of::<libc::cpu_set_t>(), &self.original) };
    }
}

/// Checks that the calling thread may run on `cpu`, as [`RuntimeBuilder::build`](super::RuntimeBuilder::build)
/// does before anything is created.
pub(super) fn check(cpu: usize) -> Result<(), RuntimeError> {
    allowed_for(cpu, &current()?).map(drop)
}

/// The CPUs in `cpus`, if `cpu` is one of them; else the refusal naming them.
fn allowed_for(cpu: usize, cpus: &libc::cpu_set_t) -> Result<Vec<usize>, RuntimeError> {
    let allowed = members(cpus);
    if allowed.contains(&cpu) {
        Ok(allowed)
    } else {
        Err(RuntimeError::Cpu(format!(
            "the cycle cannot run on CPU {cpu}: this process may run on CPUs {} only \
             (its affinity or cgroup's cpuset); choose one of those",
            list(&allowed)
        )))
    }
}

/// The calling thread's CPUs.
fn current() -> Result<libc::cpu_set_t, RuntimeError> {
    // SAFETY: cpu_set_t is plain data; all-zero is the empty set.
    let mut cpus: libc::cpu_set_t = unsafe { zeroed() };
    // SAFETY: `cpus` is a valid cpu_set_t of the size passed; pid 0 is the calling thread.
    let rc = unsafe { libc::sched_getaffinity(0, size_of::<libc::cpu_set_t>(), &mut cpus) };
    if rc != 0 {
        return Err(RuntimeError::Cpu(format!(
            "the CPUs this process may use could not be read (sched_getaffinity): {}",
            std::io::Error::last_os_error()
        )));
    }
    Ok(cpus)
}

fn set(cpus: &libc::cpu_set_t, whose: &str, listed: &[usize]) -> Result<(), RuntimeError> {
    // SAFETY: `cpus` is a valid cpu_set_t of the size passed; pid 0 is the calling thread.
    let rc = unsafe { libc::sched_setaffinity(0, size_of::<libc::cpu_set_t>(), cpus) };
    if rc != 0 {
        return Err(RuntimeError::Cpu(format!(
            "{whose} could not be placed on CPUs {} (sched_setaffinity): {}",
            list(listed),
            std::io::Error::last_os_error()
        )));
    }
    Ok(())
}

/// The CPUs in `cpus`, ascending.
fn members(cpus: &libc::cpu_set_t) -> Vec<usize> {
    (0..libc::CPU_SETSIZE as usize)
        // SAFETY: `cpu` is below CPU_SETSIZE, the size of the set.
        .filter(|&cpu| unsafe { libc::CPU_ISSET(cpu, cpus) })
        .collect()
}

/// A set of `cpus`, each one a member of a set the kernel returned (so below CPU_SETSIZE).
fn set_of(cpus: &[usize]) -> libc::cpu_set_t {
    // SAFETY: cpu_set_t is plain data; all-zero is the empty set.
    let mut set: libc::cpu_set_t = unsafe { zeroed() };
    for &cpu in cpus {
        // SAFETY: every caller passes members of a kernel-returned set, below CPU_SETSIZE.
        unsafe { libc::CPU_SET(cpu, &mut set) };
    }
    set
}

fn list(cpus: &[usize]) -> String {
    let names: Vec<String> = cpus.iter().map(usize::to_string).collect();
    names.join(", ")
}
