//! Cycle-time statistics: kept by the runtime, seen by the program's tick, published in the
//! status block and read back by the tools, all as this one type.

use std::time::Duration;

/// Cycle-time statistics: the work of one cycle (exchange to publish), not the sleep.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CycleStats {
    /// The configured period.
    pub period: Duration,
    /// Last cycle.
    pub last: Duration,
    /// Shortest cycle.
    pub min: Duration,
    /// Longest cycle.
    pub max: Duration,
    /// Mean cycle.
    pub mean: Duration,
    /// Cycles that did not finish within their period.
    pub overruns: u64,
}
