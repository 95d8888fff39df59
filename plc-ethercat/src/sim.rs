//! The simulated bus (feature `sim`): the SubDevices of `ethercat-sim`, made from the bus
//! description alone, and the in-process transport that carries ethercrab's frames to them.
//! A program runs without hardware from the same description it runs on hardware with, and a
//! plant model animates the machine through the description's link names
//! ([`SimBus::set_input`], [`SimBus::output`]).
//!
//! ```
//! use plc_ethercat::{BusConfig, Options, Transport, devices};
//! let config = BusConfig { devices: vec![devices::ek1100("coupler"), devices::el1004("di")] };
//! let (transport, sim) = Transport::simulated(&config)?;
//! sim.set_input("ethercat.di.input1", true)?; // a limit switch the program reads
//! // `EtherCatBackend::<Gm>::new(config, transport, Options::simulated())` then runs the
//! // program's links on it as on hardware.
//! # drop(transport);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub use ethercat_sim::{DescriptionError, Device, LinkError, LinkValue, SimBus, Unmodelled};

use crate::{BusConfig, Transport};

impl Transport {
    /// The simulated bus of `config` (each device the model with its identity, in ring
    /// order; [`SimBus::from_description`]) and the in-process transport to it. Keep the
    /// [`SimBus`] to animate the machine; pass the transport to the backend with
    /// [`Options::simulated`](crate::Options::simulated).
    ///
    /// A device the simulator has no model for is refused, naming it ([`DescriptionError`]).
    pub fn simulated(config: &BusConfig) -> Result<(Transport, SimBus), DescriptionError> {
        let bus = SimBus::from_description(config)?;
        Ok((Transport::sim(&bus), bus))
    }

    /// The in-process transport to a simulated bus already made: a thread moves ethercrab's
    /// frames through `bus` while the backend runs (no privileges, no network interface).
    pub fn sim(bus: &SimBus) -> Transport {
        let bus = bus.clone();
        Transport::custom(move |tx, rx| Ok(Box::new(ethercat_sim::inproc::spawn(tx, rx, bus)?)))
    }
}
