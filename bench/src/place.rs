//! Where the benchmark's threads run: which CPUs the process may use, pinning a thread to one,
//! and SCHED_FIFO, which a container or an unprivileged user may not be allowed.

/// The realtime priority of the cycle threads (and of the threads they start, which inherit
/// it): the Runtime's `realtime_priority` and the direct loop's `sched_setscheduler` alike.
pub const CYCLE_PRIORITY: i32 = 80;

/// The priority of the simulator's thread, below the cycle's: it stands for hardware that
/// answers at once, not for work that may delay the cycle.
pub const SIM_PRIORITY: i32 = 70;

/// The CPUs this process may run on, in ascending order.
pub fn allowed_cpus() -> Vec<usize> {
    // SAFETY: cpu_set_t is plain data; all-zero is the empty set.
    let mut set: libc::cpu_set_t = unsafe { std::mem::zeroed() };
    // SAFETY: `set` is a valid cpu_set_t of the size passed; pid 0 is the calling thread.
    let rc = unsafe { libc::sched_getaffinity(0, std::mem::size_of_val(&set), &mut set) };
    if rc != 0 {
        return vec![0];
    }
    (0..libc::CPU_SETSIZE as usize)
        // SAFETY: `cpu` is below CPU_SETSIZE, the size of `set`.
        .filter(|&cpu| unsafe { libc::CPU_ISSET(cpu, &set) })
        .collect()
}

/// Pins the calling thread to `cpu`; threads it starts afterwards inherit the pin.
pub fn pin(cpu: usize) -> Result<(), String> {
    pin_to(&[cpu])
}

/// Lets the calling thread run on `cpus` only; threads it starts afterwards inherit that.
pub fn pin_to(cpus: &[usize]) -> Result<(), String> {
    let set = cpu_set(cpus)?;
    // SAFETY: `set` is a valid cpu_set_t of the size passed; pid 0 is the calling thread.
    let rc = unsafe { libc::sched_setaffinity(0, std::mem::size_of_val(&set), &set) };
    if rc != 0 {
        return Err(format!(
            "pinning to CPUs {cpus:?}: {}",
            std::io::Error::last_os_error()
        ));
    }
    Ok(())
}

/// Starts `command`'s process on `cpus` only (all its threads).
pub fn pin_command(command: &mut std::process::Command, cpus: &[usize]) -> Result<(), String> {
    use std::os::unix::process::CommandExt;
    let set = cpu_set(cpus)?;
    // SAFETY: the hook runs in the forked child before exec and only makes one
    // async-signal-safe system call on data copied into the closure.
    unsafe {
        command.pre_exec(move || {
            if libc::sched_setaffinity(0, std::mem::size_of_val(&set), &set) != 0 {
                return Err(std::io::Error::last_os_error());
            }
            Ok(())
        })
    };
    Ok(())
}

fn cpu_set(cpus: &[usize]) -> Result<libc::cpu_set_t, String> {
    // SAFETY: cpu_set_t is plain data; all-zero is the empty set.
    let mut set: libc::cpu_set_t = unsafe { std::mem::zeroed() };
    for &cpu in cpus {
        if cpu >= libc::CPU_SETSIZE as usize {
            return Err(format!("CPU {cpu} is beyond what sched_setaffinity takes"));
        }
        // SAFETY: `cpu` was checked against the set's size above.
        unsafe { libc::CPU_SET(cpu, &mut set) };
    }
    Ok(set)
}

/// Puts the calling thread under SCHED_FIFO at `priority`; threads it starts afterwards
/// inherit it.
pub fn set_fifo(priority: i32) -> Result<(), String> {
    let param = libc::sched_param {
        sched_priority: priority,
    };
    // SAFETY: plain syscall on the calling thread with a valid parameter struct.
    if unsafe { libc::sched_setscheduler(0, libc::SCHED_FIFO, &param) } != 0 {
        return Err(format!(
            "SCHED_FIFO {priority} not permitted: {}",
            std::io::Error::last_os_error()
        ));
    }
    Ok(())
}

/// Whether SCHED_FIFO at `priority` is permitted here, tried on a thread of its own so the
/// caller's scheduling is untouched.
pub fn fifo_permitted(priority: i32) -> Result<(), String> {
    std::thread::spawn(move || set_fifo(priority))
        .join()
        .unwrap_or_else(|_| Err("the thread trying SCHED_FIFO panicked".into()))
}
