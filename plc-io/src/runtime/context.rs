//! What the program's tick sees: its variables and the facts of the cycle.

use super::{BusState, CycleStats};
use std::time::Duration;

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
    /// The bus state ([`BusState::NoBus`] without a bus).
    pub bus_state: BusState,
}

impl<T> Context<T> {
    /// A context for unit tests of a tick function: cycle 1, valid inputs, no bus.
    pub fn for_test(gm: T) -> Self {
        Context {
            cycle: 1,
            ..Context::before_first_cycle(gm, Duration::ZERO)
        }
    }

    /// The runtime's context before its first cycle: no cycle done, statistics empty.
    pub(crate) fn before_first_cycle(gm: T, period: Duration) -> Self {
        Context {
            gm,
            cycle: 0,
            stats: CycleStats {
                period,
                ..CycleStats::default()
            },
            inputs_valid: true,
            bus_fault: false,
            bus_state: BusState::NoBus,
        }
    }
}
