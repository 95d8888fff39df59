//! The bus description: which SubDevices sit on the ring, in which order, under which names,
//! and what their process data looks like.
//!
//! ethercrab 0.7 tells the names of neither PDOs nor PDO entries (ethercrab issues #215/#228),
//! and ESI files repeat names ("Output" eight times), so the description names every entry
//! itself, as a configurator would. The file is TOML or JSON; see [`BusConfig`].
//!
//! A description can also be made from the SubDevices themselves (`plc bus scan`): [`sii`]
//! parses what a SubDevice's EEPROM holds, [`scan`] turns what was read into a description
//! with the names of [`naming`], and [`scan_file`] writes it as commented TOML.

use crate::IecType;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::fmt;
use std::path::Path;

mod dc;
pub mod devices;
mod hex;
pub mod layout;
pub mod links;
pub mod naming;
pub mod scan;
pub mod scan_file;
pub mod sii;
mod validate;

pub use dc::{DcConfig, MAX_DC_NS, written_duration};
pub use layout::{BusLayout, EntryLayout, LayoutError};
pub use links::{LinkIssue, LinkedVar, resolve_links};

use hex::{hex_u32, hex_u32_opt};

/// Most SubDevices on one bus (ethercrab's const-generic `MAX_SUBDEVICES`, which plc-io is
/// built with). A larger description is refused with a clear error.
pub const MAX_SUBDEVICES: usize = 16;

/// Most bytes of process data, inputs and outputs together (ethercrab's const-generic
/// `MAX_PDI`, which plc-io is built with). A larger description is refused with a clear error.
pub const MAX_PDI: usize = 1024;

/// A bus description: the SubDevices in ring order (position 0 is the one next to the
/// MainDevice).
///
/// TOML (numbers may be hexadecimal; `revision` is optional, and when given must match):
///
/// ```
/// use plc_rules::bus::BusConfig;
/// let bus = BusConfig::from_toml_str(r#"
///     [[devices]]
///     name = "coupler"
///     identity = { vendor = 0x2, product = 0x044c2c52 }
///
///     [[devices]]
///     name = "door"
///     identity = { vendor = 0x2, product = 0x03ec3052, revision = 0x00130000 }
///     entries = [
///         { name = "closed", direction = "input", bits = 1, type = "BOOL" },
///         { name = "spare", direction = "input", bits = 3, type = "BYTE" },
///     ]
///     startup = [{ index = 0x8000, subindex = 0x06, value = 1, bits = 8 }]
/// "#).unwrap();
/// assert_eq!(bus.devices[1].entries[1].bits, 3);
/// assert_eq!(bus.devices[1].startup[0].to_string(), "0x8000:06");
/// ```
///
/// JSON has no hexadecimal numbers, so identity values may also be strings such as
/// `"0x044c2c52"`:
///
/// ```
/// use plc_rules::bus::BusConfig;
/// let bus = BusConfig::from_json_str(r#"{ "devices": [
///     { "name": "coupler", "identity": { "vendor": 2, "product": "0x044c2c52" } }
/// ] }"#).unwrap();
/// assert_eq!(bus.devices[0].identity.product, 0x044c_2c52);
/// ```
///
/// Every problem of a description is reported at once ([`ConfigError`]): names that are not
/// identifiers or repeat, an entry wider than its type, a bus beyond the caps
/// ([`MAX_SUBDEVICES`], [`MAX_PDI`]), distributed clock settings out of range or differing
/// between devices ([`DcConfig`]).
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BusConfig {
    /// The SubDevices in ring order.
    pub devices: Vec<DeviceConfig>,
}

/// One SubDevice of the ring.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DeviceConfig {
    /// The name links use: `ethercat.<name>.<entry>` (an identifier).
    ///
    /// Consecutive SubDevices may share a name: they then form one module whose entries are
    /// the union of theirs (entry names unique across them). This is how an I/O block that is
    /// one device in the wiring diagram but several SubDevices on the ring (or a stand-in made
    /// of an input and an output terminal) keeps one name in the links.
    pub name: String,
    /// What the SubDevice at this position must report before the bus goes to OP.
    pub identity: Identity,
    /// Free text for people (e.g. the order number and where the terminal sits).
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub description: String,
    /// The PDO entries in the order of the SubDevice's PDO assignment, inputs and outputs
    /// mixed as they come (each direction is laid out on its own). Empty for a coupler.
    #[serde(default)]
    pub entries: Vec<PdoEntry>,
    /// CoE objects written in PRE-OP when the bus comes up, in order, each read back
    /// (a filter, a presentation, a range): `startup = [{ index = 0x8000, subindex = 0x06,
    /// value = 1, bits = 8 }]`.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub startup: Vec<StartupSdo>,
    /// Distributed clock: SYNC0 on this device, `dc = { sync0 = "1ms", shift = "250us" }`
    /// (see [`DcConfig`]). The device must have a DC unit; every device with `dc` on the bus
    /// gives the same settings. Absent (the default): the device's clock is not used.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dc: Option<DcConfig>,
}

/// One start-up SDO: a CoE object entry and the value written to it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StartupSdo {
    /// Object index (`0x8000`).
    #[serde(with = "hex_u32")]
    pub index: u32,
    /// Sub-index (`0x15`).
    #[serde(with = "hex_u32")]
    pub subindex: u32,
    /// The value; a negative one is written as its two's complement in `bits`.
    pub value: i64,
    /// The entry's width: 8, 16 or 32 bits.
    pub bits: u32,
}

impl StartupSdo {
    /// The value as the `bits`-wide unsigned number sent, if it fits (as signed or unsigned).
    pub fn raw(&self) -> Option<u32> {
        let bits = self.bits;
        if !matches!(bits, 8 | 16 | 32) {
            return None;
        }
        let (lo, hi) = (-(1i64 << (bits - 1)), (1i64 << bits) - 1);
        (lo..=hi)
            .contains(&self.value)
            .then(|| (self.value as u64 & ((1u64 << bits) - 1)) as u32)
    }
}

impl fmt::Display for StartupSdo {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:#06x}:{:02x}", self.index, self.subindex)
    }
}

impl DeviceConfig {
    /// Bits of this device's entries of `direction`, per SyncManager.
    pub fn sync_manager_bits(&self, direction: PdoDirection) -> BTreeMap<u8, usize> {
        let mut sms = BTreeMap::new();
        for e in self.entries.iter().filter(|e| e.direction == direction) {
            *sms.entry(e.sm).or_insert(0) += e.bits as usize;
        }
        sms
    }

    /// Bytes of this device's process data in `direction`: each SyncManager's bits rounded
    /// up to whole bytes.
    pub fn process_data_bytes(&self, direction: PdoDirection) -> usize {
        self.sync_manager_bits(direction)
            .values()
            .map(|bits| bits.div_ceil(8))
            .sum()
    }
}

/// The identity a SubDevice reports from its EEPROM (SII words 0x08..0x0D).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Identity {
    /// Vendor id (Beckhoff: 2).
    #[serde(with = "hex_u32")]
    pub vendor: u32,
    /// Product code (EL1004: 0x03ec3052).
    #[serde(with = "hex_u32")]
    pub product: u32,
    /// Revision; `None` accepts any revision.
    #[serde(default, with = "hex_u32_opt", skip_serializing_if = "Option::is_none")]
    pub revision: Option<u32>,
}

impl fmt::Display for Identity {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "vendor {:#x}, product {:#010x}",
            self.vendor, self.product
        )?;
        match self.revision {
            Some(r) => write!(f, ", revision {r:#010x}"),
            None => f.write_str(", any revision"),
        }
    }
}

/// Which way an entry's data flows, seen from the MainDevice.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PdoDirection {
    /// From the SubDevice to the program (TxPDO, an SM of type "inputs").
    Input,
    /// From the program to the SubDevice (RxPDO, an SM of type "outputs").
    Output,
}

impl PdoDirection {
    /// `"input"` or `"output"`.
    pub const fn name(self) -> &'static str {
        match self {
            PdoDirection::Input => "input",
            PdoDirection::Output => "output",
        }
    }
}

impl fmt::Display for PdoDirection {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(self.name())
    }
}

/// One PDO entry, or several consecutive 1-bit entries grouped under one name.
///
/// Entries of one direction are packed bit after bit in the order given, within their
/// SyncManager (`sm`, default 0), as ethercrab lays out the PDO assignment; each SyncManager's
/// data starts on a byte. Bit 0 of a multi-bit entry is its first bit in the process data, so
/// an entry `digital_inputs` of 4 bits over an EL1004's four 1-bit channels has channel 1 in
/// bit 0 and channel 4 in bit 3.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PdoEntry {
    /// The name links use (an identifier, unique within the device).
    pub name: String,
    /// Input or output.
    pub direction: PdoDirection,
    /// Bits in the process data: 1 for `BOOL`; up to the type's width for unsigned integers and
    /// bit strings (the value is zero-extended; an output drops the bits above); exactly the
    /// width for signed integers and reals.
    pub bits: u32,
    /// IEC type of the value, e.g. `"BOOL"`, `"UINT"`, `"WORD"`, `"INT"`, `"REAL"`.
    #[serde(rename = "type")]
    pub iec_type: String,
    /// SyncManager index, for SubDevices whose entries of one direction span several
    /// SyncManagers whose sizes are not whole bytes. Default 0.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub sm: u8,
}

fn is_zero(v: &u8) -> bool {
    *v == 0
}

impl PdoEntry {
    /// A 1-bit `BOOL` entry.
    pub fn bool(name: &str, direction: PdoDirection) -> Self {
        PdoEntry::new(name, direction, 1, IecType::Bool)
    }

    /// An entry of `bits` bits of type `iec_type` in SyncManager 0.
    pub fn new(name: &str, direction: PdoDirection, bits: u32, iec_type: IecType) -> Self {
        PdoEntry {
            name: name.to_owned(),
            direction,
            bits,
            iec_type: iec_type.name().to_owned(),
            sm: 0,
        }
    }

    /// The IEC type, if the `type` text names one.
    pub fn iec(&self) -> Option<IecType> {
        self.iec_type.parse().ok()
    }
}

/// Why a bus description was refused: every problem found, one per line.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ConfigError {
    /// Where the description came from (a file name, or "bus description").
    pub source: String,
    /// The problems, each a sentence that says what to change.
    pub problems: Vec<String>,
}

impl fmt::Display for ConfigError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: ", self.source)?;
        if let [one] = self.problems.as_slice() {
            return f.write_str(one);
        }
        write!(f, "{} problems:", self.problems.len())?;
        for p in &self.problems {
            write!(f, "\n  - {p}")?;
        }
        Ok(())
    }
}

impl std::error::Error for ConfigError {}

impl BusConfig {
    /// Parses and checks a TOML description.
    pub fn from_toml_str(text: &str) -> Result<Self, ConfigError> {
        let bus: BusConfig = toml::from_str(text).map_err(|e| ConfigError {
            source: "bus description".into(),
            problems: vec![format!("not a valid TOML bus description: {e}")],
        })?;
        bus.validate()?;
        Ok(bus)
    }

    /// Parses and checks a JSON description.
    pub fn from_json_str(text: &str) -> Result<Self, ConfigError> {
        let bus: BusConfig = serde_json::from_str(text).map_err(|e| ConfigError {
            source: "bus description".into(),
            problems: vec![format!("not a valid JSON bus description: {e}")],
        })?;
        bus.validate()?;
        Ok(bus)
    }

    /// Reads a description from a file: JSON if the name ends in `.json`, TOML otherwise.
    /// Errors name the file.
    pub fn load(path: impl AsRef<Path>) -> Result<Self, ConfigError> {
        let path = path.as_ref();
        let name = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|e| ConfigError {
            source: name.clone(),
            problems: vec![format!("cannot read the bus description: {e}")],
        })?;
        let json = path
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("json"));
        let parsed = if json {
            Self::from_json_str(&text)
        } else {
            Self::from_toml_str(&text)
        };
        parsed.map_err(|mut e| {
            e.source = name;
            e
        })
    }

    /// The description as TOML text (what [`from_toml_str`](Self::from_toml_str) reads back).
    pub fn to_toml_string(&self) -> String {
        // Serializing plain strings, numbers and arrays of tables cannot fail.
        toml::to_string_pretty(self).unwrap_or_default()
    }

    /// The devices named `name` (one, or the consecutive parts of a module), with their ring
    /// positions.
    pub fn devices_named<'a>(
        &'a self,
        name: &'a str,
    ) -> impl Iterator<Item = (usize, &'a DeviceConfig)> + 'a {
        self.devices
            .iter()
            .enumerate()
            .filter(move |(_, d)| d.name == name)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn json_identity_accepts_hex_strings_and_numbers() {
        let bus = BusConfig::from_json_str(
            r#"{"devices":[{"name":"a","identity":{"vendor":"0x2","product":1154,"revision":"0x00120000"}}]}"#,
        )
        .unwrap();
        assert_eq!(
            bus.devices[0].identity,
            Identity {
                vendor: 2,
                product: 1154,
                revision: Some(0x0012_0000)
            }
        );
        let err = BusConfig::from_json_str(
            r#"{"devices":[{"name":"a","identity":{"vendor":"two","product":1}}]}"#,
        )
        .unwrap_err();
        assert!(err.to_string().contains("`two` is not a number"), "{err}");
    }

    #[test]
    fn toml_round_trips() {
        let bus = BusConfig {
            devices: vec![
                crate::bus::devices::ek1100("coupler"),
                crate::bus::devices::el1004("inputs").grouped(
                    PdoDirection::Input,
                    "digital_inputs",
                    IecType::Uint,
                ),
            ],
        };
        let text = bus.to_toml_string();
        assert_eq!(BusConfig::from_toml_str(&text).unwrap(), bus, "{text}");
    }
}
