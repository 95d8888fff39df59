//! The simulated bus from a bus description alone: each device kind the description names
//! becomes its model in ring order, a device without a model or a broken description is
//! refused naming it, and a plant model's I/O by link name reaches real ethercrab.

#[macro_use]
mod common;

use common::{maindevice, timeouts};
use ethercat_sim::{DescriptionError, SimBus, inproc};
use futures_lite::future::block_on;
use plc_rules::IecType;
use plc_rules::bus::{BusConfig, PdoDirection, devices};

/// The tensile tester's bus description (`examples/bus/tensile_tester.toml`, its devices
/// and entries): a coupler, an I/O module of an EL1004 and an EL2889 under one name, an
/// EL2004 and an AKD servo drive.
const TENSILE_TESTER: &str = r#"
[[devices]]
name = "coupler"
identity = { vendor = 0x2, product = 0x044c2c52 }

[[devices]]
name = "impact67_0"
identity = { vendor = 0x2, product = 0x03ec3052 }
entries = [{ name = "digital_inputs", direction = "input", bits = 4, type = "UINT" }]

[[devices]]
name = "impact67_0"
identity = { vendor = 0x2, product = 0x0b493052 }
entries = [{ name = "digital_outputs", direction = "output", bits = 16, type = "UINT" }]

[[devices]]
name = "lamps"
identity = { vendor = 0x2, product = 0x07d43052 }
entries = [
    { name = "green", direction = "output", bits = 1, type = "BOOL" },
    { name = "yellow", direction = "output", bits = 1, type = "BOOL" },
    { name = "red", direction = "output", bits = 1, type = "BOOL" },
    { name = "horn", direction = "output", bits = 1, type = "BOOL" },
]

[[devices]]
name = "crosshead"
identity = { vendor = 0x6a, product = 0x00414b44 }
entries = [
    { name = "controlword", direction = "output", bits = 16, type = "UINT", sm = 2 },
    { name = "statusword", direction = "input", bits = 16, type = "UINT", sm = 3 },
    { name = "position_actual_value", direction = "input", bits = 32, type = "DINT", sm = 3 },
]
"#;

#[test]
fn the_tensile_testers_description_gives_its_devices_in_ring_order() {
    let config = BusConfig::from_toml_str(TENSILE_TESTER).unwrap();
    let bus = SimBus::from_description(&config).unwrap();
    assert_eq!(
        bus.device_names(),
        ["EK1100", "EL1004", "EL2889", "EL2004", "AKD"]
    );
    assert_eq!(bus.device(4).identity(), (0x6A, 0x0041_4B44, 2));
    assert_eq!(
        bus.links()[..3],
        [
            "ethercat.impact67_0.digital_inputs",
            "ethercat.impact67_0.digital_outputs",
            "ethercat.lamps.green"
        ]
    );
}

#[test]
fn every_modelled_device_kind_comes_from_its_identity() {
    let config = BusConfig {
        devices: vec![
            devices::ek1100("coupler"),
            devices::el1004("di"),
            devices::el2004("dq4"),
            devices::el2828("dq8"),
            devices::el2889("dq16"),
            devices::el3004("ai"),
            devices::akd("drive"),
        ],
    };
    let bus = SimBus::from_description(&config).unwrap();
    let names = [
        "EK1100", "EL1004", "EL2004", "EL2828", "EL2889", "EL3004", "AKD",
    ];
    assert_eq!(bus.device_names(), names);
    for (pos, d) in config.devices.iter().enumerate() {
        let (vendor, product, _) = bus.device(pos).identity();
        assert_eq!((vendor, product), (d.identity.vendor, d.identity.product));
    }
}

#[test]
fn a_device_without_a_model_is_refused_naming_it_and_its_identity() {
    let mut config = BusConfig::from_toml_str(TENSILE_TESTER).unwrap();
    config.devices[3].name = "tower".into();
    config.devices[3].description = "EL2809 16 DO".into();
    config.devices[3].identity.product = 0x0af9_3052;
    config.devices[1].identity.revision = Some(0x0099_0000);
    let err = SimBus::from_description(&config).unwrap_err();
    let text = err.to_string();
    assert!(matches!(&err, DescriptionError::NoModel { devices, .. } if devices.len() == 2));
    for part in [
        "bus description: no simulated bus: 2 devices cannot be simulated",
        "device `tower` (position 3, \"EL2809 16 DO\") is vendor 0x2, product 0x0af93052",
        "which the simulator has no model for",
        "device `impact67_0` (position 1) asks for revision 0x00990000, but the simulated \
         EL1004 is revision 0x00130000",
        "The simulator models EK1100 (vendor 0x2, product 0x044c2c52)",
        "AKD (vendor 0x6a, product 0x00414b44)",
    ] {
        assert!(text.contains(part), "`{part}` missing from:\n{text}");
    }
}

#[test]
fn garbage_and_broken_descriptions_are_refused_naming_the_file_never_a_panic() {
    let dir = std::env::temp_dir().join(format!("sim-description-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let cases: [(&str, &[u8], &str); 5] = [
        (
            "garbage.toml",
            b"\xff\xfe[[devices]\x00",
            "cannot read the bus description",
        ),
        (
            "half.toml",
            b"[[devices]]\nname = \"a\"\n",
            "not a valid TOML bus description",
        ),
        ("empty.json", b"{\"devices\": []}", "the bus has no devices"),
        (
            "bad.json",
            b"{\"devices\": [{\"name\": 7}]}",
            "not a valid JSON bus description",
        ),
        (
            "name.toml",
            b"[[devices]]\nname = \"1st\"\nidentity = { vendor = 2, product = 0x044c2c52 }\n",
            "name `1st` is not an identifier",
        ),
    ];
    for (name, bytes, expected) in cases {
        let path = dir.join(name);
        std::fs::write(&path, bytes).unwrap();
        let err = SimBus::from_description_file(&path).unwrap_err();
        let text = err.to_string();
        assert!(
            matches!(err, DescriptionError::Refused(_)),
            "{name}: {text}"
        );
        assert!(text.contains(expected), "{name}: {text}");
        assert!(text.contains(&path.display().to_string()), "{name}: {text}");
    }
    let missing = SimBus::from_description_file(dir.join("none.toml")).unwrap_err();
    assert!(missing.to_string().contains("none.toml"), "{missing}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn unknown_links_and_wrong_directions_are_refused_naming_the_link_and_the_nearest_name() {
    let bus = SimBus::from_description(&BusConfig::from_toml_str(TENSILE_TESTER).unwrap()).unwrap();
    let problem = |r: Result<(), ethercat_sim::LinkError>| r.unwrap_err().to_string();
    let cases = [
        (
            problem(bus.set_input("ethercat.lampz.green", true)),
            "`ethercat.lampz.green`: the bus description has no device `lampz` (did you mean \
             `lamps`?): use one of `coupler`, `impact67_0`, `lamps`, `crosshead`",
        ),
        (
            problem(bus.set_input("ethercat.impact67_0.digital_input", 1u8)),
            "(did you mean `digital_inputs`?): use one of `digital_inputs`, `digital_outputs`",
        ),
        (
            problem(bus.set_input("ethercat.coupler.x", 1u8)),
            "device `coupler` has no process data",
        ),
        (
            problem(bus.set_input("ethercat.lamps.green", true)),
            "`green` is an output entry, which cannot be set as an input: read it with `output`",
        ),
        (
            problem(
                bus.output::<u16>("ethercat.impact67_0.digital_inputs")
                    .map(|_| ()),
            ),
            "read it with `input` or set it with `set_input`",
        ),
        (
            problem(bus.set_input("lamps.green", true)),
            "a link must start with `ethercat.`",
        ),
        (
            problem(bus.set_input("ethercat.impact67_0.digital_inputs", 16u8)),
            "16 does not fit this 4-bit UINT entry",
        ),
        (
            problem(bus.set_input("ethercat.impact67_0.digital_inputs", 1.0f32)),
            "(a bool or an integer, not a float)",
        ),
    ];
    for (text, expected) in cases {
        assert!(text.contains(expected), "`{expected}` missing from: {text}");
    }
    let by_list = SimBus::new(vec![ethercat_sim::Device::ek1100()]);
    let err = by_list.output::<bool>("ethercat.lamps.green").unwrap_err();
    assert!(
        err.to_string().contains("SimBus::from_description"),
        "{err}"
    );
}

#[test]
fn inputs_set_by_link_name_reach_ethercrab_and_its_outputs_read_back_by_link_name() {
    let config = BusConfig {
        devices: vec![
            devices::ek1100("coupler"),
            devices::el1004("io").grouped(PdoDirection::Input, "digital_inputs", IecType::Uint),
            devices::el2889("io").grouped(PdoDirection::Output, "digital_outputs", IecType::Uint),
            devices::el3004("ai"),
            devices::el2004("lamps"),
        ],
    };
    let bus = SimBus::from_description(&config).unwrap();
    let (tx, rx, pdu_loop) = storage!();
    let driver = inproc::spawn(tx, rx, bus.clone()).unwrap();
    let md = maindevice(pdu_loop, timeouts());
    let group = block_on(md.init_single_group::<8, 64>(ethercrab::std::ethercat_now)).unwrap();
    let group = block_on(group.into_op(&md)).unwrap();

    bus.set_input("ethercat.io.digital_inputs", 0b1010u8)
        .unwrap();
    bus.set_input("ethercat.ai.ch2_value", -1234i16).unwrap();
    bus.set_input("ethercat.ai.ch2_error", true).unwrap();
    group
        .subdevice(&md, 2)
        .unwrap()
        .outputs_raw_mut()
        .copy_from_slice(&[0x01, 0x80]);
    group.subdevice(&md, 4).unwrap().outputs_raw_mut()[0] = 0b0100;
    block_on(group.tx_rx(&md)).unwrap();

    assert_eq!(group.subdevice(&md, 1).unwrap().inputs_raw()[0], 0b1010);
    let ch2 = group.subdevice(&md, 3).unwrap().inputs_raw()[4..8].to_vec();
    assert_eq!(i16::from_le_bytes([ch2[2], ch2[3]]), -1234);
    assert_eq!(
        ch2[0] & 0x40,
        0x40,
        "ch2_error is bit 6 of the channel's status"
    );
    assert_eq!(bus.input::<i16>("ethercat.ai.ch2_value").unwrap(), -1234);
    assert_eq!(bus.input::<i32>("ethercat.ai.ch1_value").unwrap(), 0);
    assert_eq!(
        bus.output::<u16>("ethercat.io.digital_outputs").unwrap(),
        0x8001
    );
    let lamps: Vec<bool> = ["output1", "output2", "output3", "output4"]
        .map(|l| bus.output(&format!("ethercat.lamps.{l}")).unwrap())
        .to_vec();
    assert_eq!(lamps, [false, false, true, false]);
    let err = bus.output::<u8>("ethercat.io.digital_outputs").unwrap_err();
    assert!(
        err.to_string()
            .contains("holds 0x8001, which a `u8` cannot hold"),
        "{err}"
    );

    drop(group);
    // SAFETY: the group is gone and no frame is in flight.
    let _ = unsafe { md.release_all() };
    driver.stop();
}
