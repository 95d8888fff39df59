//! The text of a scanned bus description: TOML that [`BusConfig::from_toml_str`] reads back
//! to the same description, with identities in hexadecimal as data sheets print them and each
//! entry's object (`0x6000:01`) in a comment, for the engineer who renames entries to match the
//! program's links.
//!
//! ```
//! use plc_rules::bus::scan::{describe, ScannedDevice};
//! use plc_rules::bus::scan_file::to_toml;
//! use plc_rules::bus::{BusConfig, Identity};
//! let coupler = ScannedDevice {
//!     order: "EK1100".into(),
//!     description: "EK1100 EtherCAT-Koppler (2A E-Bus)".into(),
//!     identity: Identity { vendor: 2, product: 0x044c2c52, revision: Some(0x00120000) },
//!     entries: vec![],
//!     note: None,
//! };
//! let bus = describe(std::slice::from_ref(&coupler)).unwrap();
//! let text = to_toml(&bus, &[coupler]);
//! assert!(text.contains("identity = { vendor = 0x2, product = 0x044c2c52, revision = 0x00120000 }"));
//! assert_eq!(BusConfig::from_toml_str(&text).unwrap(), bus);
//! ```

use super::BusConfig;
use super::scan::ScannedDevice;
use std::fmt::Write;

/// `text` for a comment: on one line, without control characters (it may hold device data).
fn one_line(text: &str) -> String {
    text.chars()
        .map(|c| if c.is_control() { ' ' } else { c })
        .collect()
}

/// The description as commented TOML; `scanned` (the devices it was made from, same order)
/// gives each entry's object for its comment.
pub fn to_toml(bus: &BusConfig, scanned: &[ScannedDevice]) -> String {
    let mut out = String::from(
        "# Bus description read from the SubDevices by `plc bus scan`: identities, and PDO entries\n\
         # as the bus is configured (each entry's CoE object in its comment). Rename devices and\n\
         # entries to the names the program's links use; see docs/bus-scan.md.\n",
    );
    for (pos, d) in bus.devices.iter().enumerate() {
        let _ = write!(
            out,
            "\n[[devices]]\n# position {pos}\nname = {}\n",
            quoted(&d.name)
        );
        if !d.description.is_empty() {
            let _ = writeln!(out, "description = {}", quoted(&d.description));
        }
        let id = d.identity;
        let _ = write!(
            out,
            "identity = {{ vendor = {:#x}, product = {:#010x}",
            id.vendor, id.product
        );
        if let Some(r) = id.revision {
            let _ = write!(out, ", revision = {r:#010x}");
        }
        out.push_str(" }\n");
        if let Some(note) = scanned.get(pos).and_then(|s| s.note.as_deref()) {
            let _ = writeln!(out, "# {}", one_line(note));
        }
        if d.entries.is_empty() {
            out.push_str("# no process data\n");
            continue;
        }
        out.push_str("entries = [\n");
        let objects = scanned
            .get(pos)
            .map(|s| s.entries.as_slice())
            .unwrap_or(&[]);
        for (i, e) in d.entries.iter().enumerate() {
            let _ = write!(
                out,
                "    {{ name = {}, direction = \"{}\", bits = {}, type = {}",
                quoted(&e.name),
                e.direction.name(),
                e.bits,
                quoted(&e.iec_type)
            );
            if e.sm != 0 {
                let _ = write!(out, ", sm = {}", e.sm);
            }
            out.push_str(" },");
            match objects.get(i) {
                Some(o) if o.index == 0 => out.push_str(" # gap"),
                Some(o) => {
                    let _ = write!(out, " # {:#06x}:{:02x}", o.index, o.subindex);
                }
                None => {}
            }
            out.push('\n');
        }
        out.push_str("]\n");
    }
    out
}

/// `text` as a TOML basic string: quotes, backslashes and control characters escaped.
fn quoted(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 2);
    out.push('"');
    for c in text.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if c.is_control() => {
                let _ = write!(out, "\\u{:04X}", c as u32);
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bus::scan::{ScannedEntry, describe};
    use crate::bus::{Identity, PdoDirection};

    #[test]
    fn the_text_reads_back_to_the_same_description_with_odd_characters_in_it() {
        let entry = |name: &str, sm| ScannedEntry {
            name: Some(name.into()),
            index: 0x7000,
            subindex: 1,
            direction: PdoDirection::Output,
            bits: 1,
            data_type: Some(1),
            sm,
        };
        let device = ScannedDevice {
            order: "EL2002".into(),
            description: "quote \" backslash \\ tab \t ü".into(),
            identity: Identity {
                vendor: 2,
                product: 0x07d2_3052,
                revision: None,
            },
            entries: vec![entry("Output", 0), entry("Output", 1)],
            note: Some("names by object index:\nline two\u{1b}[2J".into()),
        };
        let bus = describe(std::slice::from_ref(&device)).unwrap();
        let text = to_toml(&bus, &[device]);
        assert_eq!(BusConfig::from_toml_str(&text).unwrap(), bus, "{text}");
        assert!(
            text.contains(
                "{ name = \"output_2\", direction = \"output\", bits = 1, type = \"BOOL\", sm = 1 }, # 0x7000:01"
            ),
            "{text}"
        );
        assert!(
            text.contains(r#"description = "quote \" backslash \\ tab \u0009 ü""#),
            "{text}"
        ); // The note is one comment line: device text cannot start a TOML line of its own.
        assert!(
            text.contains("\n# names by object index: line two [2J\n"),
            "{text}"
        );
    }
}
