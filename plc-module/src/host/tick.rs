//! The runtime's tick for a program run from a module: the cycle's facts to the module, its
//! tick over the image; a panic in the module (caught there, with its message) becomes a panic
//! here, inside the runtime's protection, which zeroes the outputs and puts the I/O in a safe
//! state as for a linked program.

use super::memory::ModuleMemory;
use crate::abi::CycleFacts;
use plc_runtime::Context;

/// The facts of the cycle `ctx` describes, as a module takes them.
pub fn facts(ctx: &Context<ModuleMemory>) -> CycleFacts {
    let ns = |d: std::time::Duration| u64::try_from(d.as_nanos()).unwrap_or(u64::MAX);
    CycleFacts {
        cycle: ctx.cycle,
        now_ns: u64::try_from(ctx.now().as_nanos()).unwrap_or(0),
        period_ns: ns(ctx.stats.period),
        last_ns: ns(ctx.stats.last),
        max_ns: ns(ctx.stats.max),
        overruns: ctx.stats.overruns,
        inputs_valid: ctx.inputs_valid.into(),
        bus_fault: ctx.bus_fault.into(),
        bus_state: ctx.bus_state.code(),
        reserved: [0; 5],
    }
}

/// One tick of the module whose variables `ctx` holds.
///
/// # Panics
/// With the module's own message, when the module panicked in this tick or in its bit
/// packing since the last one: the runtime catches it.
pub fn tick(ctx: &mut Context<ModuleMemory>) {
    if let Some(fault) = ctx.gm.take_fault() {
        panic!("{fault}");
    }
    let facts = facts(ctx);
    let module = ctx.gm.module().clone();
    if let Err(fault) = module.tick(ctx.gm.image_mut(), &facts) {
        panic!("{fault}");
    }
}
