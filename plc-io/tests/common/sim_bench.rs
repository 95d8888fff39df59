//! The simulated test bench most EtherCAT tests run on: EK1100, EL1004, EL2004 and EL2889, and
//! the bus description that names them `coupler`, `di`, `dq4` and `dq16`.
// Each test binary uses a different subset of these helpers.
#![allow(dead_code)]

use ethercat_sim::{Device, SimBus};
use plc_core::GlobalMemory;
use plc_io::ethercat::{BusConfig, EtherCatBackend, Options, Transport, devices};

/// The simulated devices, in ring order.
pub fn sim() -> SimBus {
    SimBus::new(vec![
        Device::ek1100(),
        Device::el1004(),
        Device::el2004(),
        Device::el2889(),
    ])
}

/// The bus description of [`sim`].
pub fn description() -> BusConfig {
    BusConfig {
        devices: vec![
            devices::ek1100("coupler"),
            devices::el1004("di"),
            devices::el2004("dq4"),
            devices::el2889("dq16"),
        ],
    }
}

/// ethercrab's network on `bus`, in process.
pub fn transport(bus: &SimBus) -> Transport {
    let bus = bus.clone();
    Transport::custom(move |tx, rx| Ok(Box::new(ethercat_sim::inproc::spawn(tx, rx, bus)?)))
}

/// A backend for `T` on `bus` with `config`, not started.
pub fn backend<T: GlobalMemory + Clone + Send + 'static>(
    bus: &SimBus,
    config: BusConfig,
) -> EtherCatBackend<T> {
    EtherCatBackend::<T>::new(config, transport(bus), Options::simulated()).unwrap()
}

/// [`backend`], started: the bus in OP.
pub fn started<T: GlobalMemory + Clone + Send + 'static>(
    bus: &SimBus,
    config: BusConfig,
) -> EtherCatBackend<T> {
    let mut backend = backend::<T>(bus, config);
    backend.start().unwrap();
    backend
}

/// Ring positions of the simulated bus.
pub const COUPLER: usize = 0;
pub const DI: usize = 1;
pub const DQ4: usize = 2;
pub const DQ16: usize = 3;

/// A program of the bench's bools: inputs of the EL1004, outputs of the EL2004 and EL2889.
#[derive(GlobalMemory, Debug, Clone)]
pub struct Io {
    #[plc(link = "ethercat.di.input1", direction = "input")]
    pub in1: bool,
    #[plc(link = "ethercat.di.input4", direction = "input")]
    pub in4: bool,
    /// A second variable on an input entry: both receive it.
    #[plc(link = "ethercat.di.input4", direction = "input")]
    pub in4_again: bool,
    #[plc(link = "ethercat.dq4.output2", direction = "output")]
    pub q4_2: bool,
    #[plc(link = "ethercat.dq16.output1", direction = "output")]
    pub q16_1: bool,
    #[plc(link = "ethercat.dq16.output10", direction = "output")]
    pub q16_10: bool,
    #[plc(link = "ethercat.dq16.output16", direction = "output")]
    pub q16_16: bool,
}

/// The options of a simulated bus.
pub fn options() -> Options {
    Options::simulated()
}
