//! A program module for the loader's tests: it counts its cycles, copies a bit of its input
//! word to an output through a bit-mapped bool, remembers the facts of the last cycle, and
//! panics in the cycle `panic_at_cycle` names (0: never).

use plc_core::GlobalMemory;
use plc_module::__Context as Context;

/// The program's variables.
#[derive(GlobalMemory, Debug, Clone)]
pub struct Gm {
    /// An input word whose bit 2 is `start`.
    #[plc(direction = "input")]
    pub inputs: u16,
    /// Bit 2 of `inputs`.
    #[plc(source = "inputs", bit = 2)]
    pub start: bool,
    /// An output word whose bit 0 is `motor_on`.
    #[plc(direction = "output")]
    pub outputs: u8,
    /// Bit 0 of `outputs`.
    #[plc(source = "outputs", bit = 0)]
    pub motor_on: bool,
    /// Ticks run.
    #[plc(initial = 100, direction = "status")]
    pub count: u32,
    /// The cycle number the last tick saw.
    #[plc(direction = "status")]
    pub last_cycle: u64,
    /// The last tick's time in microseconds.
    #[plc(direction = "status")]
    pub last_now_us: i64,
    /// Panic in this cycle (0: never).
    #[plc(direction = "command")]
    pub panic_at_cycle: u64,
}

/// One cycle: counts, copies `start` to `motor_on` while the inputs are valid, panics when asked.
pub fn tick(ctx: &mut Context<Gm>) {
    if ctx.gm.panic_at_cycle != 0 && ctx.cycle == ctx.gm.panic_at_cycle {
        ctx.gm.count = 0;
        panic!("counter: asked to panic in cycle {}", ctx.cycle);
    }
    ctx.gm.count += 1;
    ctx.gm.last_cycle = ctx.cycle;
    ctx.gm.last_now_us = ctx.now().as_micros();
    ctx.gm.motor_on = ctx.gm.start && ctx.inputs_valid;
}

plc_module::program!(Gm, tick);
