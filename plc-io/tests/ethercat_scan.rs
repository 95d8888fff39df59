//! `plc_io::ethercat::scan` on the simulated bus: real ethercrab brings simulated terminals to
//! PRE-OP, the scan reads their EEPROMs (and the EL3004's and the drive's CoE objects, their
//! names through the SDO information service), and the description it
//! makes matches the hand-written one and the terminals' data sheets, reads back through
//! `BusConfig`, and brings the same bus to OP.

#[path = "common/sim_bench.rs"]
mod sim_bench;

use ethercat_sim::{Device, SimBus};
use plc_core::GlobalMemory;
use plc_io::ethercat::scan::{ScannedBus, scan};
use plc_io::ethercat::{
    BusConfig, BusLayout, DeviceConfig, EtherCatBackend, Options, PdoDirection, PdoEntry, devices,
};
use sim_bench::transport;

fn scanned(models: Vec<Device>) -> ScannedBus {
    let bus = SimBus::new(models);
    scan(transport(&bus), &Options::simulated()).unwrap()
}

fn tensile_tester_file() -> BusConfig {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../examples/bus/tensile_tester.toml"
    );
    BusConfig::load(path).unwrap()
}

/// The tensile tester's simulated bus, in the ring order of its example's set-up.
fn tensile_tester_sim() -> Vec<Device> {
    vec![
        Device::ek1100(),
        Device::el1004(),
        Device::el2889(),
        Device::el2004(),
        Device::akd(),
    ]
}

/// An entry without its name, to compare entries names aside.
fn unnamed(e: &PdoEntry) -> (PdoDirection, u32, String, u8) {
    (e.direction, e.bits, e.iec_type.clone(), e.sm)
}

fn unnamed_entries(d: &DeviceConfig) -> Vec<(PdoDirection, u32, String, u8)> {
    d.entries.iter().map(unnamed).collect()
}

#[test]
fn a_scan_of_the_tensile_tester_bus_reproduces_its_devices_identities_and_entries() {
    let scan = scanned(tensile_tester_sim());
    let file = tensile_tester_file();
    assert_eq!(scan.bus.devices.len(), file.devices.len());
    let sims = tensile_tester_sim();
    for ((got, want), sim) in scan.bus.devices.iter().zip(&file.devices).zip(&sims) {
        assert_eq!(
            (got.identity.vendor, got.identity.product),
            (want.identity.vendor, want.identity.product),
            "{}",
            want.description
        );
        assert_eq!(
            got.identity.revision,
            Some(sim.identity().2),
            "{}",
            got.name
        );
    }
    // The file groups the EL1004's inputs and the EL2889's outputs into one word each; grouped
    // the same way, the scanned entries are the file's, names aside.
    let mut grouped = scan.bus.clone();
    // The drive is named and typed from its CiA 402 object dictionary (the SDO information
    // service) as its ready description and the file name it.
    assert_eq!(grouped.devices[4].entries, devices::akd("").entries);
    for (got, want) in grouped.devices.iter_mut().zip(&file.devices) {
        if let [only] = want.entries.as_slice()
            && got.entries.len() > 1
        {
            *got = got
                .clone()
                .grouped(only.direction, &only.name, only.iec().unwrap());
        }
        assert_eq!(unnamed_entries(got), unnamed_entries(want), "{}", want.name);
    }
    // And the process image is the same, byte for byte.
    let sizes = |b: &BusConfig| BusLayout::new(b).devices;
    assert_eq!(sizes(&scan.bus), sizes(&file));
    // Ungrouped, each terminal has its ready per-channel description, names aside.
    let ready = [
        devices::ek1100(""),
        devices::el1004(""),
        devices::el2889(""),
        devices::el2004(""),
    ];
    for (got, want) in scan.bus.devices.iter().zip(&ready) {
        assert_eq!(unnamed_entries(got), unnamed_entries(want), "{}", got.name);
    }
}

#[test]
fn the_scan_leaves_every_subdevice_in_init() {
    let bus = SimBus::new(tensile_tester_sim());
    scan(transport(&bus), &Options::simulated()).unwrap();
    assert!((0..5).all(|pos| bus.al_state(pos) == ethercat_sim::al::INIT));
}

#[test]
fn devices_are_named_by_order_number_and_a_coupler_has_no_entries() {
    let scan = scanned(tensile_tester_sim());
    let names: Vec<_> = scan.bus.devices.iter().map(|d| d.name.as_str()).collect();
    assert_eq!(names, ["ek1100", "el1004", "el2889", "el2004", "akd"]);
    assert!(scan.bus.devices[0].entries.is_empty());
    assert_eq!(
        scan.bus.devices[0].description,
        "EK1100 EtherCAT-Koppler (2A E-Bus)"
    );
}

#[test]
fn the_el1004_has_four_1_bit_inputs() {
    let scan = scanned(vec![Device::ek1100(), Device::el1004()]);
    let d = &scan.bus.devices[1];
    let got: Vec<_> = d
        .entries
        .iter()
        .map(|e| (e.name.as_str(), e.direction, e.bits, e.iec_type.as_str()))
        .collect();
    let input = |n| (n, PdoDirection::Input, 1, "BOOL");
    assert_eq!(
        got,
        [
            input("input_1"),
            input("input_2"),
            input("input_3"),
            input("input_4")
        ]
    );
    let objects: Vec<_> = scan.devices[1]
        .entries
        .iter()
        .map(|e| (e.index, e.subindex))
        .collect();
    assert_eq!(
        objects,
        [(0x6000, 1), (0x6010, 1), (0x6020, 1), (0x6030, 1)]
    );
}

#[test]
fn the_el2889_has_sixteen_outputs_over_two_sync_managers() {
    let scan = scanned(vec![Device::ek1100(), Device::el2889()]);
    let d = &scan.bus.devices[1];
    assert_eq!(d.entries.len(), 16);
    for (i, e) in d.entries.iter().enumerate() {
        assert_eq!(e.name, format!("output_{}", i + 1));
        assert_eq!(
            (e.direction, e.bits, e.iec_type.as_str(), e.sm),
            (PdoDirection::Output, 1, "BOOL", u8::from(i >= 8))
        );
    }
    let layout = BusLayout::new(&scan.bus);
    assert_eq!(layout.entry("el2889", "output_9").unwrap().bit_offset, 8);
}

#[test]
fn the_el3004_has_four_channels_of_status_and_value_from_its_coe_objects() {
    let scan = scanned(vec![Device::ek1100(), Device::el3004()]);
    let d = &scan.bus.devices[1];
    assert_eq!(d.name, "el3004");
    assert!(d.entries.iter().all(|e| e.direction == PdoDirection::Input));
    let layout = BusLayout::new(&scan.bus);
    assert_eq!(layout.devices[1].input_bytes, 16);
    for ch in 0..4u16 {
        let object = 0x6000 + 0x10 * ch;
        // Named from the terminal's object dictionary: 0x60n0:11 "Value", INTEGER16.
        let value = layout
            .entry("el3004", &format!("value_{}", ch + 1))
            .unwrap();
        assert_eq!(value.iec_type, plc_core::IecType::Int);
        assert_eq!(
            (value.bit_offset, value.bits),
            (32 * ch as usize + 16, 16),
            "channel {} value",
            ch + 1
        );
        // The status word: underrange, overrange, limit 1 and 2, error, gaps, TxPDO state and
        // toggle, as the data sheet's 0x60n0:01..0x60n0:10.
        let status: Vec<_> = scan.devices[1]
            .entries
            .iter()
            .filter(|e| e.index == object && e.subindex < 0x11)
            .map(|e| (e.subindex, e.bits))
            .collect();
        assert_eq!(
            status,
            [(1, 1), (2, 1), (3, 2), (5, 2), (7, 1), (0x0F, 1), (0x10, 1)]
        );
    }
    let gaps = d
        .entries
        .iter()
        .filter(|e| e.name.starts_with("gap_"))
        .count();
    assert_eq!(gaps, 8, "two gaps a channel, numbered across the device");
    // The same layout as the ready description, which names the bits after the data sheet.
    let ready = BusConfig {
        devices: vec![devices::ek1100("c"), devices::el3004("ai")],
    };
    assert_eq!(BusLayout::new(&ready).devices, layout.devices);
}

#[test]
fn the_second_terminal_of_a_model_gets_2_in_ring_order() {
    let scan = scanned(vec![Device::ek1100(), Device::el2004(), Device::el2004()]);
    let names: Vec<_> = scan.bus.devices.iter().map(|d| d.name.as_str()).collect();
    assert_eq!(names, ["ek1100", "el2004", "el2004_2"]);
}

#[test]
fn the_scanned_file_reads_back_through_bus_config_unchanged() {
    let mut models = tensile_tester_sim();
    models.extend([Device::el2828(), Device::el3004()]);
    let scan = scanned(models);
    let text = scan.to_toml();
    assert_eq!(BusConfig::from_toml_str(&text).unwrap(), scan.bus, "{text}");
    assert!(
        text.contains("identity = { vendor = 0x2, product = 0x03ec3052, revision = 0x00130000 }"),
        "{text}"
    );
    assert!(text.contains("# 0x6000:01"), "{text}");
}

/// Brings `bus` to OP with `config` through plc-io's bring-up, runs three cycles of `gm` (each
/// with valid inputs) and returns what the struct holds then. The outputs stay as the last
/// cycle left them: `stop` would zero them.
fn run_three_cycles<T: GlobalMemory + Clone + Send + 'static>(
    bus: &SimBus,
    config: BusConfig,
    mut gm: T,
) -> T {
    let mut backend =
        EtherCatBackend::<T>::new(config, transport(bus), Options::simulated()).unwrap();
    backend.start().unwrap();
    for _ in 0..3 {
        let status = backend.exchange(&mut gm);
        assert!(status.inputs_valid && !status.bus_fault, "{status:?}");
    }
    gm
}

#[derive(GlobalMemory, Debug, Clone)]
struct Io {
    #[plc(link = "ethercat.el1004.input_2", direction = "input")]
    in2: bool,
    #[plc(link = "ethercat.el2889.output_10", direction = "output")]
    out10: bool,
    #[plc(link = "ethercat.el2004.output_4", direction = "output")]
    horn: bool,
}

#[test]
fn the_scanned_description_brings_the_same_bus_to_op_and_moves_its_data() {
    let bus = SimBus::new(tensile_tester_sim());
    let scan = scan(transport(&bus), &Options::simulated()).unwrap();
    let gm = Io {
        out10: true,
        horn: true,
        ..Io::default()
    };
    bus.set_input_bit(1, 1, true);
    let gm = run_three_cycles(&bus, scan.bus, gm);
    assert!(gm.in2);
    assert_eq!(bus.outputs(2), [0x00, 0x02], "EL2889 channel 10");
    assert_eq!(bus.outputs(3), [0x08], "EL2004 channel 4");
}

/// The links of the tensile tester's program (its JSON variable list): the impact67 block's
/// input and output words and the signal tower's horn.
#[derive(GlobalMemory, Debug, Clone)]
struct TensileTesterLinks {
    #[plc(link = "ethercat.impact67_0.digital_inputs", direction = "input")]
    inputs: u16,
    #[plc(link = "ethercat.impact67_0.digital_outputs", direction = "output")]
    outputs: u16,
    #[plc(link = "ethercat.lamps.horn", direction = "output")]
    horn: bool,
}

/// What the engineer does to the scanned file for the tensile tester: the names its program's
/// links use, and the EL1004's and EL2889's channels as one word each.
fn renamed_for_the_tensile_tester(mut bus: BusConfig) -> BusConfig {
    let names = ["coupler", "impact67_0", "impact67_0", "lamps", "crosshead"];
    for (d, name) in bus.devices.iter_mut().zip(names) {
        d.name = name.into();
    }
    let word = plc_core::IecType::Uint;
    bus.devices[1] = bus.devices[1]
        .clone()
        .grouped(PdoDirection::Input, "digital_inputs", word);
    bus.devices[2] = bus.devices[2]
        .clone()
        .grouped(PdoDirection::Output, "digital_outputs", word);
    for (e, name) in bus.devices[3]
        .entries
        .iter_mut()
        .zip(["green", "yellow", "red", "horn"])
    {
        e.name = name.into();
    }
    bus
}

#[test]
fn the_scanned_file_with_the_programs_names_is_the_tensile_testers_and_runs_its_links() {
    let bus = SimBus::new(tensile_tester_sim());
    let scan = scan(transport(&bus), &Options::simulated()).unwrap();
    let edited = renamed_for_the_tensile_tester(scan.bus);
    // The hand-written file, but for its descriptions and the revisions it leaves open.
    let mut file = tensile_tester_file();
    for (f, e) in file.devices.iter_mut().zip(&edited.devices) {
        f.description.clone_from(&e.description);
        f.identity.revision = e.identity.revision;
    }
    assert_eq!(edited, file);

    let gm = TensileTesterLinks {
        outputs: 0x0201,
        horn: true,
        ..TensileTesterLinks::default()
    };
    bus.set_input_bit(1, 3, true);
    let gm = run_three_cycles(&bus, edited, gm);
    assert_eq!(gm.inputs, 0b1000, "EL1004 channel 4");
    assert_eq!(bus.outputs(2), [0x01, 0x02], "EL2889 channels 1 and 10");
    assert_eq!(bus.outputs(3), [0x08], "EL2004 channel 4: the horn");
}

#[test]
fn a_device_whose_eeprom_does_not_parse_is_an_error_naming_its_position() {
    // A strings category longer than the EEPROM holds (not so long that ethercrab's own walk of
    // the categories overflows its 16-bit word address, which panics in a debug build).
    let mut long = Device::el2004();
    long.eeprom_words_mut()[0x41] = 0x0800;
    let err = scan(
        transport(&SimBus::new(vec![Device::ek1100(), long])),
        &Options::simulated(),
    )
    .unwrap_err()
    .to_string();
    // (ethercrab finds no General category behind it, so it names the device by identity.)
    assert!(
        err.starts_with("SubDevice 1 (manu. 0x00000002, device 0x07d43052")
            && err.ends_with(
                "EEPROM category 10 at word 0x0040 (4096 bytes) runs past the 2048 bytes the \
                 EEPROM holds"
            ),
        "{err}"
    );
    // An RxPDO that claims more entries than its category holds (EL2004: 0x1600 at word 0xA3).
    let mut crowded = Device::el2004();
    crowded.eeprom_words_mut()[0xA4] = 0x0009;
    let bus = SimBus::new(vec![Device::ek1100(), crowded]);
    let err = scan(transport(&bus), &Options::simulated())
        .unwrap_err()
        .to_string();
    assert!(
        (0..2).all(|pos| bus.al_state(pos) == ethercat_sim::al::INIT),
        "back in INIT after a failed scan too"
    );
    assert_eq!(
        err,
        "SubDevice 1 (EL2004): EEPROM category 51: PDO 0x1600: its 9 entries run past the category"
    );
}
