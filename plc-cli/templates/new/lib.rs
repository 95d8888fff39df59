//! A plc-vars program built as a module. Build it with `cargo build --release`, then run it on
//! the simulated bus made from `bus/machine.toml` (or with `--interface eth0` on a real one):
//!
//! ```sh
//! plc run target/release/lib{lib}.so
//! plc set {name} run_command=true     # another terminal: start the conveyor
//! plc watch {name}
//! ```
//!
//! Everything the program keeps from one cycle to the next is in `Gm` (function block
//! instances and axes too): what it keeps anywhere else starts afresh when the program does.

use plc_core::GlobalMemory;
use plc_io::Context;

/// The program's variables, linked to the bus devices of `bus/machine.toml`.
#[derive(GlobalMemory, Debug, Clone)]
#[plc(bus = "bus/machine.toml")]
pub struct Gm {
    /// Start button (EL1004, input 1).
    #[plc(link = "ethercat.el1004.input_1", direction = "input")]
    pub start_button: bool,
    /// Stop button (EL1004, input 2).
    #[plc(link = "ethercat.el1004.input_2", direction = "input")]
    pub stop_button: bool,
    /// Conveyor motor (EL2004, output 1).
    #[plc(link = "ethercat.el2004.output_1", direction = "output")]
    pub motor: bool,
    /// Start from an HMI or `plc set`, as the start button does; the stop button clears it.
    #[plc(direction = "command")]
    pub run_command: bool,
    /// Cycles the motor has run, kept across restarts.
    #[plc(direction = "status", nonvolatile)]
    pub motor_cycles: u64,
}

/// One cycle: the motor starts with the button or the command and stops with the stop button.
pub fn tick(ctx: &mut Context<Gm>) {
    let gm = &mut ctx.gm;
    if gm.stop_button {
        gm.run_command = false;
        gm.motor = false;
    } else if gm.start_button || gm.run_command {
        gm.motor = true;
    }
    if gm.motor {
        gm.motor_cycles += 1;
    }
}

plc_io::program!(Gm, tick);
