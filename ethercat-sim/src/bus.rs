//! A ring of simulated SubDevices and the datagrams that pass through it, with working
//! counters counted as real ESCs count them (EMULATOR-NOTES §2).

use crate::device::{Device, al};
use std::sync::{Arc, Mutex, MutexGuard};

/// The MAC address in replies: real SubDevices set bit 1 of the first byte. ethercrab drops
/// frames whose source is its own 10:10:10:10:10:10 (EMULATOR-NOTES §1).
pub const REPLY_SOURCE: [u8; 6] = [0x12, 0x10, 0x10, 0x10, 0x10, 0x10];
/// EtherCAT's ethertype.
pub const ETHERTYPE: u16 = 0x88A4;

struct Ring {
    devices: Vec<Device>,
    frames: u64,
}

/// Simulated SubDevices in ring order, shared between the transport and the test or example
/// that sets inputs, reads outputs and injects faults. Cloning gives another handle to the
/// same bus.
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

impl SimBus {
    /// A bus of `devices` in ring order; the last one closes the ring (its port 1 is open).
    pub fn new(mut devices: Vec<Device>) -> SimBus {
        let n = devices.len();
        for (i, d) in devices.iter_mut().enumerate() {
            // DL status: links on ports 0 and 1 for all but the last, port 0 only for the last
            // (0x5A31 / 0x5613 as the real EK1100 and EL2889 report).
            d.set_u16(0x0110, if i + 1 < n { 0x5A31 } else { 0x5613 });
        }
        SimBus {
            ring: Arc::new(Mutex::new(Ring { devices, frames: 0 })),
        }
    }

    fn ring(&self) -> MutexGuard<'_, Ring> {
        // A panic while the lock was held cannot leave the registers inconsistent in a way
        // that matters more than losing the bus; keep going with the data.
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
    pub fn device_names(&self) -> Vec<&'static str> {
        self.ring().devices.iter().map(Device::name).collect()
    }

    /// Frames processed so far.
    pub fn frames(&self) -> u64 {
        self.ring().frames
    }

    /// Sets input bit `bit` of the device at `pos` (bit 0 = first channel).
    pub fn set_input_bit(&self, pos: usize, bit: usize, value: bool) {
        self.with(pos, |d| {
            if let Some(&(start, _)) = d.areas(4).first() {
                let a = start + bit / 8;
                let mask = 1 << (bit % 8);
                d.mem[a] = if value {
                    d.mem[a] | mask
                } else {
                    d.mem[a] & !mask
                };
            }
        })
    }

    /// Sets the input bytes of the device at `pos`.
    pub fn set_inputs(&self, pos: usize, bytes: &[u8]) {
        self.with(pos, |d| {
            if let Some(&(start, _)) = d.areas(4).first() {
                d.mem[start..start + bytes.len()].copy_from_slice(bytes);
            }
        })
    }

    /// The outputs the device at `pos` drives: its output SyncManagers' bytes in OP, zero in
    /// any other state (without a microcontroller the outputs are off outside OP).
    pub fn outputs(&self, pos: usize) -> Vec<u8> {
        self.with(pos, |d| {
            let op = d.al_state() == al::OP;
            d.areas(3)
                .iter()
                .flat_map(|&(start, len)| d.mem[start..start + len].to_vec())
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

    /// Makes the device at `pos` stop answering (as if its E-bus contact failed): frames pass
    /// it unprocessed and it adds nothing to working counters. `true` brings it back.
    pub fn set_responding(&self, pos: usize, responding: bool) {
        self.with(pos, |d| d.responding = responding)
    }

    /// Changes the identity the device at `pos` reports (a wrong terminal plugged in).
    pub fn set_identity(&self, pos: usize, vendor: u32, product: u32, revision: u32) {
        self.with(pos, |d| d.set_identity(vendor, product, revision))
    }

    /// Makes the device at `pos` refuse requests for AL state `state` with `code`.
    pub fn refuse_transition(&self, pos: usize, state: u8, code: u16) {
        self.with(pos, |d| d.refuse_transition(state, code))
    }

    /// Processes one Ethernet frame as the ring would and returns the frame that comes back,
    /// or `None` for a frame that is not EtherCAT or is malformed (never a panic).
    pub fn process_frame(&self, frame: &[u8]) -> Option<Vec<u8>> {
        if frame.len() < 16 || u16::from_be_bytes([frame[12], frame[13]]) != ETHERTYPE {
            return None;
        }
        let header = u16::from_le_bytes([frame[14], frame[15]]);
        if header >> 12 != 1 {
            return None;
        }
        let end = 16 + (header & 0x07FF) as usize;
        if end > frame.len() {
            return None;
        }
        let mut out = frame.to_vec();
        let mut ring = self.ring();
        ring.frames += 1;
        let mut at = 16;
        loop {
            if at + 12 > end {
                return None;
            }
            let flags = u16::from_le_bytes([out[at + 6], out[at + 7]]);
            let len = (flags & 0x07FF) as usize;
            let data_end = at + 10 + len;
            if data_end + 2 > end {
                return None;
            }
            let (head, rest) = out.split_at_mut(at + 10);
            let (data, wkc_bytes) = rest.split_at_mut(len);
            let cmd = head[at];
            let adp = u16::from_le_bytes([head[at + 2], head[at + 3]]);
            let ado = u16::from_le_bytes([head[at + 4], head[at + 5]]);
            let mut wkc = u16::from_le_bytes([wkc_bytes[0], wkc_bytes[1]]);
            let new_adp = datagram(&mut ring.devices, cmd, adp, ado, data, &mut wkc);
            head[at + 2..at + 4].copy_from_slice(&new_adp.to_le_bytes());
            wkc_bytes[..2].copy_from_slice(&wkc.to_le_bytes());
            at = data_end + 2;
            if flags & 0x8000 == 0 {
                break;
            }
        }
        out[6..12].copy_from_slice(&REPLY_SOURCE);
        if out.len() < 60 {
            out.resize(60, 0);
        }
        Some(out)
    }
}

/// One datagram through the ring. Returns the address position field as it comes back.
fn datagram(
    devices: &mut [Device],
    cmd: u8,
    adp: u16,
    ado: u16,
    data: &mut [u8],
    wkc: &mut u16,
) -> u16 {
    let ado = ado as usize;
    let len = data.len();
    let logical = (adp as u32) | ((ado as u32) << 16);
    let mut position = adp;
    let mut reader_value: Option<Vec<u8>> = None;
    for d in devices.iter_mut().filter(|d| d.responding) {
        match cmd {
            // APRD, APWR, APRW: the device that sees position 0 acts; each one increments it.
            0x01..=0x03 => {
                if position == 0 && d.has(ado, len) {
                    access(d, cmd - 0x01, ado, data, wkc);
                }
                position = position.wrapping_add(1);
            }
            // FPRD, FPWR, FPRW: the device with this configured address acts.
            0x04..=0x06 if d.station_address() == adp && d.has(ado, len) => {
                access(d, cmd - 0x04, ado, data, wkc);
            }
            // BRD (OR of everyone's bytes), BWR, BRW.
            0x07 => {
                if d.has(ado, len) {
                    d.read(ado, data, true);
                    *wkc += 1;
                }
                position = position.wrapping_add(1);
            }
            0x08 | 0x09 => {
                if d.has(ado, len) {
                    access(d, cmd - 0x07, ado, data, wkc);
                }
                position = position.wrapping_add(1);
            }
            // LRD, LWR, LRW: every device with an FMMU over the logical range.
            0x0A..=0x0C => logical_access(d, cmd, logical, data, wkc),
            // FRMW: the addressed device reads, every other device writes what it read.
            0x0E => {
                if d.station_address() == adp {
                    d.read(ado, data, false);
                    reader_value = Some(data.to_vec());
                    *wkc += 1;
                } else if reader_value.is_some() {
                    d.write(ado, data);
                    *wkc += 1;
                }
            }
            _ => {}
        }
    }
    position
}

/// `kind` 0 read, 1 write, 2 read-write (the read reply is the old value).
fn access(d: &mut Device, kind: u8, ado: usize, data: &mut [u8], wkc: &mut u16) {
    match kind {
        0 => {
            d.read(ado, data, false);
            *wkc += 1;
        }
        1 => {
            d.write(ado, data);
            *wkc += 1;
        }
        _ => {
            let new = data.to_vec();
            d.read(ado, data, false);
            d.write(ado, &new);
            *wkc += 3;
        }
    }
}

/// LRD/LWR/LRW: +1 if a read FMMU matched, +2 (LWR: +1) if a write FMMU matched.
fn logical_access(d: &mut Device, cmd: u8, start: u32, data: &mut [u8], wkc: &mut u16) {
    let (mut read, mut wrote) = (false, false);
    let end = start as u64 + data.len() as u64;
    let fmmus: Vec<_> = d.fmmus().collect();
    for (log, len, phys, reads, writes) in fmmus {
        let (f_start, f_end) = (log as u64, log as u64 + len as u64);
        let (lo, hi) = (f_start.max(start as u64), f_end.min(end));
        if lo >= hi {
            continue;
        }
        for l in lo..hi {
            let p = phys + (l - f_start) as usize;
            let i = (l - start as u64) as usize;
            if reads && cmd != 0x0B {
                data[i] = d.mem.get(p).copied().unwrap_or(0);
                read = true;
            }
            if writes && cmd != 0x0A {
                if let Some(m) = d.mem.get_mut(p) {
                    *m = data[i];
                }
                wrote = true;
            }
        }
    }
    *wkc += read as u16
        + if cmd == 0x0C {
            2 * wrote as u16
        } else {
            wrote as u16
        };
}
