//! `plc bus show` and `plc bus scan`: bus description files in, process images and scanned
//! descriptions out.

mod common;

use common::{plc, stderr, stdout};

/// `plc bus show` prints the process image of the main example's bus description, and names
/// the file and the problem of one it cannot use.
#[test]
fn bus_show_prints_the_process_image_and_refuses_a_bad_file() {
    let file = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../examples/bus/tensile_tester.toml"
    );
    let o = plc(&["bus", "show", file]);
    assert!(o.status.success(), "{}", stderr(&o));
    let table = stdout(&o);
    let rows: Vec<Vec<&str>> = table
        .lines()
        .map(|l| l.split_whitespace().collect())
        .collect();
    assert_eq!(
        rows[0],
        [
            "pos",
            "device",
            "entry",
            "direction",
            "byte.bit",
            "bits",
            "type"
        ]
    );
    assert!(
        rows.contains(&vec!["0", "coupler", "(no", "process", "data)"]),
        "{table}"
    );
    assert!(
        rows.contains(&vec![
            "1",
            "impact67_0",
            "digital_inputs",
            "input",
            "0.0",
            "4",
            "UINT"
        ]),
        "{table}"
    );
    assert!(
        rows.contains(&vec![
            "2",
            "impact67_0",
            "digital_outputs",
            "output",
            "0.0",
            "16",
            "UINT"
        ]),
        "{table}"
    );
    assert!(
        rows.contains(&vec!["3", "lamps", "horn", "output", "0.3", "1", "BOOL"]),
        "{table}"
    );

    let dir = std::env::temp_dir().join(format!("plc-bus-show-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let bad = dir.join("bad.toml");
    std::fs::write(
        &bad,
        "[[devices]]\nname = \"1st\"\nidentity = { vendor = 2, product = 3 }\n",
    )
    .unwrap();
    let o = plc(&["bus", "show", bad.to_str().unwrap()]);
    assert!(!o.status.success());
    let err = stderr(&o);
    assert!(
        err.contains("bad.toml") && err.contains("`1st` is not an identifier"),
        "{err}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `plc bus show` lists the distributed clocks of a description whose devices take SYNC0.
#[test]
fn bus_show_lists_the_devices_sync0_and_shift() {
    let dir = std::env::temp_dir().join(format!("plc-bus-show-dc-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("dc.toml");
    let mut bus = plc_rules::bus::BusConfig {
        devices: vec![
            plc_rules::bus::devices::ek1100("coupler"),
            plc_rules::bus::devices::el2004("lamps"),
        ],
    };
    bus.devices[1].dc = Some(plc_rules::bus::DcConfig {
        sync0: plc_rules::time::Time::from_millis(2),
        shift: plc_rules::time::Time::from_micros(300),
    });
    std::fs::write(&file, bus.to_toml_string()).unwrap();
    let o = plc(&["bus", "show", file.to_str().unwrap()]);
    std::fs::remove_dir_all(&dir).unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    let clocks: Vec<Vec<&str>> = text
        .lines()
        .skip_while(|l| *l != "distributed clocks:")
        .map(|l| l.split_whitespace().collect())
        .collect();
    assert!(clocks.len() >= 3, "{text}");
    assert_eq!(clocks[1], ["pos", "device", "sync0", "shift"], "{text}");
    assert_eq!(clocks[2], ["1", "lamps", "2ms", "300us"], "{text}");
}

/// `plc bus scan --sim` names the entries a CoE device's EEPROM leaves unnamed from its object
/// dictionary (SDO information service): the EL3004's values and the AKD's CiA 402 objects.
#[test]
fn bus_scan_names_coe_entries_from_the_object_dictionary() {
    let o = plc(&["bus", "scan", "--sim", "EK1100,EL3004,AKD"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    let bus = plc_rules::bus::BusConfig::from_toml_str(&text).unwrap();
    let value = &bus.devices[1].entries[9];
    assert_eq!(
        (value.name.as_str(), value.iec_type.as_str()),
        ("value_1", "INT")
    );
    assert_eq!(
        bus.devices[2].entries,
        plc_rules::bus::devices::akd("").entries,
        "{text}"
    );
    assert!(
        !text.contains("name = \"x"),
        "no entry named by its object index: {text}"
    );
}

/// `plc bus scan --sim` scans a simulated bus in its own process: the TOML it prints is a bus
/// description of those terminals that `BusConfig` reads, `--out` writes the same text (a
/// symlink in its place is replaced, not followed) and `plc bus show` takes the file.
#[test]
fn bus_scan_of_a_simulated_bus_prints_a_description_that_reads_back() {
    let o = plc(&["bus", "scan", "--sim", "EK1100,el1004,EL2889,EL2004"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    let bus = plc_rules::bus::BusConfig::from_toml_str(&text).unwrap();
    let names: Vec<_> = bus.devices.iter().map(|d| d.name.as_str()).collect();
    assert_eq!(names, ["ek1100", "el1004", "el2889", "el2004"]);
    assert_eq!(bus.devices[2].entries.len(), 16);
    assert_eq!(bus.devices[1].identity.product, 0x03ec_3052);

    let dir = std::env::temp_dir().join(format!("plc-bus-scan-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let elsewhere = dir.join("elsewhere.toml");
    std::fs::write(&elsewhere, "keep me").unwrap();
    let out = dir.join("scanned.toml");
    std::os::unix::fs::symlink(&elsewhere, &out).unwrap();
    let o = plc(&[
        "bus",
        "scan",
        "--sim",
        "EK1100,EL1004,EL2889,EL2004",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(std::fs::read_to_string(&out).unwrap(), text);
    assert!(!std::fs::symlink_metadata(&out).unwrap().is_symlink());
    assert_eq!(std::fs::read_to_string(&elsewhere).unwrap(), "keep me");
    let o = plc(&["bus", "show", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let table = stdout(&o);
    assert!(
        table
            .lines()
            .any(|l| l.split_whitespace().collect::<Vec<_>>()
                == ["2", "el2889", "output_16", "output", "1.7", "1", "BOOL"]),
        "{table}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A terminal the simulator does not model, or no bus at all, is refused with what to write.
#[test]
fn bus_scan_refuses_an_unknown_terminal_and_a_missing_bus() {
    let o = plc(&["bus", "scan", "--sim", "EK1100,EL9999"]);
    assert!(!o.status.success());
    let err = stderr(&o);
    assert!(
        err.contains("`EL9999` is not a simulated terminal")
            && err.contains("EK1100, EL1004, EL2004, EL2828, EL2889, EL3004"),
        "{err}"
    );
    let o = plc(&["bus", "scan"]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("--interface"), "{}", stderr(&o));
}
