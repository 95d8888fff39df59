//! A ring of simulated SubDevices and the datagrams that pass through it, with working
//! counters counted as real ESCs count them (EMULATOR-NOTES §2).

use crate::al;
use crate::datagram::{self, Command, Datagram, Malformed};
use crate::dc::Position;
use crate::device::Device;
use crate::esc;
use std::sync::{Arc, Mutex, MutexGuard};
use std::time::Instant;

/// The source MAC of replies to ethercrab's frames: the first SubDevice sets bit 1 of the
/// first byte, and ethercrab drops frames that still carry its own 10:10:10:10:10:10
/// (EMULATOR-NOTES §1).
pub const REPLY_SOURCE: [u8; 6] = [0x12, 0x10, 0x10, 0x10, 0x10, 0x10];

/// Local clocks of the devices start this far apart (real terminals power up at different
/// times; capture \[A\] shows clocks at 0x158A.., 0x1636.., 0x15A9..).
const CLOCK_SPREAD_NS: u64 = 0x0B00_0000;

/// What the bus has seen.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FrameCounters {
    /// EtherCAT frames processed (each gave a reply).
    pub processed: u64,
    /// Datagrams in those frames.
    pub datagrams: u64,
    /// Frames of another ethertype, ignored.
    pub not_ethercat: u64,
    /// EtherCAT frames that were too short or whose lengths did not add up, ignored.
    pub malformed: u64,
}

struct Ring {
    devices: Vec<Device>,
    counters: FrameCounters,
    epoch: Instant,
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
    /// and 1 open, the last only port 0 (its port 1 closes the ring).
    pub fn new(mut devices: Vec<Device>) -> SimBus {
        let count = devices.len();
        for (index, d) in devices.iter_mut().enumerate() {
            d.position = Position {
                index,
                count,
                clock_offset: 0x1580_0000 + CLOCK_SPREAD_NS * ((index as u64 * 5) % 3),
                next_link_lost: false,
            };
            d.set_dl_status();
        }
        SimBus {
            ring: Arc::new(Mutex::new(Ring {
                devices,
                counters: FrameCounters::default(),
                epoch: Instant::now(),
            })),
        }
    }

    fn ring(&self) -> MutexGuard<'_, Ring> {
        // A panic elsewhere while the lock was held (a failed assertion in a test's closure)
        // leaves the registers as they were written; the bus stays usable.
        self.ring.lock().unwrap_or_else(|e| e.into_inner())
    }

    fn with<R>(&self, pos: usize, f: impl FnOnce(&mut Device) -> R) -> R {
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

    /// Sets input bit `bit` of the device at `pos` (bit 0 = first channel of its first input
    /// SyncManager). Devices without inputs ignore it.
    pub fn set_input_bit(&self, pos: usize, bit: usize, value: bool) {
        self.with(pos, |d| {
            if let Some(area) = d.areas(4).first()
                && bit / 8 < area.len()
            {
                let a = area.start + bit / 8;
                let mask = 1 << (bit % 8);
                d.mem[a] = if value {
                    d.mem[a] | mask
                } else {
                    d.mem[a] & !mask
                };
            }
        })
    }

    /// Sets the input bytes of the device at `pos` (as many as its first input SyncManager
    /// holds).
    pub fn set_inputs(&self, pos: usize, bytes: &[u8]) {
        self.with(pos, |d| {
            if let Some(area) = d.areas(4).first() {
                let n = area.len().min(bytes.len());
                d.mem[area.start..area.start + n].copy_from_slice(&bytes[..n]);
            }
        })
    }

    /// The outputs the device at `pos` drives: its output SyncManagers' bytes in OP, zero in
    /// any other state (the terminals switch their outputs off outside OP).
    pub fn outputs(&self, pos: usize) -> Vec<u8> {
        self.with(pos, |d| {
            let op = d.al_state() == al::OP;
            d.areas(3)
                .iter()
                .flat_map(|area| d.mem[area.clone()].to_vec())
                .map(|b| if op { b } else { 0 })
                .collect()
        })
    }

    /// Output bit `bit` of the device at `pos`.
    pub fn output_bit(&self, pos: usize, bit: usize) -> bool {
        self.outputs(pos)
            .get(bit / 8)
            .is_some_and(|b| b >> (bit % 8) & 1 != 0)
    }

    /// The AL state of the device at `pos` (1 INIT, 2 PRE-OP, 4 SAFE-OP, 8 OP).
    pub fn al_state(&self, pos: usize) -> u8 {
        self.with(pos, |d| d.al_state())
    }

    /// The AL status code (0x0134) of the device at `pos`.
    pub fn al_status_code(&self, pos: usize) -> u16 {
        self.with(pos, |d| d.al_status_code())
    }

    /// Makes the device at `pos` stop answering as a real one does: the link into its port 0
    /// goes down (the device lost power, or its cable was pulled), so the device before it
    /// closes its port 1 (DL status shows the lost link) and frames turn back there. Neither
    /// this device nor any device behind it sees a frame: they do not act on any datagram,
    /// do not count working counters and do not increment auto-increment addresses (APRD
    /// and FPRD to them get working counter 0, a BRD counts only the devices before). With
    /// `pos` 0 no device answers. `true` restores the link; the devices kept their registers,
    /// as after a pulled and re-plugged cable (add [`power_cycle`](Self::power_cycle) for a
    /// device that lost its power).
    pub fn set_responding(&self, pos: usize, responding: bool) {
        let mut ring = self.ring();
        let n = ring.devices.len();
        assert!(pos < n, "no SubDevice at position {pos}: the bus has {n}");
        ring.devices[pos].faults.link_lost = !responding;
        for i in 0..n {
            let lost = ring.devices.get(i + 1).is_some_and(|d| d.faults.link_lost);
            let d = &mut ring.devices[i];
            d.position.next_link_lost = lost;
            d.set_dl_status();
        }
    }

    /// Restarts the device at `pos` as after a loss of power: its registers and process
    /// RAM return to their power-on values (AL state INIT, station address 0, SyncManagers
    /// and FMMUs off, outputs off, station alias reloaded), its EEPROM keeps its contents.
    /// A MainDevice must address and configure it again. Call it while the device is off the
    /// ring ([`set_responding`](Self::set_responding) `false`) to model an outage, or on its
    /// own for a short power dip.
    pub fn power_cycle(&self, pos: usize) {
        self.with(pos, |d| d.power_on_reset())
    }

    /// The SyncManager watchdog of the device at `pos` expires, as when process data stopped
    /// arriving for longer than its watchdog time (100 ms by default on Beckhoff terminals):
    /// the device drops to SAFE-OP (or stays lower), switches its outputs off and reports AL
    /// status 0x0014 with AL status code 0x001B ([`al::SYNC_MANAGER_WATCHDOG`]). It ignores
    /// state requests until one carries the error-acknowledge bit (AL control bit 4). The
    /// simulator has no clock of its own to trip it: a test injects it.
    pub fn trip_watchdog(&self, pos: usize) {
        self.with(pos, |d| d.trip_watchdog())
    }

    /// Changes the identity the device at `pos` reports from its EEPROM (a different
    /// terminal in this slot).
    pub fn set_identity(&self, pos: usize, vendor: u32, product: u32, revision: u32) {
        self.with(pos, |d| d.set_identity(vendor, product, revision))
    }

    /// Makes the device at `pos` refuse requests for AL state `state` (see [`al`]): it keeps
    /// its state, sets the error bit 4 of AL status and reports `code` in AL status code
    /// 0x0134, as a terminal with a microcontroller does.
    pub fn refuse_transition(&self, pos: usize, state: u8, code: u16) {
        self.with(pos, |d| d.faults.refuse(state, code))
    }

    /// Lets the device at `pos` accept requests for `state` again.
    pub fn accept_transition(&self, pos: usize, state: u8) {
        self.with(pos, |d| d.faults.accept(state))
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
    /// receive times follow the given time. Keep to one time base per bus.
    pub fn process_frame_at(&self, frame: &[u8], now_ns: u64) -> Option<Vec<u8>> {
        Self::process(&mut self.ring(), frame, now_ns)
    }

    fn process(ring: &mut Ring, frame: &[u8], now: u64) -> Option<Vec<u8>> {
        let mut out = frame.to_vec();
        let mut datagrams = 0;
        let devices = &mut ring.devices;
        let result = datagram::for_each(&mut out, |d| {
            datagrams += 1;
            process_datagram(devices, d, now);
        });
        match result {
            Ok(()) => {
                ring.counters.processed += 1;
                ring.counters.datagrams += datagrams;
                datagram::finish_reply(&mut out);
                Some(out)
            }
            Err(Malformed::NotEtherCat) => {
                ring.counters.not_ethercat += 1;
                None
            }
            Err(_) => {
                ring.counters.malformed += 1;
                None
            }
        }
    }
}

/// One datagram through the ring, device by device in ring order.
fn process_datagram(devices: &mut [Device], d: &mut Datagram<'_>, now: u64) {
    let ado = d.ado as usize;
    let len = d.data.len();
    for dev in devices.iter_mut() {
        if dev.faults.link_lost {
            // The device before closed its port 1: the frame turns back there, and this
            // device and all behind it never see it.
            break;
        }
        match d.command {
            Command::Aprd | Command::Apwr | Command::Aprw => {
                if d.adp == 0 && dev.has(ado, len) {
                    access(dev, d.command, ado, d.data, &mut d.wkc, now);
                }
                d.adp = d.adp.wrapping_add(1);
            }
            Command::Fprd | Command::Fpwr | Command::Fprw => {
                if dev.addressed_as(d.adp) && dev.has(ado, len) {
                    access(dev, d.command, ado, d.data, &mut d.wkc, now);
                }
            }
            Command::Brd | Command::Bwr | Command::Brw => {
                if dev.has(ado, len) {
                    access(dev, d.command, ado, d.data, &mut d.wkc, now);
                }
                d.adp = d.adp.wrapping_add(1);
            }
            Command::Lrd | Command::Lwr | Command::Lrw => {
                let start = d.logical_address();
                logical(dev, d.command, start, d.data, &mut d.wkc);
            }
            Command::Frmw | Command::Armw => {
                // The addressed device reads; every other device writes the datagram's data
                // (devices before the reader write what the MainDevice sent, as real ESCs do).
                let reader = if d.command == Command::Frmw {
                    dev.addressed_as(d.adp)
                } else {
                    d.adp == 0
                };
                if dev.has(ado, len) {
                    if reader {
                        dev.read(ado, d.data, now);
                        d.wkc = d.wkc.wrapping_add(1);
                    } else {
                        dev.write(ado, d.data, now);
                        if esc::any_writable(ado, len) {
                            d.wkc = d.wkc.wrapping_add(1);
                        }
                    }
                }
                if d.command == Command::Armw {
                    d.adp = d.adp.wrapping_add(1);
                }
            }
            Command::Nop | Command::Unknown(_) => {}
        }
    }
}

/// A physical read, write or read-write at `ado`. Reads add 1, writes add 1 if they find a
/// writable byte, read-writes add 1 for the read and 2 for the write (ETG.1000.4).
fn access(
    dev: &mut Device,
    command: Command,
    ado: usize,
    data: &mut [u8],
    wkc: &mut u16,
    now: u64,
) {
    let len = data.len();
    match command {
        Command::Aprd | Command::Fprd => {
            dev.read(ado, data, now);
            *wkc = wkc.wrapping_add(1);
        }
        Command::Brd => {
            dev.read_or(ado, data, now);
            *wkc = wkc.wrapping_add(1);
        }
        Command::Apwr | Command::Fpwr | Command::Bwr => {
            dev.write(ado, data, now);
            if esc::any_writable(ado, len) {
                *wkc = wkc.wrapping_add(1);
            }
        }
        _ => {
            let new = data.to_vec();
            if command == Command::Brw {
                dev.read_or(ado, data, now);
            } else {
                dev.read(ado, data, now);
            }
            dev.write(ado, &new, now);
            *wkc = wkc.wrapping_add(if esc::any_writable(ado, len) { 3 } else { 1 });
        }
    }
}

/// LRD/LWR/LRW through the device's FMMUs, byte-wise (bit-granular FMMUs are not modelled:
/// ethercrab maps whole bytes, start bit 0 and end bit 7). Per device the working counter
/// gets +1 if a read FMMU matched, and +1 (LWR) or +2 (LRW) if a write FMMU matched.
fn logical(dev: &mut Device, command: Command, start: u32, data: &mut [u8], wkc: &mut u16) {
    let (mut read, mut wrote) = (false, false);
    let start = start as u64;
    let end = start + data.len() as u64;
    for fmmu in dev.fmmus() {
        let f_start = u64::from(fmmu.logical);
        let f_end = f_start + fmmu.len as u64;
        let (lo, hi) = (f_start.max(start), f_end.min(end));
        for l in lo..hi {
            let p = fmmu.physical + (l - f_start) as usize;
            let i = (l - start) as usize;
            if fmmu.reads && command != Command::Lwr {
                data[i] = dev.mem.get(p).copied().unwrap_or(0);
                read = true;
            }
            if fmmu.writes && command != Command::Lrd {
                if let Some(m) = dev.mem.get_mut(p) {
                    *m = data[i];
                }
                wrote = true;
            }
        }
    }
    let write_weight = if command == Command::Lrw { 2 } else { 1 };
    *wkc = wkc.wrapping_add(read as u16 + write_weight * wrote as u16);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A frame from 10:10:10:10:10:10 with one datagram.
    fn frame(cmd: u8, adp: u16, ado: u16, data: &[u8]) -> Vec<u8> {
        let mut f = vec![0xFF; 6];
        f.extend_from_slice(&[0x10; 6]);
        f.extend_from_slice(&crate::ETHERTYPE.to_be_bytes());
        f.extend_from_slice(&(0x1000 | (12 + data.len()) as u16).to_le_bytes());
        f.extend_from_slice(&[cmd, 0]);
        f.extend_from_slice(&adp.to_le_bytes());
        f.extend_from_slice(&ado.to_le_bytes());
        f.extend_from_slice(&(data.len() as u16).to_le_bytes());
        f.extend_from_slice(&[0, 0]);
        f.extend_from_slice(data);
        f.extend_from_slice(&[0, 0]);
        f
    }

    /// (data, wkc, adp) of the reply's datagram.
    fn answer(reply: &[u8], len: usize) -> (Vec<u8>, u16, u16) {
        let wkc = u16::from_le_bytes([reply[26 + len], reply[27 + len]]);
        let adp = u16::from_le_bytes([reply[18], reply[19]]);
        (reply[26..26 + len].to_vec(), wkc, adp)
    }

    #[test]
    fn replies_come_from_12_10_10_10_10_10_padded_to_60_bytes() {
        let bus = SimBus::new(vec![Device::ek1100(), Device::el2004()]);
        let reply = bus.process_frame(&frame(0x07, 0, 0, &[0])).unwrap();
        assert_eq!(reply[6..12], REPLY_SOURCE);
        assert_eq!(reply.len(), 60);
        assert_eq!(answer(&reply, 1), (vec![0x13], 2, 2)); // BRD: OR of types, one per device
    }

    #[test]
    fn the_station_alias_addresses_a_device_once_dl_control_enables_it() {
        let mut ek1100 = Device::ek1100();
        ek1100.eeprom_words_mut()[4] = 0x0ABC;
        ek1100.write(0x0502, &[0x00, 0x04], 0); // reload: 0x0012 = word 4
        let bus = SimBus::new(vec![ek1100, Device::el2004()]);
        let fprd = frame(0x04, 0x0ABC, 0x0012, &[0, 0]);
        assert_eq!(
            answer(&bus.process_frame(&fprd).unwrap(), 2).1,
            0,
            "alias not enabled"
        );
        bus.process_frame(&frame(0x02, 0, 0x0103, &[0x01])).unwrap(); // APWR DL control byte 3
        let (data, wkc, _) = answer(&bus.process_frame(&fprd).unwrap(), 2);
        assert_eq!((data, wkc), (vec![0xBC, 0x0A], 1));
    }

    #[test]
    fn a_device_that_stops_answering_takes_the_ring_behind_it_away_for_every_addressing_mode() {
        let bus = SimBus::new(vec![Device::ek1100(), Device::el2004(), Device::el2889()]);
        for i in 0..3u16 {
            let apwr = frame(
                0x02,
                0u16.wrapping_sub(i),
                0x0010,
                &(0x1000 + i).to_le_bytes(),
            );
            bus.process_frame(&apwr).unwrap();
        }
        bus.set_responding(1, false);
        // APRD of position 1 (the silent device) and position 2 (behind it): nobody answers,
        // in particular the EL2889 does not answer as position 1; only the EK1100 increments.
        for (adp, pos) in [(0xFFFF, 1), (0xFFFE, 2)] {
            let reply = bus
                .process_frame(&frame(0x01, adp, 0x0010, &[0, 0]))
                .unwrap();
            assert_eq!(
                answer(&reply, 2),
                (vec![0, 0], 0, adp.wrapping_add(1)),
                "APRD {pos}"
            );
        }
        let fprd = |station: u16| {
            answer(
                &bus.process_frame(&frame(0x04, station, 0x0010, &[0, 0]))
                    .unwrap(),
                2,
            )
        };
        assert_eq!(fprd(0x1000), (vec![0x00, 0x10], 1, 0x1000));
        assert_eq!(fprd(0x1001).1, 0, "FPRD of the silent device");
        assert_eq!(fprd(0x1002).1, 0, "FPRD of the device behind it");
        let brd = bus.process_frame(&frame(0x07, 0, 0x0000, &[0])).unwrap();
        assert_eq!(
            answer(&brd, 1),
            (vec![0x11], 1, 1),
            "BRD counts the EK1100 only"
        );
        // The EK1100 sees the lost link on its port 1 (DL status bit 5 clear, loop closed).
        assert_eq!(fprd_u16(&bus, 0x1000, 0x0110) & 0x0020, 0);
        bus.set_responding(1, true);
        assert_eq!(fprd(0x1002).1, 1);
        assert_eq!(fprd_u16(&bus, 0x1000, 0x0110), 0x5A31);
    }

    fn fprd_u16(bus: &SimBus, station: u16, ado: u16) -> u16 {
        let (data, _, _) = answer(
            &bus.process_frame(&frame(0x04, station, ado, &[0, 0]))
                .unwrap(),
            2,
        );
        u16::from_le_bytes([data[0], data[1]])
    }

    #[test]
    fn a_power_cycled_device_is_back_in_init_with_its_eeprom_but_no_address() {
        let mut el2004 = Device::el2004();
        el2004.eeprom_words_mut()[4] = 0x0042; // alias, reloaded at power-on
        let bus = SimBus::new(vec![Device::ek1100(), el2004]);
        bus.process_frame(&frame(0x02, 0xFFFF, 0x0010, &[0x01, 0x10]))
            .unwrap();
        bus.process_frame(&frame(
            0x05,
            0x1001,
            0x0800,
            &[0x00, 0x0F, 1, 0, 0x44, 0, 1, 0],
        ))
        .unwrap();
        bus.process_frame(&frame(0x05, 0x1001, 0x0120, &[0x08, 0]))
            .unwrap();
        bus.set_inputs(1, &[0]);
        assert_eq!(bus.al_state(1), al::OP);
        bus.power_cycle(1);
        let d = bus.device(1);
        assert_eq!((d.al_status(), d.station_address()), (0x0001, 0));
        let mut sm0 = [0xFFu8; 8];
        d.register(0x0800, &mut sm0);
        assert_eq!(sm0, [0; 8]);
        assert_eq!(d.sii()[4], 0x0042);
        let mut alias = [0u8; 2];
        d.register(0x0012, &mut alias);
        assert_eq!(alias, [0x42, 0]);
        assert_eq!(fprd_u16(&bus, 0x1001, 0x0130), 0, "the old address is gone");
    }

    #[test]
    fn a_tripped_watchdog_holds_safe_op_with_code_0x001b_until_acknowledged() {
        let bus = SimBus::new(vec![Device::el2004()]);
        bus.process_frame(&frame(0x02, 0, 0x0010, &[0x00, 0x10]))
            .unwrap();
        bus.process_frame(&frame(0x05, 0x1000, 0x0120, &[0x08, 0]))
            .unwrap();
        bus.trip_watchdog(0);
        assert_eq!(
            (bus.device(0).al_status(), bus.al_status_code(0)),
            (0x0014, 0x001B)
        );
        bus.process_frame(&frame(0x05, 0x1000, 0x0120, &[0x08, 0]))
            .unwrap();
        assert_eq!(
            bus.device(0).al_status(),
            0x0014,
            "OP without acknowledge is ignored"
        );
        bus.process_frame(&frame(0x05, 0x1000, 0x0120, &[0x14, 0]))
            .unwrap();
        bus.process_frame(&frame(0x05, 0x1000, 0x0120, &[0x08, 0]))
            .unwrap();
        assert_eq!(
            (bus.device(0).al_status(), bus.al_status_code(0)),
            (0x0008, 0)
        );
    }

    #[test]
    fn auto_increment_addresses_count_up_through_the_ring() {
        let bus = SimBus::new(vec![Device::ek1100(), Device::el2004(), Device::el2889()]);
        let reply = bus
            .process_frame(&frame(0x02, 0xFFFF, 0x0010, &[0x01, 0x10]))
            .unwrap();
        let (_, wkc, adp) = answer(&reply, 2);
        assert_eq!((wkc, adp), (1, 2)); // position -1 + 3 devices
        assert_eq!(bus.device(1).station_address(), 0x1001);
    }
}
