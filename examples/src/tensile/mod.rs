//! The tensile tester: its variables, its program and a model of the machine that animates the
//! simulated bus.
//!
//! - [`Gm`]: the example variables of the JSON variable-list format (impact67 I/O words with bit-mapped limit switches and a lift
//!   brake, test information strings, nonvolatile offsets) plus the signal tower on an EL2004
//!   and the test crosshead, a servo axis on a Kollmorgen AKD.
//! - [`process_tick`]: a state machine idle -> centering -> lifting -> testing -> done (and
//!   fault); the crosshead pulls at the test speed while testing ([`crosshead`]).
//! - [`plant`]: the machine itself, reading the simulated outputs and the crosshead's
//!   position and setting the simulated inputs from a thread, so the example visibly runs
//!   tests on the simulated bus.
//!
//! The files: `vars` declares [`Gm`], `program` runs it ([`process_tick`]), `crosshead` the
//! servo axis's part of the program, `plant` the machine.

pub mod crosshead;
pub mod drive;
pub mod plant;
mod program;
#[cfg(test)]
mod tests;
mod vars;

pub use program::{TickInfo, process_tick, tick};
pub use vars::{Axis, Gm, State, axis};

use ethercat_sim::{Device, SimBus};
use plc_io::ethercat::Transport;

/// The bus description of the example (`examples/bus/tensile_tester.toml`).
pub const BUS_TOML: &str = include_str!("../../bus/tensile_tester.toml");

/// Ring positions of the simulated SubDevices, as in the bus description.
pub mod position {
    /// EK1100 coupler.
    pub const COUPLER: usize = 0;
    /// EL1004: the impact67 inputs.
    pub const INPUTS: usize = 1;
    /// EL2889: the impact67 outputs.
    pub const OUTPUTS: usize = 2;
    /// EL2004: the signal tower.
    pub const LAMPS: usize = 3;
    /// AKD: the crosshead's servo drive.
    pub const CROSSHEAD: usize = 4;
}

/// The simulated machine: EK1100, EL1004, EL2889, EL2004 and an AKD servo drive in the ring
/// order of [`BUS_TOML`].
pub fn simulated_bus() -> SimBus {
    SimBus::new(vec![
        Device::ek1100(),
        Device::el1004(),
        Device::el2889(),
        Device::el2004(),
        Device::akd(),
    ])
}

/// The in-process transport to a simulated bus (no privileges needed).
pub fn sim_transport(bus: SimBus) -> Transport {
    Transport::custom(move |tx, rx| Ok(Box::new(ethercat_sim::inproc::spawn(tx, rx, bus)?)))
}
