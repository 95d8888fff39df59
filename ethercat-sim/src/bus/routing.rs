//! Frames through the ring: each datagram device by device in ring order, as each addressing
//! mode reaches the devices, physical and logical (FMMU) accesses, and working counters as
//! real ESCs count them; the reply frame and the frame counters.

use crate::datagram::{self, Command, Datagram, Malformed};
use crate::device::Device;
use crate::esc;

/// The source MAC of replies to ethercrab's frames: the first SubDevice sets bit 1 of the
/// first byte, and ethercrab drops frames that still carry its own 10:10:10:10:10:10
/// (EMULATOR-NOTES §1).
pub const REPLY_SOURCE: [u8; 6] = [0x12, 0x10, 0x10, 0x10, 0x10, 0x10];

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

/// One Ethernet frame through `devices` at bus time `now`, counted in `counters`: the frame
/// that comes back, or `None` for a frame that is not EtherCAT or is malformed.
pub(super) fn process(
    devices: &mut [Device],
    counters: &mut FrameCounters,
    frame: &[u8],
    now: u64,
) -> Option<Vec<u8>> {
    for dev in devices.iter_mut() {
        // SYNC0 pulses run on each device's own clock, whether the frame reaches it or not.
        dev.tick_dc(now);
    }
    let mut out = frame.to_vec();
    let mut datagrams = 0;
    let result = datagram::for_each(&mut out, |d| {
        datagrams += 1;
        process_datagram(devices, d, now);
    });
    match result {
        Ok(()) => {
            counters.processed += 1;
            counters.datagrams += datagrams;
            datagram::finish_reply(&mut out);
            Some(out)
        }
        Err(Malformed::NotEtherCat) => {
            counters.not_ethercat += 1;
            None
        }
        Err(_) => {
            counters.malformed += 1;
            None
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
                // A drive's firmware runs its cycle before the exchange (device/servo).
                dev.before_process_data(now, start, d.data.len());
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
