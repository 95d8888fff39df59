//! A bus description from what the SubDevices say about themselves: their identity, their
//! EEPROM (SII) and, for CoE devices, their PDO assignment and mapping objects.
//!
//! The process data is taken as ethercrab 0.7 configures it, so the description's layout is
//! the one the bus comes up with: a SubDevice with a CoE mailbox gets the PDOs its objects
//! 0x1C1n assign to SyncManager n (and their mapping objects 0x16xx/0x1Axx); one without gets
//! the EEPROM's TxPDOs and RxPDOs, each on the SyncManager it names. Within a direction,
//! SyncManagers follow in index order and entries in PDO order. Names follow
//! [`naming`](super::naming); an entry's type comes from its CoE data type where the EEPROM (or,
//! for an entry the EEPROM does not describe, the device's object dictionary, read by the scan
//! through the SDO information service) has one that fits, else from its width (see
//! [`iec_type`]).
//!
//! ```
//! use plc_rules::bus::scan::{describe, ScannedDevice, ScannedEntry};
//! use plc_rules::bus::{Identity, PdoDirection};
//! let input = |name: &str, sub| ScannedEntry {
//!     name: Some(name.into()), index: 0x6000, subindex: sub,
//!     direction: PdoDirection::Input, bits: 1, data_type: Some(1), sm: 0,
//! };
//! let device = ScannedDevice {
//!     order: "EL1002".into(),
//!     description: "EL1002 2K. Dig. Eingang".into(),
//!     identity: Identity { vendor: 2, product: 0x03ea3052, revision: Some(0x0011_0000) },
//!     entries: vec![input("Input", 1), input("Input", 2)],
//!     note: None,
//! };
//! let bus = describe(&[device]).unwrap();
//! assert_eq!(bus.devices[0].name, "el1002");
//! assert_eq!(bus.devices[0].entries[1].name, "input_2");
//! assert_eq!(bus.devices[0].entries[1].iec_type, "BOOL");
//! ```

use super::naming::{device_names, entry_names};
use super::sii::{Sii, SiiPdo, SmUsage};
use super::{BusConfig, ConfigError, DeviceConfig, Identity, PdoDirection, PdoEntry};
use crate::IecType;

/// What a scan learned about one SubDevice.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ScannedDevice {
    /// Its order number (the EEPROM's General category), e.g. `"EL1004"`.
    pub order: String,
    /// Its long name from the EEPROM, or empty.
    pub description: String,
    /// Its identity, revision included.
    pub identity: Identity,
    /// Its PDO entries as the bus will be configured, gaps included.
    pub entries: Vec<ScannedEntry>,
    /// What the engineer should know of how its entries were named, for a comment in the
    /// scanned file (the device did not answer the SDO information service, so entries its
    /// EEPROM does not name are named by object index); `None` if nothing.
    pub note: Option<String>,
}

/// One PDO entry of a scanned SubDevice.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ScannedEntry {
    /// Its name in the EEPROM, if the EEPROM names it; else the name the device's CoE object
    /// dictionary gives the entry (or its object), if the scan could read one.
    pub name: Option<String>,
    /// Object index (0 for a gap).
    pub index: u16,
    /// Object sub-index.
    pub subindex: u8,
    /// Input or output.
    pub direction: PdoDirection,
    /// Bits in the process data.
    pub bits: u8,
    /// CoE data type (ETG.1000.6 table 63) from the EEPROM, if the EEPROM describes the entry,
    /// else from the device's object dictionary, if the scan could read it.
    pub data_type: Option<u8>,
    /// The SyncManager it is assigned to.
    pub sm: u8,
}

/// The PDOs assigned to one process-data SyncManager over CoE: its index, then each PDO's
/// index and its mapping entries (bit length in bits 0-7, sub-index 8-15, index 16-31).
pub type CoeAssignment = (u8, Vec<(u16, Vec<u32>)>);

impl ScannedDevice {
    /// The device as its EEPROM describes it, with the EEPROM's PDOs (a SubDevice without
    /// CoE).
    pub fn from_sii(sii: &Sii) -> Self {
        let mut entries = Vec::new();
        for (sm, usage) in process_data_sms(sii) {
            let (pdos, direction) = match usage {
                SmUsage::Inputs => (&sii.tx_pdos, PdoDirection::Input),
                _ => (&sii.rx_pdos, PdoDirection::Output),
            };
            for pdo in pdos.iter().filter(|p| p.sm == sm) {
                entries.extend(pdo.entries.iter().map(|e| ScannedEntry {
                    name: sii.string(e.name).map(str::to_owned),
                    index: e.index,
                    subindex: e.subindex,
                    direction,
                    bits: e.bits,
                    data_type: Some(e.data_type),
                    sm,
                }));
            }
        }
        ScannedDevice {
            entries,
            ..Self::identity_of(sii)
        }
    }

    /// The device with the PDOs its CoE objects assign (`assigned`, per SyncManager), named
    /// and typed from the EEPROM's PDO entries of the same object where it has them.
    pub fn from_coe(sii: &Sii, assigned: &[CoeAssignment]) -> Self {
        let mut entries = Vec::new();
        for (sm, pdos) in assigned {
            let direction = match sii.sync_managers.get(usize::from(*sm)).map(|s| s.usage) {
                Some(SmUsage::Inputs) => PdoDirection::Input,
                _ => PdoDirection::Output,
            };
            let described: &[SiiPdo] = match direction {
                PdoDirection::Input => &sii.tx_pdos,
                PdoDirection::Output => &sii.rx_pdos,
            };
            for (_, mapping) in pdos {
                for &m in mapping {
                    let (index, subindex, bits) = ((m >> 16) as u16, (m >> 8) as u8, m as u8);
                    let known = described
                        .iter()
                        .flat_map(|p| &p.entries)
                        .find(|e| index != 0 && (e.index, e.subindex) == (index, subindex));
                    entries.push(ScannedEntry {
                        name: known.and_then(|e| sii.string(e.name)).map(str::to_owned),
                        index,
                        subindex,
                        direction,
                        bits,
                        data_type: known.map(|e| e.data_type),
                        sm: *sm,
                    });
                }
            }
        }
        ScannedDevice {
            entries,
            ..Self::identity_of(sii)
        }
    }

    fn identity_of(sii: &Sii) -> Self {
        ScannedDevice {
            order: sii.order_name().unwrap_or_default().to_owned(),
            description: sii.device_name().unwrap_or_default().to_owned(),
            identity: Identity {
                vendor: sii.vendor,
                product: sii.product,
                revision: Some(sii.revision),
            },
            entries: Vec::new(),
            note: None,
        }
    }
}

/// The SyncManagers that carry process data, in index order, with their use.
pub fn process_data_sms(sii: &Sii) -> impl Iterator<Item = (u8, SmUsage)> + '_ {
    sii.sync_managers
        .iter()
        .enumerate()
        .filter(|(_, s)| matches!(s.usage, SmUsage::Inputs | SmUsage::Outputs))
        .filter_map(|(i, s)| Some((u8::try_from(i).ok()?, s.usage)))
}

/// The IEC type of an entry of `bits` bits and CoE `data_type`: the matching IEC type where
/// the data type names one and the width fits it (UNSIGNED16 -> `UINT`, INTEGER16 -> `INT`,
/// REAL32 -> `REAL`, BOOLEAN of 1 bit -> `BOOL`); otherwise, and for entries mapped over CoE
/// (whose mapping has no data type), `BOOL` for 1 bit and the narrowest bit string that
/// holds the bits (`BYTE`, `WORD`, `DWORD`, `LWORD`). `None` above 64 bits. (A scan fills in
/// the data type of an entry mapped over CoE from the device's object dictionary where it can.)
pub fn iec_type(data_type: Option<u8>, bits: u8) -> Option<IecType> {
    let named = match data_type? {
        0x01 => IecType::Bool,
        0x02 => IecType::Sint,
        0x03 => IecType::Int,
        0x04 => IecType::Dint,
        0x05 => IecType::Usint,
        0x06 => IecType::Uint,
        0x07 => IecType::Udint,
        0x08 => IecType::Real,
        0x11 => IecType::Lreal,
        0x15 => IecType::Lint,
        0x1B => IecType::Ulint,
        _ => return None,
    };
    let fits = match named {
        IecType::Bool => bits == 1,
        t if t.is_signed() || t.is_real() => u32::from(bits) == t.bits(),
        t => (1..=t.bits()).contains(&u32::from(bits)),
    };
    fits.then_some(named)
}

fn by_width(bits: u8) -> Option<IecType> {
    Some(match bits {
        1 => IecType::Bool,
        2..=8 => IecType::Byte,
        9..=16 => IecType::Word,
        17..=32 => IecType::Dword,
        33..=64 => IecType::Lword,
        _ => return None,
    })
}

/// The name an entry that neither the EEPROM nor the object dictionary names is given: `gap`
/// for a gap (index 0), else its object as `x<index>_<sub-index>` in hexadecimal
/// (`x6000_11`).
fn unnamed(e: &ScannedEntry) -> String {
    if e.index == 0 {
        "gap".into()
    } else {
        format!("x{:04x}_{:02x}", e.index, e.subindex)
    }
}

/// The bus description of the scanned devices in ring order, checked as
/// [`BusConfig::validate`] checks a file. An entry wider than 64 bits (no IEC type holds it)
/// is an error naming the device and the object.
pub fn describe(devices: &[ScannedDevice]) -> Result<BusConfig, ConfigError> {
    let names = device_names(&devices.iter().map(|d| d.order.as_str()).collect::<Vec<_>>());
    let mut problems = Vec::new();
    let mut out = Vec::new();
    for (pos, (d, name)) in devices.iter().zip(names).enumerate() {
        let texts: Vec<String> = d
            .entries
            .iter()
            .map(|e| {
                e.name
                    .clone()
                    .filter(|n| !n.is_empty())
                    .unwrap_or_else(|| unnamed(e))
            })
            .collect();
        let mut entries = Vec::new();
        for (e, entry_name) in d.entries.iter().zip(entry_names(&texts)) {
            let Some(ty) = iec_type(e.data_type, e.bits).or_else(|| by_width(e.bits)) else {
                problems.push(format!(
                    "device {pos} (`{name}`, {}), entry {:#06x}:{:02x}: {} bits, wider than the \
                     64 an IEC type holds; such an entry cannot be linked",
                    d.order, e.index, e.subindex, e.bits
                ));
                continue;
            };
            entries.push(PdoEntry {
                sm: e.sm,
                ..PdoEntry::new(&entry_name, e.direction, u32::from(e.bits), ty)
            });
        }
        out.push(DeviceConfig {
            name,
            identity: d.identity,
            description: d.description.clone(),
            entries,
            startup: Vec::new(),
            dc: None,
        });
    }
    let bus = BusConfig { devices: out };
    if let Err(mut e) = bus.validate() {
        problems.append(&mut e.problems);
    }
    if problems.is_empty() {
        Ok(bus)
    } else {
        Err(ConfigError {
            source: "scanned bus".into(),
            problems,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bus::sii::{SiiPdoEntry, SyncManager};

    fn sm(usage: SmUsage) -> SyncManager {
        SyncManager {
            start: 0x1000,
            len: 0,
            control: 0,
            enable: 1,
            usage,
        }
    }

    fn entry(index: u16, sub: u8, name: u8, data_type: u8, bits: u8) -> SiiPdoEntry {
        SiiPdoEntry {
            index,
            subindex: sub,
            name,
            data_type,
            bits,
        }
    }

    fn sii() -> Sii {
        Sii {
            vendor: 2,
            product: 0x0bbc_3052,
            revision: 0x0015_0000,
            strings: vec!["EL3004".into(), "Value".into(), "Status".into()],
            general: Some([0, 0, 1, 0]),
            sync_managers: vec![
                sm(SmUsage::MailboxOut),
                sm(SmUsage::MailboxIn),
                sm(SmUsage::Outputs),
                sm(SmUsage::Inputs),
            ],
            tx_pdos: vec![SiiPdo {
                index: 0x1a00,
                sm: 3,
                name: 0,
                entries: vec![
                    entry(0x6000, 0x11, 2, 0x03, 16),
                    entry(0x6000, 1, 3, 0x06, 9),
                ],
            }],
            ..Sii::default()
        }
    }

    #[test]
    fn eeprom_pdos_are_taken_per_sync_manager_with_their_names_and_types() {
        let d = ScannedDevice::from_sii(&sii());
        assert_eq!(d.order, "EL3004");
        assert_eq!(d.identity.revision, Some(0x0015_0000));
        let bus = describe(&[d]).unwrap();
        let e = &bus.devices[0].entries;
        assert_eq!(
            (e[0].name.as_str(), e[0].iec_type.as_str(), e[0].sm),
            ("value", "INT", 3)
        );
        assert_eq!(
            (e[1].name.as_str(), e[1].iec_type.as_str()),
            ("status", "UINT")
        );
    }

    #[test]
    fn pdos_on_a_sync_manager_of_another_use_are_left_out() {
        let mut s = sii();
        s.tx_pdos[0].sm = 2; // assigned to the outputs SyncManager: ethercrab ignores it
        assert!(ScannedDevice::from_sii(&s).entries.is_empty());
    }

    #[test]
    fn coe_mappings_take_names_from_the_eeprom_where_it_has_them() {
        let assigned = vec![(
            3u8,
            vec![(0x1a00u16, vec![0x6000_1110u32, 0x0000_0006, 0x6000_0f01])],
        )];
        let d = ScannedDevice::from_coe(&sii(), &assigned);
        let bus = describe(&[d]).unwrap();
        let e = &bus.devices[0].entries;
        let got: Vec<_> = e
            .iter()
            .map(|e| (e.name.as_str(), e.bits, e.iec_type.as_str(), e.direction))
            .collect();
        let input = PdoDirection::Input;
        assert_eq!(
            got,
            [
                ("value", 16, "INT", input),
                ("gap", 6, "BYTE", input),
                ("x6000_0f", 1, "BOOL", input),
            ]
        );
    }

    #[test]
    fn names_and_types_from_the_object_dictionary_are_made_like_eeprom_ones() {
        // What a scan fills in from Get Entry Description where the EEPROM names nothing: the
        // EL3004's "Value" (INTEGER16) of two channels, a drive's "Modes of operation"
        // (INTEGER8) and an entry the device refused to describe.
        let entry = |name: Option<&str>, index, sub, bits, data_type| ScannedEntry {
            name: name.map(str::to_owned),
            index,
            subindex: sub,
            direction: PdoDirection::Input,
            bits,
            data_type,
            sm: 3,
        };
        let d = ScannedDevice {
            entries: vec![
                entry(Some("Value"), 0x6000, 0x11, 16, Some(0x03)),
                entry(Some("Value"), 0x6010, 0x11, 16, Some(0x03)),
                entry(Some("Modes of operation"), 0x6060, 0, 8, Some(0x02)),
                entry(Some("Limit 1"), 0x6000, 0x03, 2, Some(0x31)),
                entry(None, 0x603f, 0, 16, None),
            ],
            ..ScannedDevice::from_sii(&sii())
        };
        let bus = describe(&[d]).unwrap();
        let got: Vec<_> = bus.devices[0]
            .entries
            .iter()
            .map(|e| (e.name.as_str(), e.iec_type.as_str()))
            .collect();
        assert_eq!(
            got,
            [
                ("value_1", "INT"),
                ("value_2", "INT"),
                ("modes_of_operation", "SINT"),
                ("limit_1", "BYTE"),
                ("x603f_00", "WORD"),
            ]
        );
    }

    #[test]
    fn types_fall_back_to_bit_strings_when_the_data_type_does_not_fit() {
        assert_eq!(iec_type(Some(0x03), 16), Some(IecType::Int));
        assert_eq!(
            iec_type(Some(0x03), 12),
            None,
            "a signed type needs its width"
        );
        assert_eq!(iec_type(Some(0x06), 12), Some(IecType::Uint));
        assert_eq!(iec_type(Some(0x01), 2), None);
        assert_eq!(iec_type(Some(0x31), 2), None, "BIT2 has no IEC type");
        assert_eq!(by_width(2), Some(IecType::Byte));
        assert_eq!(by_width(32), Some(IecType::Dword));
        assert_eq!(by_width(65), None);
    }

    #[test]
    fn an_entry_wider_than_64_bits_is_an_error_naming_device_and_object() {
        let mut d = ScannedDevice::from_sii(&sii());
        d.entries[0].bits = 96;
        let err = describe(&[d]).unwrap_err().to_string();
        assert!(
            err.contains("device 0 (`el3004`, EL3004), entry 0x6000:11: 96 bits"),
            "{err}"
        );
    }

    #[test]
    fn a_coupler_has_no_entries() {
        let mut s = sii();
        s.sync_managers.clear();
        s.strings[0] = "EK1100".into();
        let bus = describe(&[ScannedDevice::from_sii(&s)]).unwrap();
        assert_eq!(bus.devices[0].name, "ek1100");
        assert!(bus.devices[0].entries.is_empty());
    }
}
