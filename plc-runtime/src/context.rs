//! What the program's tick sees: its variables and the facts of the cycle.

use super::{BusState, CycleStats};
use crate::alarms::RuntimeAlarms;
use plc_core::Time;
use std::time::Duration;

/// The program's view of one cycle.
///
/// ```
/// use plc_core::GlobalMemory;
/// use plc_runtime::Context;
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
///
/// Timers take the cycle's time from [`now`](Self::now); a test drives it:
///
/// ```
/// use plc_core::{GlobalMemory, Time, fb::Ton};
/// use plc_runtime::Context;
///
/// #[derive(GlobalMemory, Debug, Clone)]
/// struct Gm {
///     #[plc(direction = "input")]
///     door_closed: bool,
///     #[plc(direction = "output")]
///     lock: bool,
/// }
///
/// // A program's state between cycles: the function block instance.
/// fn tick(ctx: &mut Context<Gm>, settle: &mut Ton) {
///     ctx.gm.lock = settle.call(ctx.now(), ctx.gm.door_closed, Time::from_millis(500));
/// }
///
/// let mut ctx = Context::for_test(Gm::default());
/// let mut settle = Ton::default();
/// ctx.gm.door_closed = true;
/// tick(&mut ctx, &mut settle);
/// ctx.advance(Time::from_millis(499));
/// tick(&mut ctx, &mut settle);
/// assert!(!ctx.gm.lock);
/// ctx.advance(Time::from_millis(1));
/// tick(&mut ctx, &mut settle);
/// assert!(ctx.gm.lock);
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
    /// The start of this cycle: see [`now`](Self::now).
    now: Time,
    /// The program's alarms: see [`alarms`](Self::alarms).
    pub(crate) alarms: RuntimeAlarms,
}

impl<T> Context<T> {
    /// The time of this cycle's start, measured from the runtime's start on a monotonic clock
    /// (never the wall clock, which can jump): the same through one tick, never smaller than
    /// the last cycle's. Give it to the timers of [`plc_core::fb`], so every timer of a cycle
    /// sees one instant. In [`for_test`](Self::for_test) it starts at zero and moves only with
    /// [`set_now`](Self::set_now) and [`advance`](Self::advance).
    pub fn now(&self) -> Time {
        self.now
    }

    /// Sets [`now`](Self::now), for tests (the runtime sets it again at each cycle's start).
    pub fn set_now(&mut self, now: Time) {
        self.now = now;
    }

    /// Moves [`now`](Self::now) on by `by` (saturating at [`Time::MAX`]), for tests; the
    /// runtime sets it again at each cycle's start.
    pub fn advance(&mut self, by: Time) {
        self.now = self.now.saturating_add(by);
    }

    /// The program's alarms: their states by path, as the runtime evaluated them after the
    /// last tick. In [`for_test`](Self::for_test) there are none.
    pub fn alarms(&self) -> &RuntimeAlarms {
        &self.alarms
    }

    /// The program's alarms, to acknowledge, reset, shelve or unshelve one by path (each
    /// action journaled with the operator's name, at this cycle's time).
    pub fn alarms_mut(&mut self) -> &mut RuntimeAlarms {
        &mut self.alarms
    }

    /// A context for unit tests of a tick function: cycle 1, valid inputs, no bus, `now` zero.
    pub fn for_test(gm: T) -> Self {
        Context {
            cycle: 1,
            ..Context::before_first_cycle(gm, Duration::ZERO, RuntimeAlarms::none())
        }
    }

    /// The runtime's context before its first cycle: no cycle done, statistics empty.
    pub(crate) fn before_first_cycle(gm: T, period: Duration, alarms: RuntimeAlarms) -> Self {
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
            now: Time::ZERO,
            alarms,
        }
    }
}
