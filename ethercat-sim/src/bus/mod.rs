//! A ring of simulated SubDevices and the datagrams that pass through it, with working
//! counters counted as real ESCs count them (EMULATOR-NOTES §2).
//!
//! This file holds the shared bus ([`SimBus`]): building it, its lock, what a test reads of
//! it, and frames in; beside it: [`routing`] (a frame's datagrams through the devices, with
//! working counters), [`io`] (inputs and outputs for tests), [`dc`] (distributed clocks and
//! SYNC0 as tests see them) and [`faults`] (fault injection).

mod dc;
mod faults;
mod io;
mod routing;
#[cfg(test)]
mod tests;

pub use routing::{FrameCounters, REPLY_SOURCE};

use crate::dc::{self as clocks, Position};
use crate::device::Device;
use std::sync::{Arc, Mutex, MutexGuard};
use std::time::Instant;

/// Local clocks of the devices start this far apart (real terminals power up at different
/// times; capture \[A\] shows clocks at 0x158A.., 0x1636.., 0x15A9..).
const CLOCK_SPREAD_NS: u64 = 0x0B00_0000;

/// The clock seed of [`SimBus::new`].
const DEFAULT_CLOCK_SEED: u64 = 0x00DC_C10C;

struct Ring {
    devices: Vec<Device>,
    counters: FrameCounters,
    epoch: Instant,
    /// Bus time of the last frame.
    now: u64,
}

/// Simulated SubDevices in ring order, shared between the transport and the test or example
/// that sets inputs, reads outputs and injects faults. Cloning gives another handle to the
/// same bus; every method takes the bus's lock briefly.
///
/// Device positions (`pos`) are ring positions, 0 for the device next to the MainDevice.
/// Methods taking a `pos` panic if there is no device there: that is a mistake in the test.
///
/// ```
/// use ethercat_sim::{Device, SimBus};
/// let bus = SimBus::new(vec![Device::ek1100(), Device::el1004(), Device::el2004()]);
/// bus.set_input_bit(1, 2, true);
/// assert_eq!(bus.device_names(), ["EK1100", "EL1004", "EL2004"]);
/// assert_eq!(bus.outputs(2), vec![0]); // not in OP yet: outputs are off
/// ```
#[derive(Clone)]
pub struct SimBus {
    ring: Arc<Mutex<Ring>>,
    /// The names of the bus description the bus was made from, for I/O by link name.
    #[cfg(feature = "description")]
    pub(crate) layout: Option<Arc<plc_rules::bus::BusLayout>>,
}

impl std::fmt::Debug for SimBus {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SimBus")
            .field("devices", &self.device_names())
            .field("counters", &self.counters())
            .finish()
    }
}

impl SimBus {
    /// A bus of `devices` in a line, in ring order: every device but the last has ports 0
    /// and 1 open, the last only port 0 (its port 1 closes the ring). The devices' local
    /// clocks drift as [`with_clock_seed`](Self::with_clock_seed) describes, with a fixed
    /// seed: every bus of the same devices has the same clocks.
    pub fn new(devices: Vec<Device>) -> SimBus {
        SimBus::with_clock_seed(devices, DEFAULT_CLOCK_SEED)
    }

    /// A bus as [`new`](Self::new) makes it, whose devices' local clocks come from `seed`:
    /// each starts at its own time (hundreds of milliseconds apart, as terminals that
    /// powered up one after the other) and drifts by 5 to 100 ppm, faster or slower
    /// ([`Device::dc_drift_ppb`]). The same seed gives the same clocks; a MainDevice that
    /// distributes the reference clock's time (ethercrab's static drift compensation and
    /// cyclic FRMW) brings their system times together through each device's time control
    /// loop.
    ///
    /// ```
    /// use ethercat_sim::{Device, SimBus};
    /// let bus = SimBus::with_clock_seed(vec![Device::ek1100(), Device::el2004()], 42);
    /// let again = SimBus::with_clock_seed(vec![Device::ek1100(), Device::el2004()], 42);
    /// let drift = bus.device(1).dc_drift_ppb();
    /// assert!((5_000..=100_000).contains(&drift.abs()));
    /// assert_eq!(drift, again.device(1).dc_drift_ppb());
    /// ```
    pub fn with_clock_seed(mut devices: Vec<Device>, seed: u64) -> SimBus {
        let count = devices.len();
        for (index, d) in devices.iter_mut().enumerate() {
            d.position = Position {
                index,
                count,
                next_link_lost: false,
            };
            let start = 0x1580_0000 + CLOCK_SPREAD_NS * ((index as u64 * 5) % 3);
            d.dc.clock = clocks::seeded(seed, index, start);
            d.set_dl_status();
        }
        SimBus {
            ring: Arc::new(Mutex::new(Ring {
                devices,
                counters: FrameCounters::default(),
                epoch: Instant::now(),
                now: 0,
            })),
            #[cfg(feature = "description")]
            layout: None,
        }
    }

    fn ring(&self) -> MutexGuard<'_, Ring> {
        // A panic elsewhere while the lock was held (a failed assertion in a test's closure)
        // leaves the registers as they were written; the bus stays usable.
        self.ring.lock().unwrap_or_else(|e| e.into_inner())
    }

    pub(crate) fn with<R>(&self, pos: usize, f: impl FnOnce(&mut Device) -> R) -> R {
        let mut ring = self.ring();
        let n = ring.devices.len();
        let d = ring
            .devices
            .get_mut(pos)
            .unwrap_or_else(|| panic!("no SubDevice at position {pos}: the bus has {n}"));
        f(d)
    }

    /// Model names in ring order.
    pub fn device_names(&self) -> Vec<String> {
        self.ring()
            .devices
            .iter()
            .map(|d| d.name().to_string())
            .collect()
    }

    /// Number of devices.
    pub fn len(&self) -> usize {
        self.ring().devices.len()
    }

    /// Whether the bus has no devices.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// A copy of the device at `pos` with its registers as they are now.
    pub fn device(&self, pos: usize) -> Device {
        self.with(pos, |d| d.clone())
    }

    /// EtherCAT frames processed so far.
    pub fn frames(&self) -> u64 {
        self.ring().counters.processed
    }

    /// Frame and datagram counters.
    pub fn counters(&self) -> FrameCounters {
        self.ring().counters
    }

    /// The AL state of the device at `pos` (1 INIT, 2 PRE-OP, 4 SAFE-OP, 8 OP).
    pub fn al_state(&self, pos: usize) -> u8 {
        self.with(pos, |d| d.al_state())
    }

    /// The AL status code (0x0134) of the device at `pos`.
    pub fn al_status_code(&self, pos: usize) -> u16 {
        self.with(pos, |d| d.al_status_code())
    }

    /// Processes one Ethernet frame as the ring would and returns the frame that comes back
    /// (source MAC with bit 1 set, padded to 60 bytes), or `None` for a frame that is not
    /// EtherCAT or is malformed (counted, never a panic).
    pub fn process_frame(&self, frame: &[u8]) -> Option<Vec<u8>> {
        let mut ring = self.ring();
        // Bus time: nanoseconds since the bus was made.
        let now = ring.epoch.elapsed().as_nanos() as u64;
        Self::process(&mut ring, frame, now)
    }

    /// [`process_frame`](Self::process_frame) at bus time `now_ns` instead of the bus's
    /// clock, for replaying captures with their timestamps: EEPROM busy times and DC
    /// receive times, local clocks and SYNC0 follow the given time. Keep to one time base per
    /// bus.
    pub fn process_frame_at(&self, frame: &[u8], now_ns: u64) -> Option<Vec<u8>> {
        Self::process(&mut self.ring(), frame, now_ns)
    }

    fn process(ring: &mut Ring, frame: &[u8], now: u64) -> Option<Vec<u8>> {
        ring.now = now;
        routing::process(&mut ring.devices, &mut ring.counters, frame, now)
    }
}
