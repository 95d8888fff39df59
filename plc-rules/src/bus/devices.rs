//! Ready descriptions of the devices the simulated bus (`ethercat-sim`) models: Beckhoff
//! terminals, and a Kollmorgen AKD servo drive ([`akd`]).
//!
//! Identities are vendor 2 (Beckhoff) and the product codes of the real terminals; the
//! revision is left open (`None`), since terminals of one product ship in several revisions.
//! Channel entries are named `input1..inputN` / `output1..outputN` after the terminal's channel
//! numbers (ESI names them all "Input"/"Output"). [`DeviceConfig::grouped`] merges the channels
//! of one direction into one word, as the JSON variable-list format's impact67 `digital_inputs`.
//!
//! ```
//! use plc_rules::bus::{devices, BusConfig, PdoDirection};
//! use plc_rules::IecType;
//! let bus = BusConfig {
//!     devices: vec![
//!         devices::ek1100("coupler"),
//!         devices::el1004("di").grouped(PdoDirection::Input, "digital_inputs", IecType::Uint),
//!         devices::el2889("dout"),
//!     ],
//! };
//! bus.validate().unwrap();
//! assert_eq!(bus.devices[1].entries[0].bits, 4);
//! assert_eq!(bus.devices[2].entries[15].name, "output16");
//! ```

use super::{DeviceConfig, Identity, PdoDirection, PdoEntry};
use crate::IecType;

/// Beckhoff's EtherCAT vendor id.
pub const BECKHOFF: u32 = 0x0000_0002;

/// Product code of the EK1100 coupler.
pub const EK1100: u32 = 0x044c_2c52;
/// Product code of the EL1004 (4 digital inputs).
pub const EL1004: u32 = 0x03ec_3052;
/// Product code of the EL2004 (4 digital outputs).
pub const EL2004: u32 = 0x07d4_3052;
/// Product code of the EL2828 (8 digital outputs).
pub const EL2828: u32 = 0x0b0c_3052;
/// Product code of the EL2889 (16 digital outputs).
pub const EL2889: u32 = 0x0b49_3052;
/// Product code of the EL3004 (4 analog inputs).
pub const EL3004: u32 = 0x0bbc_3052;

fn beckhoff(name: &str, product: u32, description: &str, entries: Vec<PdoEntry>) -> DeviceConfig {
    DeviceConfig {
        name: name.to_owned(),
        identity: Identity {
            vendor: BECKHOFF,
            product,
            revision: None,
        },
        description: description.to_owned(),
        entries,
        startup: Vec::new(),
        dc: None,
    }
}

fn channels(
    prefix: &str,
    n: usize,
    direction: PdoDirection,
    sm: impl Fn(usize) -> u8,
) -> Vec<PdoEntry> {
    (1..=n)
        .map(|i| PdoEntry {
            sm: sm(i),
            ..PdoEntry::bool(&format!("{prefix}{i}"), direction)
        })
        .collect()
}

/// EK1100 EtherCAT coupler: no process data.
pub fn ek1100(name: &str) -> DeviceConfig {
    beckhoff(name, EK1100, "EK1100 EtherCAT coupler", Vec::new())
}

/// EL1004, 4 digital inputs 24 V: entries `input1..input4`, 1-bit `BOOL`, SM0.
pub fn el1004(name: &str) -> DeviceConfig {
    beckhoff(
        name,
        EL1004,
        "EL1004 4-channel digital input 24 V",
        channels("input", 4, PdoDirection::Input, |_| 0),
    )
}

/// EL2004, 4 digital outputs 24 V: entries `output1..output4`, 1-bit `BOOL`, SM0.
pub fn el2004(name: &str) -> DeviceConfig {
    beckhoff(
        name,
        EL2004,
        "EL2004 4-channel digital output 24 V",
        channels("output", 4, PdoDirection::Output, |_| 0),
    )
}

/// EL2828, 8 digital outputs 24 V 2 A: entries `output1..output8`, 1-bit `BOOL`, SM0.
pub fn el2828(name: &str) -> DeviceConfig {
    beckhoff(
        name,
        EL2828,
        "EL2828 8-channel digital output 24 V 2 A",
        channels("output", 8, PdoDirection::Output, |_| 0),
    )
}

/// EL2889, 16 digital outputs 24 V ground switching: entries `output1..output16`, 1-bit
/// `BOOL`; channels 1-8 in SM0, 9-16 in SM1 (as its SII says).
pub fn el2889(name: &str) -> DeviceConfig {
    beckhoff(
        name,
        EL2889,
        "EL2889 16-channel digital output 24 V",
        channels("output", 16, PdoDirection::Output, |i| u8::from(i > 8)),
    )
}

/// EL3004, 4 analog inputs ±10 V, with its default PDO assignment (TxPDOs 0x1A00, 0x1A02,
/// 0x1A04, 0x1A06 in SM3, 32 bits per channel). Per channel `N` (1-4): `chN_underrange`,
/// `chN_overrange` (`BOOL`), `chN_limit1`, `chN_limit2` (2-bit `USINT`), `chN_error` (`BOOL`),
/// `chN_reserved` (7 bits the terminal leaves unused, `BYTE`), `chN_txpdo_state`,
/// `chN_txpdo_toggle` (`BOOL`) and `chN_value` (16-bit `INT`, ±10 V = ±0x7FFF).
pub fn el3004(name: &str) -> DeviceConfig {
    let input = PdoDirection::Input;
    let entries = (1..=4)
        .flat_map(|n| {
            [
                PdoEntry::bool(&format!("ch{n}_underrange"), input),
                PdoEntry::bool(&format!("ch{n}_overrange"), input),
                PdoEntry::new(&format!("ch{n}_limit1"), input, 2, IecType::Usint),
                PdoEntry::new(&format!("ch{n}_limit2"), input, 2, IecType::Usint),
                PdoEntry::bool(&format!("ch{n}_error"), input),
                PdoEntry::new(&format!("ch{n}_reserved"), input, 7, IecType::Byte),
                PdoEntry::bool(&format!("ch{n}_txpdo_state"), input),
                PdoEntry::bool(&format!("ch{n}_txpdo_toggle"), input),
                PdoEntry::new(&format!("ch{n}_value"), input, 16, IecType::Int),
            ]
        })
        .map(|e| PdoEntry { sm: 3, ..e })
        .collect();
    beckhoff(name, EL3004, "EL3004 4-channel analog input ±10 V", entries)
}

impl DeviceConfig {
    /// Replaces every entry of `direction` by one entry `name` of type `iec_type` spanning all
    /// of them (their total bits, the first channel in bit 0), e.g. an EL2889's 16 outputs as
    /// one `UINT` word `digital_outputs`. The SyncManager is the first entry's; grouping
    /// entries of several SyncManagers whose sizes are whole bytes (as the EL2889's) keeps the
    /// layout. Check the result with [`BusConfig::validate`](super::BusConfig::validate): the
    /// type must be wide enough.
    pub fn grouped(mut self, direction: PdoDirection, name: &str, iec_type: IecType) -> Self {
        let bits: u32 = self
            .entries
            .iter()
            .filter(|e| e.direction == direction)
            .map(|e| e.bits)
            .sum();
        let Some(first) = self.entries.iter().position(|e| e.direction == direction) else {
            return self;
        };
        let sm = self.entries[first].sm;
        let group = PdoEntry {
            sm,
            ..PdoEntry::new(name, direction, bits, iec_type)
        };
        self.entries.retain(|e| e.direction != direction);
        self.entries.insert(first.min(self.entries.len()), group);
        self
    }
}

/// Kollmorgen's EtherCAT vendor id.
pub const KOLLMORGEN: u32 = 0x0000_006a;
/// Product code of the AKD servo drive.
pub const AKD: u32 = 0x0041_4b44;

/// Kollmorgen AKD servo drive (CiA 402 over CoE) with the process image of its 0x1600/0x1A00
/// mappings for cyclic synchronous position and velocity: outputs `controlword` (`UINT`),
/// `modes_of_operation` (`SINT`), `target_position`, `target_velocity` (`DINT`) in SM2;
/// inputs `statusword` (`UINT`), `modes_of_operation_display` (`SINT`),
/// `position_actual_value`, `velocity_actual_value`, `following_error_actual_value` (`DINT`),
/// `error_code` (`UINT`) in SM3. The names are `plc_core::motion::Cia402`'s members.
///
/// ```
/// let drive = plc_rules::bus::devices::akd("crosshead");
/// assert_eq!(drive.entries.len(), 10);
/// assert_eq!(drive.entries[2].name, "target_position");
/// ```
pub fn akd(name: &str) -> DeviceConfig {
    let (output, input) = (PdoDirection::Output, PdoDirection::Input);
    let entries = [
        ("controlword", output, 16, IecType::Uint),
        ("modes_of_operation", output, 8, IecType::Sint),
        ("target_position", output, 32, IecType::Dint),
        ("target_velocity", output, 32, IecType::Dint),
        ("statusword", input, 16, IecType::Uint),
        ("modes_of_operation_display", input, 8, IecType::Sint),
        ("position_actual_value", input, 32, IecType::Dint),
        ("velocity_actual_value", input, 32, IecType::Dint),
        ("following_error_actual_value", input, 32, IecType::Dint),
        ("error_code", input, 16, IecType::Uint),
    ]
    .map(|(entry, direction, bits, ty)| PdoEntry {
        sm: if direction == output { 2 } else { 3 },
        ..PdoEntry::new(entry, direction, bits, ty)
    });
    DeviceConfig {
        name: name.to_owned(),
        identity: Identity {
            vendor: KOLLMORGEN,
            product: AKD,
            revision: None,
        },
        description: "Kollmorgen AKD servo drive, CiA 402".to_owned(),
        entries: entries.to_vec(),
        startup: Vec::new(),
        dc: None,
    }
}
