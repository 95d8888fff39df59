//! The clocks a segment's times are read from.

/// The heartbeat clock, CLOCK_MONOTONIC_COARSE: one clock for every process on the machine
/// (in one time namespace), unlike `Instant`, whose values cannot be shared; unlike the wall
/// clock it does not jump when the time is set, which would make a live owner look stalled or
/// a stalled one alive. The coarse variant is read from the vDSO in a few nanoseconds (the
/// owner stamps it on every publish); its resolution, a few milliseconds, is far below the
/// stall threshold.
#[inline]
pub fn now_ns() -> u64 {
    clock_ns(libc::CLOCK_MONOTONIC_COARSE)
}

/// The wall clock, CLOCK_REALTIME, in nanoseconds since the Unix epoch: the time a cycle's
/// values were produced, as other machines' clocks read it.
#[inline]
pub fn utc_ns() -> u64 {
    clock_ns(libc::CLOCK_REALTIME)
}

/// `clock` (a `CLOCK_*` of `clock_gettime`) in nanoseconds, saturating; 0 if the system cannot
/// read it (a clock this kernel lacks): the one reading of a clock in the workspace, so every
/// caller gets the check of the call's result.
///
/// ```
/// assert!(plc_shm::clock_ns(libc::CLOCK_MONOTONIC) > 0);
/// assert_eq!(plc_shm::clock_ns(-1), 0, "no such clock: 0, not what the buffer held");
/// ```
#[inline]
pub fn clock_ns(clock: libc::clockid_t) -> u64 {
    let mut ts = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: clock_gettime writes one timespec into the valid one we pass.
    if unsafe { libc::clock_gettime(clock, &mut ts) } != 0 {
        return 0;
    }
    (ts.tv_sec as u64)
        .saturating_mul(1_000_000_000)
        .saturating_add(ts.tv_nsec as u64)
}
