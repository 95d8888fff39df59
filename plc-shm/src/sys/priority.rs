//! Helper threads of a realtime owner leave its priority.

/// Puts the calling thread back to normal scheduling. A thread started from a realtime cycle
/// thread inherits its SCHED_FIFO priority, and a helper (a tools' server, the retain
/// writer) must never compete with the cycle: under SCHED_FIFO a cycle that wakes waits for a
/// runnable helper of its own priority on its CPU to block.
pub fn normal_priority() {
    let param = libc::sched_param { sched_priority: 0 };
    // SAFETY: plain call on the calling thread with a valid parameter struct; failure leaves
    // the thread as it was.
    unsafe { libc::pthread_setschedparam(libc::pthread_self(), libc::SCHED_OTHER, &param) };
}
