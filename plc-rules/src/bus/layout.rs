//! Where each PDO entry sits in a SubDevice's process data, computed as ethercrab 0.7 lays it
//! out, and the bit-level access to it.
//!
//! ethercrab gives each SubDevice one input slice and one output slice of the group's process
//! data image (`inputs_raw()` / `outputs_raw()`). Within a slice, the SyncManagers of that
//! direction follow in index order, each taking ⌈its PDO bits / 8⌉ bytes
//! (`configure_pdos_eeprom`/`configure_pdos_coe`); within a SyncManager the PDO entries are
//! packed bit after bit, least significant bit first (EtherCAT is little endian).
//!
//! ```
//! use plc_rules::bus::{devices, layout::BusLayout, BusConfig};
//! let bus = BusConfig { devices: vec![devices::ek1100("c"), devices::el2889("q")] };
//! let layout = BusLayout::new(&bus);
//! let e = layout.entry("q", "output10").unwrap();
//! assert_eq!((e.bit_offset, e.bits), (9, 1)); // SM1 starts at byte 1
//! assert_eq!(layout.devices[1].output_bytes, 2);
//! ```

use super::{BusConfig, PdoDirection};
use crate::IecType;
use std::collections::BTreeMap;
use std::fmt;

/// The place of one PDO entry.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EntryLayout {
    /// Ring position of the device.
    pub device: usize,
    /// Index of the entry in the device's `entries`.
    pub entry: usize,
    /// The entry's name.
    pub name: String,
    /// Input or output.
    pub direction: PdoDirection,
    /// Bit offset from the start of the device's input or output slice.
    pub bit_offset: usize,
    /// Number of bits.
    pub bits: u32,
    /// The entry's IEC type.
    pub iec_type: IecType,
}

/// Sizes of one device's slices, as computed from its description.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct DeviceLayout {
    /// Bytes of `inputs_raw()`.
    pub input_bytes: usize,
    /// Bytes of `outputs_raw()`.
    pub output_bytes: usize,
}

/// The layout of a whole (validated) bus description.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BusLayout {
    /// Per device, in ring order.
    pub devices: Vec<DeviceLayout>,
    /// Device names, in ring order.
    pub names: Vec<String>,
    /// Every entry of every device.
    pub entries: Vec<EntryLayout>,
}

impl BusLayout {
    /// Lays out every entry of `bus` (call [`BusConfig::validate`] first; entries with an
    /// unknown type are skipped).
    pub fn new(bus: &BusConfig) -> Self {
        let mut entries = Vec::new();
        let mut devices = Vec::new();
        for (pos, d) in bus.devices.iter().enumerate() {
            for direction in [PdoDirection::Input, PdoDirection::Output] {
                // Start bit of each SyncManager: the SMs follow in index order, byte-aligned.
                let mut start = BTreeMap::new();
                let mut byte = 0;
                for (sm, bits) in d.sync_manager_bits(direction) {
                    start.insert(sm, byte * 8);
                    byte += bits.div_ceil(8);
                }
                for (i, e) in d.entries.iter().enumerate() {
                    if e.direction != direction {
                        continue;
                    }
                    let Some(ty) = e.iec() else { continue };
                    let Some(at) = start.get_mut(&e.sm) else {
                        continue;
                    };
                    entries.push(EntryLayout {
                        device: pos,
                        entry: i,
                        name: e.name.clone(),
                        direction,
                        bit_offset: *at,
                        bits: e.bits,
                        iec_type: ty,
                    });
                    *at += e.bits as usize;
                }
            }
            devices.push(DeviceLayout {
                input_bytes: d.process_data_bytes(PdoDirection::Input),
                output_bytes: d.process_data_bytes(PdoDirection::Output),
            });
        }
        BusLayout {
            devices,
            names: bus.devices.iter().map(|d| d.name.clone()).collect(),
            entries,
        }
    }

    /// The entry `entry` of the device (or module of consecutive devices) `device`, by the
    /// names links use, compared case-insensitively as links compare
    /// (`ethercat.RC8_0.statusword` is `ethercat.rc8_0.statusword`).
    pub fn entry(&self, device: &str, entry: &str) -> Option<&EntryLayout> {
        self.entries.iter().find(|e| {
            self.names[e.device].eq_ignore_ascii_case(device) && e.name.eq_ignore_ascii_case(entry)
        })
    }

    /// Checks the computed slice sizes against the ones ethercrab reports after reaching
    /// SAFE-OP/OP, `(inputs_raw().len(), outputs_raw().len())` per ring position.
    pub fn check_sizes(&self, reported: &[(usize, usize)]) -> Result<(), LayoutError> {
        let mut mismatches = Vec::new();
        for (pos, (want, got)) in self.devices.iter().zip(reported).enumerate() {
            if want.input_bytes != got.0 || want.output_bytes != got.1 {
                mismatches.push(SizeMismatch {
                    position: pos,
                    device: self.names[pos].clone(),
                    described: (want.input_bytes, want.output_bytes),
                    reported: *got,
                });
            }
        }
        if mismatches.is_empty() {
            Ok(())
        } else {
            Err(LayoutError { mismatches })
        }
    }
}

/// One device whose process data size differs from its description.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SizeMismatch {
    /// Ring position.
    pub position: usize,
    /// Name in the description.
    pub device: String,
    /// (input bytes, output bytes) the description gives.
    pub described: (usize, usize),
    /// (input bytes, output bytes) ethercrab configured.
    pub reported: (usize, usize),
}

/// The process data ethercrab configured does not match the bus description.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LayoutError {
    /// Every device that differs.
    pub mismatches: Vec<SizeMismatch>,
}

impl fmt::Display for LayoutError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(
            "the process data the SubDevices report does not match the bus description \
             (fix the PDO entries in the description, or the PDO assignment of the device):",
        )?;
        for m in &self.mismatches {
            write!(
                f,
                "\n  - position {} (`{}`): described {} input and {} output bytes, the device \
                 has {} input and {} output bytes",
                m.position, m.device, m.described.0, m.described.1, m.reported.0, m.reported.1
            )?;
        }
        Ok(())
    }
}

impl std::error::Error for LayoutError {}

/// Reads `bits` bits (1..=64) starting at bit `offset` of `buf`, least significant first.
/// Bits beyond `buf` read as 0.
///
/// ```
/// use plc_rules::bus::layout::read_bits;
/// assert_eq!(read_bits(&[0b1010_0000, 0b0000_0011], 5, 5), 0b11101);
/// ```
pub fn read_bits(buf: &[u8], offset: usize, bits: u32) -> u64 {
    if offset.is_multiple_of(8) && bits.is_multiple_of(8) {
        // Whole bytes: the common case of words and reals.
        let start = offset / 8;
        let n = (bits / 8) as usize;
        let mut le = [0u8; 8];
        if let Some(src) = buf.get(start..start + n) {
            le[..n].copy_from_slice(src);
            return u64::from_le_bytes(le);
        }
    }
    let mut v = 0u64;
    for i in 0..bits as usize {
        let at = offset + i;
        if buf.get(at / 8).is_some_and(|b| b & (1 << (at % 8)) != 0) {
            v |= 1 << i;
        }
    }
    v
}

/// Writes the low `bits` bits (1..=64) of `value` at bit `offset` of `buf`, keeping the other
/// bits. Bits beyond `buf` are dropped.
///
/// ```
/// use plc_rules::bus::layout::write_bits;
/// let mut buf = [0xffu8, 0x00];
/// write_bits(&mut buf, 6, 4, 0b0110);
/// assert_eq!(buf, [0b1011_1111, 0b0000_0001]);
/// ```
pub fn write_bits(buf: &mut [u8], offset: usize, bits: u32, value: u64) {
    if offset.is_multiple_of(8) && bits.is_multiple_of(8) {
        let start = offset / 8;
        let n = (bits / 8) as usize;
        if let Some(dst) = buf.get_mut(start..start + n) {
            dst.copy_from_slice(&value.to_le_bytes()[..n]);
            return;
        }
    }
    for i in 0..bits as usize {
        let at = offset + i;
        if let Some(b) = buf.get_mut(at / 8) {
            let mask = 1u8 << (at % 8);
            if value & (1 << i) != 0 {
                *b |= mask;
            } else {
                *b &= !mask;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bus::devices;

    #[test]
    fn bits_round_trip_at_every_offset() {
        for offset in 0..20 {
            for bits in [1u32, 3, 8, 13, 16, 32] {
                let mut buf = [0x5au8; 8];
                let v = 0x1234_5678_9abc_def0u64 & ((1u64 << bits) - 1);
                write_bits(&mut buf, offset, bits, v);
                assert_eq!(
                    read_bits(&buf, offset, bits),
                    v,
                    "offset {offset} bits {bits}"
                );
            }
        }
    }

    #[test]
    fn sync_managers_are_byte_aligned_entries_are_packed() {
        let mut d = devices::el1004("a");
        // Two 3-bit entries in SM0 and one in SM1: SM0 takes a byte, SM1 starts at byte 1.
        d.entries = vec![
            crate::bus::PdoEntry::new("x", PdoDirection::Input, 3, IecType::Byte),
            crate::bus::PdoEntry {
                sm: 1,
                ..crate::bus::PdoEntry::new("z", PdoDirection::Input, 3, IecType::Byte)
            },
            crate::bus::PdoEntry::new("y", PdoDirection::Input, 3, IecType::Byte),
        ];
        let l = BusLayout::new(&BusConfig { devices: vec![d] });
        assert_eq!(l.entry("a", "x").unwrap().bit_offset, 0);
        assert_eq!(l.entry("a", "y").unwrap().bit_offset, 3);
        assert_eq!(l.entry("a", "z").unwrap().bit_offset, 8);
        assert_eq!(l.devices[0].input_bytes, 2);
    }

    #[test]
    fn a_size_mismatch_names_the_device() {
        let bus = BusConfig {
            devices: vec![devices::ek1100("c"), devices::el2004("q")],
        };
        let err = BusLayout::new(&bus)
            .check_sizes(&[(0, 0), (0, 2)])
            .unwrap_err()
            .to_string();
        assert!(err.contains("position 1 (`q`): described 0 input and 1 output bytes, the device has 0 input and 2 output bytes"), "{err}");
    }
}
