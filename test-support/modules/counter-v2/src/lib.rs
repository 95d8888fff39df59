//! The counter test module's next build: `count` widened from UDINT to ULINT, `last_now_us`
//! narrowed from LINT to DINT (which a change refuses unless it is reset), `speed` added with
//! an initial value (retained), `panic_at_cycle` removed, the rest kept.

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
    /// Ticks run, counted by two.
    #[plc(initial = 100, direction = "status")]
    pub count: u64,
    /// The cycle number the last tick saw.
    #[plc(direction = "status")]
    pub last_cycle: u64,
    /// The last tick's time in microseconds.
    #[plc(direction = "status")]
    pub last_now_us: i32,
    /// A new setpoint, kept across restarts.
    #[plc(initial = 2.5, direction = "command", nonvolatile)]
    pub speed: f32,
}

fn tick(ctx: &mut Context<Gm>) {
    ctx.gm.count += 2;
    ctx.gm.last_cycle = ctx.cycle;
    ctx.gm.last_now_us = ctx.now().as_micros() as i32;
    ctx.gm.motor_on = ctx.gm.start && ctx.inputs_valid;
}

plc_module::program!(Gm, tick);
