//! What the program's tick sees: its variables and the facts of the cycle.

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

impl CycleStats {
    pub(crate) fn add(&mut self, took: Duration, count: u64) {
        self.last = took;
        if count == 1 || took < self.min {
            self.min = took;
        }
        self.max = self.max.max(took);
        // Running mean without overflow: mean += (x - mean) / n.
        let n = count.max(1) as f64;
        let mean = self.mean.as_secs_f64();
        self.mean = Duration::from_secs_f64(mean + (took.as_secs_f64() - mean) / n);
        if took > self.period && !self.period.is_zero() {
            self.overruns += 1;
        }
    }
}

/// The program's view of one cycle.
///
/// ```
/// use plc_core::GlobalMemory;
/// use plc_io::Context;
///
/// #[derive(GlobalMemory, Debug, Clone)]
/// struct Gm {
///     #[plc(direction = "input")]
///     start: bool,
///     #[plc(direction = "output")]
///     motor_on: bool,
/// }
///
/// fn tick(ctx: &mut Context<Gm>) {
///     ctx.gm.motor_on = ctx.gm.start && ctx.inputs_valid;
/// }
///
/// // Unit-test the program without a bus or a segment:
/// let mut ctx = Context::for_test(Gm::default());
/// ctx.gm.start = true;
/// tick(&mut ctx);
/// assert!(ctx.gm.motor_on);
/// ```
#[derive(Debug)]
#[non_exhaustive]
pub struct Context<T> {
    /// The variables.
    pub gm: T,
    /// Cycles started so far, this one included.
    pub cycle: u64,
    /// Cycle-time statistics up to the last cycle.
    pub stats: CycleStats,
    /// The inputs are this cycle's (false while the bus is faulty).
    pub inputs_valid: bool,
    /// The bus is not healthy.
    pub bus_fault: bool,
    /// The bus state (`OP`, ... or `NONE`).
    pub bus_state: &'static str,
}

impl<T> Context<T> {
    /// A context for unit tests of a tick function: cycle 1, valid inputs, no bus.
    pub fn for_test(gm: T) -> Self {
        Context {
            gm,
            cycle: 1,
            stats: CycleStats::default(),
            inputs_valid: true,
            bus_fault: false,
            bus_state: "NONE",
        }
    }
}
