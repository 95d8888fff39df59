//! A plant model's view of the bus by link name: the entries of the bus description the bus
//! was built from, found by the `ethercat.<device>.<entry>` names links use, and their bits
//! in the simulated devices' process data.

use super::value::LinkValue;
use super::value::sealed::Slot;
use crate::{SimBus, al};
use plc_rules::bus::{BusLayout, EntryLayout, PdoDirection};
use plc_rules::link::Link;
use plc_rules::names::nearest;
use std::fmt;

/// SII SyncManager kinds of the process data.
const OUTPUTS: u8 = 3;
const INPUTS: u8 = 4;

/// The problem of a link on a bus made without a description.
const NO_NAMES: &str = "this bus was made from a list of devices, which names no entries: make \
                        it with `SimBus::from_description` from the bus description";

/// Why an I/O access by link name failed: the link and what to change.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LinkError {
    /// The link as given.
    pub link: String,
    /// What is wrong and what to do, a sentence.
    pub problem: String,
}

impl fmt::Display for LinkError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "`{}`: {}", self.link, self.problem)
    }
}

impl std::error::Error for LinkError {}

impl SimBus {
    /// Sets the input entry `link` (`ethercat.<device>.<entry>`, as `#[plc(link = ...)]`
    /// names it) of a bus made by [`from_description`](Self::from_description) to `value`: the
    /// bits the device sends at the next exchange. A device whose firmware writes its own
    /// inputs (the AKD drive) overwrites them at its next cycle.
    ///
    /// Refused, naming the link: an entry the description does not have (with the nearest
    /// name), an output entry, a value that does not fit the entry ([`LinkValue`]).
    ///
    /// ```
    /// use ethercat_sim::SimBus;
    /// use plc_rules::bus::{devices, BusConfig, PdoDirection};
    /// use plc_rules::IecType;
    /// let bus = SimBus::from_description(&BusConfig {
    ///     devices: vec![
    ///         devices::ek1100("coupler"),
    ///         devices::el1004("io").grouped(PdoDirection::Input, "digital_inputs", IecType::Uint),
    ///     ],
    /// })?;
    /// bus.set_input("ethercat.io.digital_inputs", 0b1001u16)?;
    /// assert_eq!(bus.input::<u16>("ethercat.io.digital_inputs")?, 0b1001);
    /// let err = bus.set_input("ethercat.io.digital_input", 1u16).unwrap_err();
    /// assert!(err.to_string().contains("did you mean `digital_inputs`?"), "{err}");
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn set_input<T: LinkValue>(&self, link: &str, value: T) -> Result<(), LinkError> {
        let entry = self.entry(link, PdoDirection::Input, "set")?;
        let slot = slot(&entry);
        let raw = value.encode(slot).ok_or_else(|| LinkError {
            link: link.to_owned(),
            problem: format!(
                "{value:?} does not fit this {}-bit {} entry: give a value of its range{}",
                slot.bits,
                slot.iec,
                real_hint(slot)
            ),
        })?;
        self.with(entry.device, |d| {
            let areas = d.areas(INPUTS);
            let mut bytes: Vec<u8> = areas
                .iter()
                .flat_map(|a| d.mem[a.clone()].to_vec())
                .collect();
            put_bits(&mut bytes, entry.bit_offset, entry.bits, raw)
                .ok_or_else(|| beyond(link, &entry, bytes.len()))?;
            let mut at = 0;
            for a in areas {
                let n = a.len();
                d.mem[a].copy_from_slice(&bytes[at..at + n]);
                at += n;
            }
            Ok(())
        })
    }

    /// The input entry `link` as the device sends it at the next exchange (what
    /// [`set_input`](Self::set_input) set, or a drive's own inputs).
    pub fn input<T: LinkValue>(&self, link: &str) -> Result<T, LinkError> {
        let entry = self.entry(link, PdoDirection::Input, "read")?;
        let bytes = self.with(entry.device, |d| {
            let areas = d.areas(INPUTS);
            areas
                .iter()
                .flat_map(|a| d.mem[a.clone()].to_vec())
                .collect::<Vec<u8>>()
        });
        decode(link, &entry, &bytes)
    }

    /// The output entry `link` as the device drives it: what the program wrote, in OP; 0 in
    /// any other state (the terminals switch their outputs off outside OP), as
    /// [`outputs`](Self::outputs) reads them.
    ///
    /// ```
    /// use ethercat_sim::SimBus;
    /// use plc_rules::bus::{devices, BusConfig};
    /// let bus = SimBus::from_description(&BusConfig {
    ///     devices: vec![devices::ek1100("coupler"), devices::el2004("lamps")],
    /// })?;
    /// assert!(!bus.output::<bool>("ethercat.lamps.output1")?);
    /// let err = bus.output::<bool>("ethercat.lamps.green").unwrap_err();
    /// assert!(err.to_string().contains("use one of `output1`"), "{err}");
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn output<T: LinkValue>(&self, link: &str) -> Result<T, LinkError> {
        let entry = self.entry(link, PdoDirection::Output, "read")?;
        let bytes = self.with(entry.device, |d| {
            let op = d.al_state() == al::OP;
            d.areas(OUTPUTS)
                .iter()
                .flat_map(|a| d.mem[a.clone()].to_vec())
                .map(|b| if op { b } else { 0 })
                .collect::<Vec<u8>>()
        });
        decode(link, &entry, &bytes)
    }

    /// The direction of the entry `link` names, or why the bus has no such entry (as
    /// [`set_input`](Self::set_input) refuses it): a check of a plant model's links before
    /// the bus runs, when a device whose process data the MainDevice configures over CoE
    /// (the AKD, the EL3004) has none to read yet.
    ///
    /// ```
    /// use ethercat_sim::SimBus;
    /// use plc_rules::bus::{devices, BusConfig, PdoDirection};
    /// let bus = SimBus::from_description(&BusConfig {
    ///     devices: vec![devices::ek1100("coupler"), devices::akd("axis")],
    /// })?;
    /// assert_eq!(bus.link_direction("ethercat.axis.statusword")?, PdoDirection::Input);
    /// let err = bus.input::<u16>("ethercat.axis.statusword").unwrap_err();
    /// assert!(err.to_string().contains("only once the bus went through PRE-OP"), "{err}");
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn link_direction(&self, link: &str) -> Result<PdoDirection, LinkError> {
        let error = |problem: String| LinkError {
            link: link.to_owned(),
            problem,
        };
        let layout = self.layout.as_ref().ok_or_else(|| error(NO_NAMES.into()))?;
        let parsed = Link::parse(link).map_err(|e| error(e.to_string()))?;
        find(layout, &parsed).map(|e| e.direction).map_err(error)
    }

    /// Every link name of the bus description the bus was made from, in ring order and each
    /// device's entry order (inputs first); empty for a bus made from a list of devices.
    pub fn links(&self) -> Vec<String> {
        let Some(layout) = &self.layout else {
            return Vec::new();
        };
        layout
            .entries
            .iter()
            .map(|e| format!("ethercat.{}.{}", layout.names[e.device], e.name))
            .collect()
    }

    /// The entry `link` names, if the bus has names and the entry has `direction`; else why
    /// not. `verb` says what the caller does, for the message.
    fn entry(
        &self,
        link: &str,
        direction: PdoDirection,
        verb: &str,
    ) -> Result<EntryLayout, LinkError> {
        let error = |problem: String| LinkError {
            link: link.to_owned(),
            problem,
        };
        let Some(layout) = &self.layout else {
            return Err(error(NO_NAMES.into()));
        };
        let parsed = Link::parse(link).map_err(|e| error(e.to_string()))?;
        let entry = find(layout, &parsed).map_err(error)?;
        if entry.direction != direction {
            let (other, how) = match entry.direction {
                PdoDirection::Input => ("input", "read it with `input` or set it with `set_input`"),
                PdoDirection::Output => ("output", "read it with `output`"),
            };
            return Err(error(format!(
                "`{}` is an {other} entry, which cannot be {verb} as an {}: {how}",
                entry.name,
                direction.name()
            )));
        }
        Ok(entry.clone())
    }
}

/// The entry of `layout` that `link` names, or what is wrong with the link.
fn find<'l>(layout: &'l BusLayout, link: &Link) -> Result<&'l EntryLayout, String> {
    if let Some(entry) = layout.entry(link.device, link.entry) {
        return Ok(entry);
    }
    let mut devices: Vec<&str> = layout.names.iter().map(String::as_str).collect();
    devices.dedup();
    if !devices.iter().any(|d| d.eq_ignore_ascii_case(link.device)) {
        return Err(format!(
            "the bus description has no device `{}`{}: use one of {}",
            link.device,
            did_you_mean(link.device, &devices),
            quoted(&devices)
        ));
    }
    let entries: Vec<&str> = layout
        .entries
        .iter()
        .filter(|e| layout.names[e.device].eq_ignore_ascii_case(link.device))
        .map(|e| e.name.as_str())
        .collect();
    if entries.is_empty() {
        return Err(format!(
            "device `{}` has no process data (a coupler?): name an entry of an I/O device",
            link.device
        ));
    }
    Err(format!(
        "device `{}` has no entry `{}`{}: use one of {}",
        link.device,
        link.entry,
        did_you_mean(link.entry, &entries),
        quoted(&entries)
    ))
}

fn did_you_mean(wrong: &str, names: &[&str]) -> String {
    nearest(wrong, names.iter().copied())
        .map(|n| format!(" (did you mean `{n}`?)"))
        .unwrap_or_default()
}

fn quoted(names: &[&str]) -> String {
    names
        .iter()
        .map(|n| format!("`{n}`"))
        .collect::<Vec<_>>()
        .join(", ")
}

fn slot(entry: &EntryLayout) -> Slot {
    Slot {
        bits: entry.bits,
        iec: entry.iec_type,
    }
}

fn real_hint(slot: Slot) -> &'static str {
    match (slot.iec.is_real(), slot.bits) {
        (true, 32) => " (an `f32`)",
        (true, _) => " (an `f64`)",
        (false, _) => " (a bool or an integer, not a float)",
    }
}

/// The entry's value out of its device's process data `bytes`.
fn decode<T: LinkValue>(link: &str, entry: &EntryLayout, bytes: &[u8]) -> Result<T, LinkError> {
    let raw = get_bits(bytes, entry.bit_offset, entry.bits)
        .ok_or_else(|| beyond(link, entry, bytes.len()))?;
    T::decode(raw, slot(entry)).ok_or_else(|| LinkError {
        link: link.to_owned(),
        problem: format!(
            "the {}-bit {} entry holds {raw:#x}, which a `{}` cannot hold: read it as a type \
             that holds the entry's values{}",
            entry.bits,
            entry.iec_type,
            std::any::type_name::<T>(),
            real_hint(slot(entry))
        ),
    })
}

/// An entry that lies beyond the device's process data in the simulation.
fn beyond(link: &str, entry: &EntryLayout, bytes: usize) -> LinkError {
    LinkError {
        link: link.to_owned(),
        problem: format!(
            "the entry is bits {}..{} of the {} data of the device at ring position {}, which \
             has {bytes} bytes of it now: a device whose process data the MainDevice configures \
             over CoE (the AKD, the EL3004) has its size only once the bus went through \
             PRE-OP; otherwise make the description's entries those of the device, as a bus \
             scan reports them",
            entry.bit_offset,
            entry.bit_offset + entry.bits as usize,
            entry.direction,
            entry.device
        ),
    }
}

/// `bits` bits from bit `offset` of `bytes`, least significant first; `None` past the end.
fn get_bits(bytes: &[u8], offset: usize, bits: u32) -> Option<u64> {
    let mut raw = 0u64;
    for i in 0..bits.min(64) as usize {
        let at = offset + i;
        let bit = bytes.get(at / 8)? >> (at % 8) & 1;
        raw |= u64::from(bit) << i;
    }
    Some(raw)
}

/// Writes the low `bits` bits of `raw` from bit `offset` of `bytes`; `None` (nothing
/// written) if they do not all fit.
fn put_bits(bytes: &mut [u8], offset: usize, bits: u32, raw: u64) -> Option<()> {
    let bits = bits.min(64) as usize;
    if (offset + bits).div_ceil(8) > bytes.len() {
        return None;
    }
    for i in 0..bits {
        let at = offset + i;
        let mask = 1u8 << (at % 8);
        if raw >> i & 1 == 1 {
            bytes[at / 8] |= mask;
        } else {
            bytes[at / 8] &= !mask;
        }
    }
    Some(())
}

#[cfg(test)]
mod tests {
    use super::{get_bits, put_bits};

    #[test]
    fn bits_go_least_significant_first_across_bytes() {
        let mut bytes = [0u8; 3];
        put_bits(&mut bytes, 4, 12, 0xABC).unwrap();
        assert_eq!(bytes, [0xC0, 0xAB, 0x00]);
        assert_eq!(get_bits(&bytes, 4, 12), Some(0xABC));
        assert_eq!(get_bits(&bytes, 20, 8), None);
        assert_eq!(put_bits(&mut bytes, 20, 8, 1), None);
        assert_eq!(bytes, [0xC0, 0xAB, 0x00], "nothing written past the end");
    }
}
