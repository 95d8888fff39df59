//! Simulated EtherCAT SubDevices that real [ethercrab](https://crates.io/crates/ethercrab)
//! drives to OP, so EtherCAT programs run and are tested without hardware.
//!
//! - [`Device`]: Beckhoff EK1100, EL1004, EL2004, EL2828, EL2889 and EL3004, built from the
//!   SII EEPROM images of real terminals (`data/`), with the ESC's registers, EEPROM interface
//!   (busy timing included), AL state machine, SyncManagers, FMMUs and distributed clocks
//!   (a local clock per device that drifts, seeded per bus, its time control loop and its
//!   SYNC0 output: [`SimBus::with_clock_seed`], [`Sync0`]); the EL3004 with a CoE mailbox
//!   (expedited SDO upload and download, normal upload of its device name 0x1008, the SDO
//!   information service with its objects' names and data types) through which ethercrab
//!   reads its PDO assignment; and a Kollmorgen AKD servo drive (order name
//!   `AKD`, alias `servo`; `Device::akd`), a CiA 402 drive over CoE with its state machine,
//!   cyclic synchronous position and velocity, homing on the current position, a motor model
//!   and a following error window.
//! - [`SimBus`]: devices in ring order; datagrams (APRD/APWR, FPRD/FPWR, BRD/BWR,
//!   LRD/LWR/LRW, FRMW and the read-write variants) with working counters as real ESCs count
//!   them; inputs, outputs and faults for tests.
//! - Feature `description`: the bus from a bus description alone
//!   (`SimBus::from_description`, `SimBus::from_description_file`: each device the
//!   description lists becomes the model with its identity; a device without a model is
//!   refused naming it), and its I/O by the link names of the description
//!   (`SimBus::set_input("ethercat.lamps.green", true)`, `SimBus::input`, `SimBus::output`,
//!   values as `LinkValue` converts them), for a plant model that animates a machine.
//!   The description's format and link rules are plc-rules'; without the feature the
//!   simulator depends on no plc crate.
//! - [`inproc`]: the bus as ethercrab's network, in process, through its `PduTx`/`PduRx`.
//! - [`raw`] (Linux): the bus behind a network interface (a veth pair), for a MainDevice
//!   using its own raw socket.
//!
//! A program drives the simulated bus exactly as it drives hardware. Init and the cycle loop,
//! from synchronous code:
//!
//! ```
//! use ethercat_sim::{Device, SimBus, inproc};
//! use ethercrab::{MainDevice, MainDeviceConfig, PduStorage, Timeouts};
//! use futures_lite::future::block_on;
//! use std::time::Duration;
//!
//! // One storage per MainDevice: ethercrab's frame queues are 'static and single-use.
//! static STORAGE: PduStorage<16, 1100> = PduStorage::new();
//! let (tx, rx, pdu_loop) = STORAGE.try_split().expect("storage used once");
//!
//! let bus = SimBus::new(vec![Device::ek1100(), Device::el1004(), Device::el2004()]);
//! let driver = inproc::spawn(tx, rx, bus.clone())?;
//!
//! let md = MainDevice::new(
//!     pdu_loop,
//!     // Room for a busy machine: the simulated devices answer from a thread that may wait
//!     // for a core, where ethercrab's 30 ms PDU and 10 ms EEPROM timeouts assume hardware.
//!     Timeouts {
//!         pdu: Duration::from_millis(200),
//!         eeprom: Duration::from_millis(200),
//!         ..Timeouts::default()
//!     },
//!     // 100 static DC sync frames instead of 10 000: enough here, where no test looks at
//!     // the clocks (they settle within about a hundred; see `tests/dc.rs`).
//!     MainDeviceConfig { dc_static_sync_iterations: 100, ..Default::default() },
//! );
//! let group = block_on(md.init_single_group::<4, 8>(ethercrab::std::ethercat_now)).unwrap();
//! let group = block_on(group.into_op(&md)).unwrap();
//!
//! bus.set_input_bit(1, 0, true); // EL1004 channel 1
//! for _cycle in 0..3 {
//!     group.subdevice(&md, 2).unwrap().outputs_raw_mut()[0] = 0b0101; // EL2004
//!     let response = block_on(group.tx_rx(&md)).unwrap();
//!     assert_eq!(response.working_counter, 3); // EL1004 reads (+1), EL2004 writes (+2)
//! }
//! assert_eq!(group.subdevice(&md, 1).unwrap().inputs_raw()[0] & 1, 1);
//! assert_eq!(bus.outputs(2), [0b0101]);
//!
//! drop(group);
//! // SAFETY: the group is gone and no frame is in flight.
//! let _pdu_loop = unsafe { md.release_all() };
//! driver.stop(); // ethercrab asked it to exit; this joins its thread
//! # Ok::<(), std::io::Error>(())
//! ```
//!
//! Faults for tests ([`SimBus`]): a lost link (the device and the ring behind it stop
//! answering), a power cycle (back in INIT, unaddressed), a tripped SyncManager watchdog
//! (SAFE-OP, AL status code 0x001B), a wrong identity, a refused state change; and, on a
//! device before it goes on the bus, a CoE server that misanswers the SDO information service
//! ([`SdoInfoFault`], [`Device::set_sdo_info_fault`]).
//!
//! Not simulated: mailbox services other than expedited SDO transfers, normal uploads and the
//! SDO information service (segmented SDOs, FoE, emergencies), the slower state changes of
//! terminals with a microcontroller, SYNC1 signals, bit-granular FMMUs, watchdog timing (a
//! test trips the watchdog), line errors (the RX error counters 0x0300-0x0307 count nothing;
//! a write clears them, as on an ESC), and EEPROM contents the captures do not hold (see
//! `data/README.md`).
#![deny(missing_docs)]

pub mod al;
mod bus;
mod coe;
mod datagram;
mod dc;
#[cfg(feature = "description")]
mod description;
mod device;
pub mod esc;
mod fault;
pub mod sii;
mod transport;

pub use bus::{FrameCounters, REPLY_SOURCE, SimBus};
pub use datagram::{Command, Datagram, ETHERTYPE, Malformed, datagram_frame};
pub use dc::{HOP_NS, Sync0};
#[cfg(feature = "description")]
pub use description::{DescriptionError, LinkError, LinkValue, Unmodelled};
pub use device::Device;
pub use esc::EscInfo;
pub use fault::SdoInfoFault;
pub use sii::SiiSyncManager;
pub use transport::inproc;
#[cfg(target_os = "linux")]
pub use transport::raw;
