//! Simulated EtherCAT SubDevices that real [ethercrab](https://crates.io/crates/ethercrab)
//! drives to OP, so EtherCAT programs run and are tested without hardware.
//!
//! - [`Device`]: Beckhoff EK1100, EL1004, EL2004, EL2828 and EL2889, built from the SII
//!   EEPROM images of real terminals (`data/`), with the ESC's registers, EEPROM interface, AL
//!   state machine, SyncManagers and FMMUs.
//! - [`SimBus`]: devices in ring order; datagrams (APRD/APWR, FPRD/FPWR, BRD/BWR, LRD/LWR/LRW,
//!   FRMW) with working counters as real ESCs count them; inputs, outputs and faults for tests.
//! - [`inproc`]: the bus as ethercrab's network, in process, through its `PduTx`/`PduRx`.
//!
//! ```
//! use ethercat_sim::{Device, SimBus, inproc};
//! use ethercrab::{MainDevice, MainDeviceConfig, PduStorage, Timeouts};
//!
//! static STORAGE: PduStorage<16, 1100> = PduStorage::new();
//! let (tx, rx, pdu_loop) = STORAGE.try_split().unwrap();
//! let bus = SimBus::new(vec![Device::ek1100(), Device::el1004(), Device::el2004()]);
//! let _driver = inproc::spawn(tx, rx, bus.clone()).unwrap();
//! let timeouts = Timeouts { eeprom: std::time::Duration::from_millis(500), ..Timeouts::default() };
//! let md = MainDevice::new(pdu_loop, timeouts, MainDeviceConfig::default());
//! let group = futures_lite::future::block_on(md.init_single_group::<4, 8>(ethercrab::std::ethercat_now))
//!     .unwrap();
//! let group = futures_lite::future::block_on(group.into_op(&md)).unwrap();
//! bus.set_input_bit(1, 0, true);
//! futures_lite::future::block_on(group.tx_rx(&md)).unwrap();
//! let el1004 = group.subdevice(&md, 1).unwrap();
//! assert_eq!(el1004.name(), "EL1004");
//! assert_eq!(el1004.inputs_raw()[0] & 1, 1);
//! ```
//!
//! What the simulator leaves out: distributed clocks (the devices do not announce DC support,
//! so ethercrab skips DC configuration), mailboxes and CoE (EL3004), and EEPROM busy timing.
#![deny(missing_docs)]

mod bus;
mod device;
pub mod inproc;
pub mod sii;

pub use bus::{ETHERTYPE, REPLY_SOURCE, SimBus};
pub use device::{Device, SiiSyncManager, al};
