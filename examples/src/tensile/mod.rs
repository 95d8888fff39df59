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

use plc_io::ethercat::sim::SimBus;
use plc_io::ethercat::{BusConfig, Transport};

/// The bus description of the example (`examples/bus/tensile_tester.toml`): the one place
/// that lists the machine's devices, for the program's links, the real bus and the simulated
/// one alike.
pub const BUS_TOML: &str = include_str!("../../bus/tensile_tester.toml");

/// Ring positions of the devices in [`BUS_TOML`], for code that addresses the simulated
/// devices or ethercrab's SubDevices by position (the benchmarks' direct loop); the plant
/// model uses link names.
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

/// The simulated machine, made from [`BUS_TOML`] alone (an EK1100, an EL1004, an EL2889, an
/// EL2004 and an AKD servo drive, in its ring order). For a description given at run time,
/// use [`Transport::simulated`], which refuses a device without a model by name.
///
/// ```
/// let bus = examples::tensile::simulated_bus();
/// assert_eq!(bus.device_names(), ["EK1100", "EL1004", "EL2889", "EL2004", "AKD"]);
/// ```
pub fn simulated_bus() -> SimBus {
    let made = BusConfig::from_toml_str(BUS_TOML)
        .map_err(|e| e.to_string())
        .and_then(|config| SimBus::from_description(&config).map_err(|e| e.to_string()));
    // The description is compiled in and its test (`the_built_in_description_makes_the_
    // simulated_bus`) makes this bus: a failure here is a broken build, not a user's input.
    made.unwrap_or_else(|e| panic!("the built-in tensile_tester.toml: {e}"))
}

/// The in-process transport to a simulated bus (no privileges needed).
pub fn sim_transport(bus: SimBus) -> Transport {
    Transport::sim(&bus)
}
