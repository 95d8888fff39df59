//! EtherCAT I/O for a `GlobalMemory` struct, through [ethercrab](https://docs.rs/ethercrab/0.7).
//!
//! Three steps, each its own file:
//!
//! 1. [`BusConfig`] (`config`): the bus description, a TOML or JSON file listing the SubDevices
//!    in ring order with the names links use, their expected identity and their PDO entries.
//!    [`devices`] has ready descriptions of the devices the simulated bus models (Beckhoff
//!    terminals, a Kollmorgen AKD servo drive).
//! 2. [`layout`] and [`resolve`]: each entry's bit range in its SubDevice's process data, and
//!    each `#[plc(link = "ethercat.<device>.<entry>")]` of the struct checked against it
//!    (existence, direction widening, one writer per output). All problems are
//!    reported together, before anything is sent to the bus.
//! 3. [`EtherCatBackend`] (`backend`): an ethercrab MainDevice with one group brought to OP
//!    after the identities and process data sizes are checked (`bringup`); each `exchange` is
//!    one `tx_rx` with a working-counter check (`status`), or on a bus with distributed clocks
//!    (devices with `dc` in the description) SYNC0 configured in PRE-OP and one `tx_rx_dc`
//!    per exchange (`dc`, `group`), whose phase against SYNC0 the runtime's cycle follows
//!    (`EtherCatBackend::cycle_phase`), moving the linked variables (`process_data`) and
//!    bringing SubDevices back to OP after a fault, a restarted DC SubDevice with its clock
//!    and SYNC0 set up again (`recovery`). The
//!    transport (`transport`) is a raw socket on a NIC ([`Transport::Interface`]) or anything
//!    that drives ethercrab's `PduTx`/`PduRx`, such as the in-process simulated bus of
//!    `ethercat-sim` ([`Transport::custom`]). Settings are [`Options`], failures to start
//!    [`EtherCatError`].
//!
//! [`scan`] reads a bus description from the SubDevices themselves, for commissioning.
//!
//! Feature `sim`: the simulated bus of `ethercat-sim` made from the bus description alone,
//! with the transport to it (`Transport::simulated`) and its I/O by link name for a plant
//! model (module `sim`), so a program needs no dependency on the simulator.
//!
//! Feature `backend` (default) builds the runtime's backend (step 3); without it this crate
//! is the bus description and the scan alone, for tools that never run a cycle.
//!
//! ```
//! use plc_ethercat::{devices, layout::BusLayout, resolve, BusConfig, PdoDirection};
//! use plc_core::IecType;
//!
//! let bus = BusConfig {
//!     devices: vec![
//!         devices::ek1100("coupler"),
//!         devices::el1004("impact67_0").grouped(PdoDirection::Input, "digital_inputs", IecType::Uint),
//!     ],
//! };
//! bus.validate()?;
//! let layout = BusLayout::new(&bus);
//! let entry = layout.entry("impact67_0", "digital_inputs").unwrap();
//! assert_eq!((entry.bit_offset, entry.bits, entry.iec_type), (0, 4, IecType::Uint));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! Multi-bit entries over 1-bit channels: an entry of N bits covers the next N bits of the
//! process data, so grouping four consecutive 1-bit channels into one 4-bit `UINT` entry gives
//! a word whose bit 0 is the first channel. Declare the word in the struct (e.g. `u16`) and map
//! bools onto its bits with `source`/`bit`, as the JSON variable-list format does for an impact67 module.
#![deny(missing_docs)]

#[cfg(feature = "backend")]
mod backend;
#[cfg(feature = "backend")]
mod bringup;
pub mod config;
#[cfg(feature = "backend")]
mod dc;
pub use plc_rules::bus::devices;
mod error;
#[cfg(feature = "backend")]
mod group;
#[cfg(feature = "backend")]
mod io_backend;
pub mod layout;
mod options;
#[cfg(feature = "backend")]
mod process_data;
#[cfg(feature = "backend")]
mod recovery;
pub mod resolve;
pub mod scan;
#[cfg(feature = "sim")]
pub mod sim;
#[cfg(feature = "backend")]
mod startup;
#[cfg(feature = "backend")]
mod status;
mod transport;

#[cfg(feature = "backend")]
pub use backend::EtherCatBackend;
pub use config::{
    BusConfig, ConfigError, DcConfig, DeviceConfig, Identity, PdoDirection, PdoEntry, StartupSdo,
};
pub use error::EtherCatError;
pub use layout::{BusLayout, LayoutError};
pub use options::{DriverFn, DriverGuard, InputsOnFault, Options, Transport};
pub use plc_shm::BusState;
pub use resolve::{Binding, ResolveError};
#[cfg(feature = "backend")]
pub use status::{BusStatus, DcStatus};

pub use plc_rules::bus::{MAX_PDI, MAX_SUBDEVICES};

/// Frames ethercrab may have in flight.
const MAX_FRAMES: usize = 16;

/// Bytes of one frame's PDU data (a standard Ethernet frame holds 1500).
const MAX_PDU_DATA: usize = ethercrab::PduStorage::element_size(1100);
