//! The bus description files shipped with the examples parse, validate and lay out as the
//! simulated terminals do.

use plc_core::IecType;
use plc_io::ethercat::{BusConfig, BusLayout, PdoDirection, devices};

fn example(name: &str) -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../examples/bus")
        .join(name)
}

#[test]
fn the_tensile_tester_bus_file_maps_impact67_onto_el1004_and_el2889() {
    let bus = BusConfig::load(example("tensile_tester.toml")).unwrap();
    let layout = BusLayout::new(&bus);
    let inputs = layout.entry("impact67_0", "digital_inputs").unwrap();
    let outputs = layout.entry("impact67_0", "digital_outputs").unwrap();
    assert_eq!(
        (inputs.device, inputs.bits, inputs.iec_type),
        (1, 4, IecType::Uint)
    );
    assert_eq!(
        (outputs.device, outputs.bits, outputs.iec_type),
        (2, 16, IecType::Uint)
    );
    assert_eq!(layout.entry("lamps", "horn").unwrap().bit_offset, 3);
    let sizes: Vec<_> = layout
        .devices
        .iter()
        .map(|d| (d.input_bytes, d.output_bytes))
        .collect();
    // The crosshead drive: 17 input bytes (statusword, mode, position, velocity, following
    // error, error code) and 11 output bytes (controlword, mode, target position, velocity).
    assert_eq!(sizes, [(0, 0), (1, 0), (0, 2), (0, 1), (17, 11)]);
    // The crosshead is the ready AKD description under its own name and description.
    let crosshead = bus.devices.iter().find(|d| d.name == "crosshead").unwrap();
    let ready = devices::akd("crosshead");
    assert_eq!(
        (&crosshead.identity, &crosshead.entries),
        (&ready.identity, &ready.entries)
    );
}

#[test]
fn the_json_sim_bus_file_equals_the_ready_descriptions() {
    let bus = BusConfig::load(example("sim_ek1100_el1004_el2004_el2889.json")).unwrap();
    let mut ready = vec![
        devices::ek1100("coupler"),
        devices::el1004("di"),
        devices::el2004("dq4"),
        devices::el2889("dq16").grouped(PdoDirection::Output, "digital_outputs", IecType::Word),
    ];
    for (file, code) in bus.devices.iter().zip(&mut ready) {
        code.description = file.description.clone();
    }
    assert_eq!(bus.devices, ready);
}

#[test]
fn a_bad_file_is_an_error_naming_it() {
    let dir = std::env::temp_dir().join(format!("plc-io-bus-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("bad.toml");
    std::fs::write(&path, "[[devices]]\nname = \"x\"\n").unwrap();
    let err = BusConfig::load(&path).unwrap_err().to_string();
    assert!(err.starts_with(&path.display().to_string()), "{err}");
    assert!(err.contains("missing field `identity`"), "{err}");
    let missing = BusConfig::load(dir.join("none.toml"))
        .unwrap_err()
        .to_string();
    assert!(
        missing.contains("cannot read the bus description"),
        "{missing}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
