//! The checks of a bus description: every problem at once, each naming the device and entry.

use super::{BusConfig, ConfigError, DeviceConfig, PdoDirection, PdoEntry};
use super::{MAX_PDI, MAX_SUBDEVICES};
use crate::TypeFamily;

impl BusConfig {
    /// Checks the description; every problem at once. The parsers call it; call it yourself for
    /// a description built in code.
    pub fn validate(&self) -> Result<(), ConfigError> {
        let mut problems = Vec::new();
        if self.devices.is_empty() {
            problems.push(
                "the bus has no devices: list the SubDevices in ring order under `devices`".into(),
            );
        }
        if self.devices.len() > MAX_SUBDEVICES {
            problems.push(format!(
                "the bus has {} devices, more than the {MAX_SUBDEVICES} plc-io is built for \
                 (ethercrab's MAX_SUBDEVICES): split the machine over two buses or raise \
                 `plc_io::ethercat::MAX_SUBDEVICES`",
                self.devices.len()
            ));
        }
        for (pos, d) in self.devices.iter().enumerate() {
            if !crate::link::is_identifier(&d.name) {
                problems.push(format!(
                    "device {pos}: name `{}` is not an identifier (letters, digits, underscores, \
                     not starting with a digit), so no link can name it: rename it, e.g. `el1004_0`",
                    d.name
                ));
            }
            // A name given to consecutive SubDevices makes them one module (see `DeviceConfig::name`).
            let module_start = self.devices[..pos]
                .iter()
                .rposition(|o| !o.name.eq_ignore_ascii_case(&d.name))
                .map_or(0, |p| p + 1);
            if let Some(first) = self.devices[..module_start]
                .iter()
                .position(|o| o.name.eq_ignore_ascii_case(&d.name))
            {
                problems.push(format!(
                    "device {pos}: name `{}` is already used by device {first}, and the devices between them have other names: give each device its own name (only consecutive devices may share a name, as parts of one module)",
                    d.name
                ));
            }
            for s in &d.startup {
                if s.index == 0 || s.index > 0xFFFF || s.subindex > 0xFF {
                    problems.push(format!(
                        "device {pos} (`{}`), start-up SDO {s}: an object is an index of 16 bits \
                         (not 0) and a sub-index of 8",
                        d.name
                    ));
                } else if s.raw().is_none() {
                    problems.push(format!(
                        "device {pos} (`{}`), start-up SDO {s}: {} does not fit {} bits (write \
                         `bits = 8`, `16` or `32`, the object's width, and a value it holds)",
                        d.name, s.value, s.bits
                    ));
                }
            }
            for (i, e) in d.entries.iter().enumerate() {
                check_entry(
                    pos,
                    &self.devices[module_start..pos],
                    d,
                    i,
                    e,
                    &mut problems,
                );
            }
        }
        let pdi: usize = self
            .devices
            .iter()
            .map(|d| {
                d.process_data_bytes(PdoDirection::Input)
                    + d.process_data_bytes(PdoDirection::Output)
            })
            .sum();
        super::dc::problems(self, &mut problems);
        if pdi > MAX_PDI {
            problems.push(format!(
                "the process data of this bus takes {pdi} bytes, more than the {MAX_PDI} plc-io \
                 is built for (ethercrab's MAX_PDI): raise `plc_io::ethercat::MAX_PDI`"
            ));
        }
        if problems.is_empty() {
            Ok(())
        } else {
            Err(ConfigError {
                source: "bus description".into(),
                problems,
            })
        }
    }
}

fn check_entry(
    pos: usize,
    module_before: &[DeviceConfig],
    d: &DeviceConfig,
    i: usize,
    e: &PdoEntry,
    problems: &mut Vec<String>,
) {
    let at = format!("device {pos} (`{}`), entry `{}`", d.name, e.name);
    if !crate::link::is_entry_path(&e.name) {
        problems.push(format!(
            "{at}: the name is not an identifier, or identifiers joined by dots (letters, \
             digits, underscores, not starting with a digit): rename it, e.g. `output1` or \
             `x.position`"
        ));
    }
    if module_before
        .iter()
        .flat_map(|o| &o.entries)
        .chain(&d.entries[..i])
        .any(|o| o.name.eq_ignore_ascii_case(&e.name))
    {
        problems.push(format!(
            "{at}: the name is used twice in this device: ESI files repeat names such as \
             \"Output\"; give each entry its own, e.g. `output1`, `output2` (devices sharing \
             a name share one set of entry names)"
        ));
    }
    let Some(ty) = e.iec() else {
        problems.push(format!(
            "{at}: `{}` is not an IEC type: use BOOL, SINT, INT, DINT, LINT, USINT, UINT, \
             UDINT, ULINT, REAL, LREAL, BYTE, WORD, DWORD or LWORD",
            e.iec_type
        ));
        return;
    };
    let width = ty.bits();
    let ok = match ty.family() {
        TypeFamily::String | TypeFamily::Time => {
            problems.push(format!(
                "{at}: {ty} is not a process data type: use an integer, real or bit-string type"
            ));
            return;
        }
        TypeFamily::Bool => e.bits == 1,
        TypeFamily::UnsignedInt | TypeFamily::BitString => (1..=width).contains(&e.bits),
        TypeFamily::SignedInt | TypeFamily::Real => e.bits == width,
    };
    if !ok {
        let rule = match ty.family() {
            TypeFamily::Bool => "a BOOL entry has 1 bit".to_owned(),
            TypeFamily::UnsignedInt | TypeFamily::BitString => {
                format!("a {ty} entry has 1 to {width} bits")
            }
            _ => format!("a {ty} entry has exactly {width} bits"),
        };
        problems.push(format!(
            "{at}: {} bits do not fit type {ty} ({rule}): fix `bits` or `type`",
            e.bits
        ));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_problem_of_a_description_is_listed() {
        let err = BusConfig::from_toml_str(
            r#"
            [[devices]]
            name = "1bad"
            identity = { vendor = 2, product = 1 }
            entries = [
                { name = "a", direction = "input", bits = 2, type = "BOOL" },
                { name = "A", direction = "input", bits = 1, type = "BOOL" },
                { name = "s", direction = "output", bits = 8, type = "STRING" },
                { name = "i", direction = "output", bits = 8, type = "INT" },
                { name = "x", direction = "output", bits = 8, type = "QWORD" },
            ]
            [[devices]]
            name = "ok"
            identity = { vendor = 2, product = 1 }
            [[devices]]
            name = "OK"
            identity = { vendor = 2, product = 1 }
            [[devices]]
            name = "1bad"
            identity = { vendor = 2, product = 1 }
            "#,
        )
        .unwrap_err();
        let text = err.to_string();
        assert_eq!(err.problems.len(), 8, "{text}");
        for needle in [
            "`1bad` is not an identifier",
            "2 bits do not fit type BOOL",
            "used twice",
            "STRING is not a process data type",
            "a INT entry has exactly 16 bits",
            "`QWORD` is not an IEC type",
            "already used by device 0",
        ] {
            assert!(text.contains(needle), "missing {needle:?} in {text}");
        }
    }

    #[test]
    fn a_bus_beyond_the_caps_is_refused() {
        let bus = BusConfig {
            devices: (0..MAX_SUBDEVICES + 1)
                .map(|i| crate::bus::devices::el2889(&format!("do{i}")))
                .collect(),
        };
        let err = bus.validate().unwrap_err().to_string();
        assert!(err.contains("more than the 16"), "{err}");
    }
}
