//! The backend's settings: how frames reach the SubDevices and how it behaves on a fault.

use ethercrab::{MainDeviceConfig, PduRx, PduTx, Timeouts};
use std::fmt;

/// What the driver of a custom transport hands back: kept alive while the bus runs and dropped
/// after ethercrab has told the driver to exit (`MainDevice::release_all`), so a guard that
/// joins the driver's thread on drop shuts it down cleanly.
pub type DriverGuard = Box<dyn Send>;

/// A function that starts something driving ethercrab's frames (see [`Transport::custom`]).
pub type DriverFn =
    Box<dyn FnOnce(PduTx<'static>, PduRx<'static>) -> std::io::Result<DriverGuard> + Send>;

/// How frames reach the SubDevices.
pub enum Transport {
    /// A network interface (`eth0`, `enp3s0`): a raw socket driven by ethercrab's
    /// `tx_rx_task` on its own thread. Needs root or `CAP_NET_RAW`
    /// (`sudo setcap cap_net_raw=ep <program>`).
    Interface(String),
    /// Anything that drives ethercrab's `PduTx`/`PduRx`, e.g. the in-process simulated bus.
    Custom(DriverFn),
}

impl Transport {
    /// A custom driver: `start` receives ethercrab's frame queues and starts moving frames
    /// (usually on a thread of its own), returning a guard kept until the bus stops.
    ///
    /// With the simulated bus of `ethercat-sim`:
    /// `Transport::custom(move |tx, rx| Ok(Box::new(ethercat_sim::inproc::spawn(tx, rx, bus))))`,
    /// which feature `sim` writes for you: `Transport::simulated(&bus_config)` makes the
    /// simulated bus from the description and the transport to it.
    pub fn custom(
        start: impl FnOnce(PduTx<'static>, PduRx<'static>) -> std::io::Result<DriverGuard>
        + Send
        + 'static,
    ) -> Self {
        Transport::Custom(Box::new(start))
    }
}

impl fmt::Debug for Transport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Transport::Interface(name) => f.debug_tuple("Interface").field(name).finish(),
            Transport::Custom(_) => f.write_str("Custom(..)"),
        }
    }
}

/// What the struct's input variables hold while the bus does not answer correctly.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum InputsOnFault {
    /// Set every linked input to 0 / `false` (the default): a program that ignores the
    /// inputs-valid flag sees "no signal", which is the safe reading of normally-closed
    /// limit switches and broken wires, rather than a frozen "all good".
    #[default]
    Zero,
    /// Keep the last values read while the bus answered correctly (the program must watch the
    /// inputs-valid flag).
    KeepLast,
}

/// Settings of the backend. `Options::default()` suits real hardware.
#[derive(Clone, Debug)]
pub struct Options {
    /// ethercrab's timeouts. The PDU timeout bounds how long one `exchange` waits when a frame
    /// is lost; the default 30 ms is ethercrab's.
    pub timeouts: Timeouts,
    /// ethercrab's distributed-clock static drift compensation frames at start-up (its default
    /// 10 000; 100 is plenty on the simulated bus). They bring the SubDevices' clocks to the
    /// reference clock's time before SYNC0 is configured.
    pub dc_static_sync_iterations: u32,
    /// See [`InputsOnFault`].
    pub inputs_on_fault: InputsOnFault,
    /// While the bus is faulty, how often `exchange` tries to bring SubDevices that answer
    /// but are not in OP back to OP (a few datagrams per SubDevice; see
    /// [`EtherCatBackend::problems`](super::EtherCatBackend::problems)).
    pub recovery_interval: std::time::Duration,
    /// On a bus with distributed clocks, how often `exchange` reads each DC SubDevice's system
    /// time difference for `DcStatus` (one datagram per device;
    /// default 1 s, the first at the first exchange).
    pub dc_check_interval: std::time::Duration,
}

impl Options {
    /// Settings for the simulated bus: few DC sync frames, the DC status read every 100 ms,
    /// and timeouts with room for a busy
    /// machine (the simulated SubDevices answer from a thread that may wait for a core, where
    /// ethercrab's 10 ms EEPROM timeout assumes hardware answering within microseconds).
    pub fn simulated() -> Self {
        Options {
            timeouts: Timeouts {
                pdu: std::time::Duration::from_millis(200),
                eeprom: std::time::Duration::from_millis(500),
                ..Timeouts::default()
            },
            dc_static_sync_iterations: 100,
            dc_check_interval: std::time::Duration::from_millis(100),
            ..Options::default()
        }
    }
}

impl Default for Options {
    fn default() -> Self {
        Options {
            timeouts: Timeouts::default(),
            dc_static_sync_iterations: MainDeviceConfig::default().dc_static_sync_iterations,
            inputs_on_fault: InputsOnFault::Zero,
            recovery_interval: std::time::Duration::from_millis(100),
            dc_check_interval: std::time::Duration::from_secs(1),
        }
    }
}
