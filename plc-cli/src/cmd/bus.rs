//! `plc bus show FILE`: the resolved process image of a bus description, the table a
//! commissioning engineer checks against the wiring: each device in ring order with each PDO
//! entry's direction, place (byte and bit in the device's input or output data), width and type;
//! then, when devices take SYNC0, their distributed clocks (`dc`: SYNC0 period and shift).
//!
//! `plc bus scan --interface IFACE | --sim MODELS [--out FILE]`: a bus description read from
//! the SubDevices themselves (`plc_ethercat::scan`).

use super::Error;
use ethercat_sim::{Device, SimBus};
use plc_ethercat::scan::scan as scan_bus;
use plc_ethercat::{MAX_SUBDEVICES, Options, Transport};
use plc_rules::bus::{BusConfig, BusLayout, written_duration};
use std::fmt::Write;
use std::path::Path;

pub fn scan(interface: Option<String>, sim: &[String], out: Option<&Path>) -> Result<(), Error> {
    let (transport, options) = match interface {
        Some(name) => (Transport::Interface(name), Options::default()),
        None => (simulated(sim)?, Options::simulated()),
    };
    let text = scan_bus(transport, &options)?.to_toml();
    match out {
        None => print!("{text}"),
        Some(path) => {
            // Whole or not at all; a symlink at `path` is replaced, not followed.
            plc_files::write_atomically(path, text.as_bytes(), 0o644)
                .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
            eprintln!("plc: wrote {}", path.display());
        }
    }
    Ok(())
}

/// The in-process simulated bus of the terminals named in `models`, in ring order.
fn simulated(models: &[String]) -> Result<Transport, Error> {
    if models.is_empty() {
        return Err("--sim needs the terminals in ring order, e.g. --sim EK1100,EL1004".into());
    }
    if models.len() > MAX_SUBDEVICES {
        return Err(format!(
            "--sim lists {} terminals, more than the {MAX_SUBDEVICES} a bus holds",
            models.len()
        )
        .into());
    }
    let devices = models
        .iter()
        .map(|m| {
            Device::model(m.trim()).ok_or_else(|| {
                format!(
                    "--sim: `{m}` is not a simulated terminal (there are {})",
                    Device::MODELS.join(", ")
                )
            })
        })
        .collect::<Result<Vec<_>, _>>()?;
    let bus = SimBus::new(devices);
    Ok(Transport::custom(move |tx, rx| {
        Ok(Box::new(ethercat_sim::inproc::spawn(tx, rx, bus)?))
    }))
}

pub fn show(file: &Path) -> Result<(), Error> {
    let bus = BusConfig::load(file)?;
    print!("{}", table(&bus));
    Ok(())
}

/// The table, one line per entry (a device without process data gets one line saying so).
pub fn table(bus: &BusConfig) -> String {
    let layout = BusLayout::new(bus);
    let mut rows: Vec<[String; 7]> = vec![[
        "pos".into(),
        "device".into(),
        "entry".into(),
        "direction".into(),
        "byte.bit".into(),
        "bits".into(),
        "type".into(),
    ]];
    for (pos, name) in layout.names.iter().enumerate() {
        let mut entries: Vec<_> = layout.entries.iter().filter(|e| e.device == pos).collect();
        // Inputs first, then outputs, each in the order of the process data.
        entries.sort_by_key(|e| (e.direction.name() != "input", e.bit_offset));
        if entries.is_empty() {
            rows.push([
                pos.to_string(),
                name.clone(),
                "(no process data)".into(),
                String::new(),
                String::new(),
                String::new(),
                String::new(),
            ]);
        }
        for e in entries {
            rows.push([
                pos.to_string(),
                name.clone(),
                e.name.clone(),
                e.direction.name().into(),
                format!("{}.{}", e.bit_offset / 8, e.bit_offset % 8),
                e.bits.to_string(),
                e.iec_type.name().into(),
            ]);
        }
    }
    let mut out = String::new();
    aligned(&mut out, &rows);
    out.push_str(
        "\nbyte.bit: the place in the device's input or output data (each SyncManager starts on \
         a byte).\n",
    );
    let clocks: Vec<[String; 4]> = bus
        .devices
        .iter()
        .enumerate()
        .filter_map(|(pos, d)| {
            d.dc.map(|dc| {
                [
                    pos.to_string(),
                    d.name.clone(),
                    written_duration(dc.sync0),
                    written_duration(dc.shift),
                ]
            })
        })
        .collect();
    if !clocks.is_empty() {
        out.push_str("\ndistributed clocks:\n");
        let header = ["pos", "device", "sync0", "shift"].map(String::from);
        aligned(&mut out, &[&[header][..], &clocks].concat());
        out.push_str(
            "\nsync0: the SYNC0 period; shift: when the cycle's frame reaches the devices after \
             each pulse.\n",
        );
    }
    out
}

/// `rows` as lines of columns, each as wide as its widest cell, two spaces apart.
fn aligned<const N: usize>(out: &mut String, rows: &[[String; N]]) {
    let widths: Vec<usize> = (0..N)
        .map(|c| rows.iter().map(|r| r[c].chars().count()).max().unwrap_or(0))
        .collect();
    for r in rows {
        let line: Vec<String> = r
            .iter()
            .zip(&widths)
            .map(|(cell, w)| format!("{cell:<w$}"))
            .collect();
        let _ = writeln!(out, "{}", line.join("  ").trim_end());
    }
}

#[cfg(test)]
mod tests {
    use plc_rules::IecType;
    use plc_rules::bus::{BusConfig, DcConfig, PdoDirection, devices};
    use plc_rules::time::Time;

    #[test]
    fn the_table_lists_each_entry_in_place() {
        let bus = BusConfig {
            devices: vec![
                devices::ek1100("coupler"),
                devices::el1004("di").grouped(PdoDirection::Input, "word", IecType::Uint),
                devices::el2004("lamps"),
            ],
        };
        let t = super::table(&bus);
        let lines: Vec<&str> = t.lines().collect();
        assert!(lines[0].starts_with("pos  device   entry"), "{t}");
        assert_eq!(lines[1], "0    coupler  (no process data)");
        assert_eq!(
            lines[2],
            "1    di       word               input      0.0       4     UINT"
        );
        assert_eq!(
            lines[3],
            "2    lamps    output1            output     0.0       1     BOOL"
        );
        assert_eq!(
            lines[6],
            "2    lamps    output4            output     0.3       1     BOOL"
        );
    }

    #[test]
    fn devices_with_dc_are_listed_with_their_sync0_and_shift() {
        let dc = DcConfig {
            sync0: Time::from_millis(1),
            shift: Time::from_micros(250),
        };
        let mut bus = BusConfig {
            devices: vec![
                devices::ek1100("coupler"),
                devices::el1004("di"),
                devices::el2004("lamps"),
            ],
        };
        assert!(
            !super::table(&bus).contains("distributed clocks"),
            "nothing about clocks without `dc`"
        );
        bus.devices[2].dc = Some(dc);
        let t = super::table(&bus);
        let clocks: Vec<&str> = t
            .lines()
            .skip_while(|l| *l != "distributed clocks:")
            .collect();
        assert_eq!(
            clocks[..3],
            [
                "distributed clocks:",
                "pos  device  sync0  shift",
                "2    lamps   1ms    250us"
            ],
            "{t}"
        );
        assert!(clocks[4].starts_with("sync0: the SYNC0 period"), "{t}");
        bus.devices[2].dc = Some(DcConfig {
            shift: Time::ZERO,
            ..dc
        });
        assert!(super::table(&bus).contains("2    lamps   1ms    0s"));
    }
}
