//! Per-cycle timestamps for the benchmarks (feature `cycle-probe`, hidden): where a cycle's
//! time goes, the bus exchange and the program's tick against the framework's own work.
//!
//! The runtime stamps the cycle's start and end and the tick; the EtherCAT backend stamps its
//! `tx_rx` alone (the frame's round trip, without moving the linked variables), handed over in
//! a thread-local because the backend sits behind `dyn IoBackend` on the same thread. Nothing
//! is stamped unless a probe is installed, and without the feature none of this is compiled:
//! the cycle of a program that does not ask is the same code.

use std::cell::Cell;
use std::time::Instant;

/// When the parts of one cycle began and ended, on the monotonic clock.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CycleTimes {
    /// The cycle's start, as `Context::now` counts it (before the exchange).
    pub start: Instant,
    /// The bus exchange's start: for EtherCAT the `tx_rx` alone, otherwise the whole
    /// `IoBackend::exchange`.
    pub bus_start: Instant,
    /// The bus exchange's end.
    pub bus_end: Instant,
    /// The program's tick's start (after the writes from outside were applied).
    pub tick_start: Instant,
    /// The tick's end.
    pub tick_end: Instant,
    /// The cycle's end: published, retained values offered, statistics reported.
    pub end: Instant,
}

impl CycleTimes {
    /// The cycle's time minus the bus exchange and the tick: what the framework itself spent.
    pub fn framework(&self) -> std::time::Duration {
        (self.end - self.start)
            .saturating_sub(self.bus_end - self.bus_start)
            .saturating_sub(self.tick_end - self.tick_start)
    }
}

/// What [`RuntimeBuilder::cycle_probe`](super::RuntimeBuilder::cycle_probe) calls after
/// each cycle, on the cycle's thread, outside the cycle's timed span.
pub type Probe = Box<dyn FnMut(&CycleTimes) + Send>;

thread_local! {
    /// Set while a runtime with a probe runs on this thread.
    static ARMED: Cell<bool> = const { Cell::new(false) };
    /// The last bus exchange's start and end, as a backend stamped it.
    static BUS: Cell<Option<(Instant, Instant)>> = const { Cell::new(None) };
}

/// Arms (or disarms) the stamps of a backend running on this thread.
pub(crate) fn arm(on: bool) {
    ARMED.set(on);
    BUS.set(None);
}

/// Runs `exchange` (a backend's frame round trip), stamping it when a probe is armed on this
/// thread.
#[inline]
pub fn bus_exchange<R>(exchange: impl FnOnce() -> R) -> R {
    if !ARMED.get() {
        return exchange();
    }
    let start = Instant::now();
    let r = exchange();
    BUS.set(Some((start, Instant::now())));
    r
}

/// The stamps of the backend's exchange this cycle, if it made any.
pub(crate) fn take_bus() -> Option<(Instant, Instant)> {
    BUS.take()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::Duration;

    #[test]
    fn the_framework_time_is_the_cycle_less_the_exchange_and_the_tick() {
        let t = Instant::now();
        let at = |us| t + Duration::from_micros(us);
        let times = CycleTimes {
            start: at(0),
            bus_start: at(1),
            bus_end: at(51),
            tick_start: at(53),
            tick_end: at(60),
            end: at(62),
        };
        assert_eq!(times.framework(), Duration::from_micros(5));
    }

    #[test]
    fn a_backend_stamps_only_while_armed() {
        arm(false);
        bus_exchange(|| ());
        assert_eq!(take_bus(), None);
        arm(true);
        bus_exchange(|| ());
        assert!(take_bus().is_some());
        assert_eq!(take_bus(), None, "taken once");
        arm(false);
    }
}
