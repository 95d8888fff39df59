//! A linked program on the simulated bus made from its bus description alone, through
//! `plc_io` only (feature `sim`): the description lists the devices once, the plant sets and
//! reads the simulated I/O by the program's own link names.

use plc_core::GlobalMemory;
use plc_io::ethercat::sim::DescriptionError;
use plc_io::ethercat::{BusConfig, EtherCatBackend, Options, Transport};

const BUS: &str = r#"
[[devices]]
name = "coupler"
identity = { vendor = 0x2, product = 0x044c2c52 }

[[devices]]
name = "door"
identity = { vendor = 0x2, product = 0x03ec3052 }
entries = [{ name = "switches", direction = "input", bits = 4, type = "UINT" }]

[[devices]]
name = "tower"
identity = { vendor = 0x2, product = 0x07d43052 }
entries = [
    { name = "green", direction = "output", bits = 1, type = "BOOL" },
    { name = "red", direction = "output", bits = 1, type = "BOOL" },
    { name = "spare", direction = "output", bits = 2, type = "USINT" },
]
"#;

#[derive(GlobalMemory, Debug, Clone)]
struct Door {
    #[plc(link = "ethercat.door.switches", direction = "input")]
    switches: u16,
    #[plc(link = "ethercat.tower.green", direction = "output")]
    green: bool,
    #[plc(link = "ethercat.tower.red", direction = "output")]
    red: bool,
}

#[test]
fn a_linked_program_runs_on_the_bus_its_description_makes_and_the_plant_uses_its_links() {
    let config = BusConfig::from_toml_str(BUS).unwrap();
    let (transport, plant) = Transport::simulated(&config).unwrap();
    let mut backend =
        EtherCatBackend::<Door>::new(config, transport, Options::simulated()).unwrap();
    backend.start().unwrap();
    let mut gm = Door::default();
    for closed in [true, false, true] {
        plant
            .set_input("ethercat.door.switches", u16::from(closed) * 0b0101)
            .unwrap();
        for _ in 0..3 {
            assert!(backend.exchange(&mut gm).inputs_valid);
            // The program: green while both door switches are closed, red otherwise.
            gm.green = gm.switches == 0b0101;
            gm.red = !gm.green;
        }
        assert_eq!(
            plant.output::<bool>("ethercat.tower.green").unwrap(),
            closed
        );
        assert_eq!(plant.output::<bool>("ethercat.tower.red").unwrap(), !closed);
        assert_eq!(plant.output::<u8>("ethercat.tower.spare").unwrap(), 0);
    }
    backend.stop();
    assert!(
        !plant.output::<bool>("ethercat.tower.green").unwrap(),
        "off outside OP"
    );
}

#[test]
fn a_description_with_a_device_the_simulator_lacks_is_refused_naming_the_device() {
    let text = BUS.replace("0x07d43052", "0x0af93052");
    let config = BusConfig::from_toml_str(&text).unwrap();
    let err = Transport::simulated(&config).map(|_| ()).unwrap_err();
    assert!(matches!(err, DescriptionError::NoModel { .. }));
    let text = err.to_string();
    assert!(
        text.contains("device `tower` (position 2) is vendor 0x2, product 0x0af93052"),
        "{text}"
    );
}
