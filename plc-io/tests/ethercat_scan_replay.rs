//! The scan's EEPROM reads against real terminals: the captures in `ethercat-sim/data` hold
//! real Beckhoff terminals answering ethercrab's EEPROM reads. A scan of a simulated bus of the
//! same terminals must have read, at every EEPROM word a capture shows, the bytes the real
//! terminal gave there.
//!
//! In a capture, each EEPROM read is a write of the read command and word address to register
//! 0x0502 of one station, then (once not busy) a read of the data registers 0x0508-0x050F.
//! ethercrab gives station `0x1000 + n` to ring position n.

// The simulator's own pcapng reader (its packet times are not needed here).
#[allow(dead_code)]
#[path = "../../ethercat-sim/tests/common/pcapng.rs"]
mod pcapng;
#[path = "common/sim_bench.rs"]
mod sim_bench;

use ethercat_sim::{Device, SimBus};
use plc_io::ethercat::Options;
use plc_io::ethercat::scan::scan;
use std::collections::BTreeMap;

/// FPRD and FPWR, the datagrams of EEPROM access by station address.
const FPRD: u8 = 0x04;
const FPWR: u8 = 0x05;
const SII_CONTROL: u16 = 0x0502;
const SII_DATA: u16 = 0x0508;
const FIRST_STATION: u16 = 0x1000;

/// One datagram: command, station, register, data, working counter.
type Datagram<'a> = (u8, u16, u16, &'a [u8], u16);

fn datagrams(frame: &[u8]) -> Vec<Datagram<'_>> {
    let mut out = Vec::new();
    if frame.len() < 16 || frame[12..14] != [0x88, 0xA4] {
        return out;
    }
    let mut at = 16;
    while at + 12 <= frame.len() {
        let word = |i: usize| u16::from_le_bytes([frame[at + i], frame[at + i + 1]]);
        let (cmd, station, register, flags) = (frame[at], word(2), word(4), word(6));
        let len = usize::from(flags & 0x07FF);
        let Some(data) = frame.get(at + 10..at + 10 + len) else {
            break;
        };
        let Some(wkc) = frame.get(at + 10 + len..at + 12 + len) else {
            break;
        };
        out.push((
            cmd,
            station,
            register,
            data,
            u16::from_le_bytes([wkc[0], wkc[1]]),
        ));
        at += 12 + len;
        if flags & 0x8000 == 0 {
            break;
        }
    }
    out
}

/// Per ring position, the EEPROM bytes each captured read gave, by byte address; reads after
/// a position's first EEPROM write are left out (the EEPROM changed).
fn captured_reads(capture: &[u8]) -> BTreeMap<usize, BTreeMap<usize, u8>> {
    let packets: Vec<_> = pcapng::packets(capture)
        .into_iter()
        .filter(|p| p.data.len() >= 16 && p.data[12..14] == [0x88, 0xA4])
        .collect();
    let mut pending: BTreeMap<u16, usize> = BTreeMap::new();
    let mut written: Vec<u16> = Vec::new();
    let mut out: BTreeMap<usize, BTreeMap<usize, u8>> = BTreeMap::new();
    for w in packets.windows(2) {
        let (request, reply) = (&w[0].data, &w[1].data);
        // A request carries the MainDevice's MAC; the reply has bit 1 of the first byte set.
        if request[6] & 0x02 != 0 || reply[6] & 0x02 == 0 {
            continue;
        }
        for (sent, back) in datagrams(request).into_iter().zip(datagrams(reply)) {
            let (cmd, station, register, data, _) = sent;
            if cmd == FPWR && register == SII_CONTROL && data.len() >= 6 {
                let command = u16::from_le_bytes([data[0], data[1]]);
                if command & 0x0200 != 0 {
                    written.push(station);
                }
                if command & 0x0100 != 0 {
                    let word = u32::from_le_bytes([data[2], data[3], data[4], data[5]]);
                    pending.insert(station, 2 * word as usize);
                }
            }
            let (_, _, _, answer, wkc) = back;
            if cmd == FPRD
                && register == SII_DATA
                && wkc == 1
                && !written.contains(&station)
                && let Some(at) = pending.remove(&station)
            {
                let position = usize::from(station.wrapping_sub(FIRST_STATION));
                let bytes = out.entry(position).or_default();
                for (i, &b) in answer.iter().enumerate() {
                    bytes.insert(at + i, b);
                }
            }
        }
    }
    out
}

/// Scans `models` simulated, compares the EEPROM bytes read at `positions` with the capture's,
/// and returns how many bytes were compared at each.
fn replay(capture: &[u8], models: Vec<Device>, positions: &[usize]) -> Vec<usize> {
    let bus = SimBus::new(models);
    let scanned = scan(sim_bench::transport(&bus), &Options::simulated()).unwrap();
    let real = captured_reads(capture);
    let mut compared = Vec::new();
    for &pos in positions {
        let ours = &scanned.eeproms[pos];
        let theirs = &real[&pos];
        let mut n = 0;
        let mut differences = Vec::new();
        for (&at, &b) in theirs {
            if let Some(&o) = ours.get(at) {
                n += 1;
                if o != b {
                    differences.push(format!("byte {at:#06x}: scan {o:#04x}, real {b:#04x}"));
                }
            }
        }
        assert!(
            differences.is_empty(),
            "position {pos} ({}): {} differences:\n{}",
            scanned.devices[pos].order,
            differences.len(),
            differences.join("\n")
        );
        println!(
            "position {pos} ({}): {n} bytes compared of {} the scan read",
            scanned.devices[pos].order,
            ours.len()
        );
        compared.push(n);
    }
    compared
}

#[test]
fn the_scan_reads_what_a_real_ek1100_el2828_and_el2889_gave() {
    let n = replay(
        include_bytes!("../../ethercat-sim/data/replay-ek1100-el2828-el2889.pcapng"),
        vec![Device::ek1100(), Device::el2828(), Device::el2889()],
        &[0, 1, 2],
    );
    // Of the 240, 572 and 730 bytes the scan read (every category up to the end marker), the
    // capture covers the header's identity and mailbox words, General, the SyncManagers and
    // the PDOs (ethercrab skips most strings).
    assert_eq!(n, [78, 242, 370]);
}

#[test]
fn the_scan_reads_what_a_real_el3004_gave() {
    // The capture's coupler is an EK1914, which is not simulated: an EK1100 stands in at
    // position 0 and only the EL3004 is compared.
    let n = replay(
        include_bytes!("../../ethercat-sim/data/replay-ek1914-el3004-configure.pcapng"),
        vec![Device::ek1100(), Device::el3004()],
        &[1],
    );
    assert_eq!(n, [116]);
}

#[test]
fn the_scan_reads_what_real_el2004s_gave_to_an_early_ethercrab() {
    let n = replay(
        include_bytes!("../../ethercat-sim/data/rs-example-sii-el2004.pcapng"),
        vec![Device::ek1100(), Device::el2004(), Device::el2004()],
        &[1],
    );
    assert_eq!(n, [198]);
}

#[test]
fn the_scan_reads_what_a_real_ek1100_gave_before_its_alias_was_written() {
    let n = replay(
        include_bytes!("../../ethercat-sim/data/replay-ek1100-alias-address.pcapng"),
        vec![Device::ek1100(), Device::el2828(), Device::el2889()],
        &[0, 1, 2],
    );
    assert_eq!(n, [94, 100, 100]);
}
