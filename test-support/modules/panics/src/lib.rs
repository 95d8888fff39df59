//! The counter test module's variables with one more, `new_ticks`: this build counts its own
//! ticks there (from 0, its initial value, when it takes over) and panics in its third.

use plc_core::GlobalMemory;
use plc_module::__Context as Context;

/// The program's variables: the counter's, and `new_ticks`.
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
    /// Ticks of this build.
    #[plc(direction = "status")]
    pub new_ticks: u32,
}

fn tick(ctx: &mut Context<Gm>) {
    ctx.gm.new_ticks += 1;
    if ctx.gm.new_ticks == 3 {
        ctx.gm.outputs = 0;
        panic!("this build panics in its third cycle");
    }
    ctx.gm.count += 1;
    ctx.gm.last_cycle = ctx.cycle;
    ctx.gm.motor_on = ctx.gm.start && ctx.inputs_valid;
}

plc_module::program!(Gm, tick);
