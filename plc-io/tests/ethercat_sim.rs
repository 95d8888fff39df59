//! End-to-end tests of `plc_io::ethercat` on the simulated bus of `ethercat-sim`: real ethercrab
//! drives simulated EK1100 + EL1004 + EL2004 + EL2889 through the in-process transport. Faults
//! and recovery: `ethercat_sim_faults.rs`; the EL3004's CoE-configured PDOs and start-up SDOs:
//! `ethercat_sim_coe.rs`.

#[path = "common/sim_bench.rs"]
mod sim_bench;

use ethercat_sim::{Device, SimBus};
use plc_core::GlobalMemory;
use plc_io::ethercat::{BusConfig, EtherCatBackend, EtherCatError, PdoDirection, devices};
use sim_bench::{DI, DQ4, DQ16, Io, description, options, sim, started, transport};

#[test]
fn el1004_inputs_reach_the_mapped_bools_within_two_cycles() {
    let bus = sim();
    let mut backend = started::<Io>(&bus, description());
    let mut gm = Io::default();
    assert!(backend.exchange(&mut gm).inputs_valid);
    assert!(!gm.in1 && !gm.in4);
    bus.set_input_bit(DI, 0, true);
    bus.set_input_bit(DI, 3, true);
    let mut seen = None;
    for cycle in 1..=2 {
        let status = backend.exchange(&mut gm);
        assert!(status.inputs_valid && !status.bus_fault, "{status:?}");
        if gm.in1 && gm.in4 && gm.in4_again {
            seen = Some(cycle);
            break;
        }
    }
    assert!(seen.is_some(), "inputs not seen within two cycles: {gm:?}");
    bus.set_input_bit(DI, 0, false);
    backend.exchange(&mut gm);
    backend.exchange(&mut gm);
    assert!(!gm.in1 && gm.in4);
    backend.stop();
}

#[test]
fn program_bools_reach_the_el2004_and_el2889_outputs() {
    let bus = sim();
    let mut backend = started::<Io>(&bus, description());
    let mut gm = Io {
        q4_2: true,
        q16_1: true,
        q16_10: true,
        q16_16: true,
        ..Io::default()
    };
    backend.exchange(&mut gm);
    backend.exchange(&mut gm);
    assert_eq!(bus.outputs(DQ4), vec![0b0000_0010]);
    assert_eq!(bus.outputs(DQ16), vec![0b0000_0001, 0b1000_0010]);
    assert!(bus.output_bit(DQ16, 9));
    gm.q16_10 = false;
    backend.exchange(&mut gm);
    backend.exchange(&mut gm);
    assert!(!bus.output_bit(DQ16, 9));
    assert!(bus.output_bit(DQ16, 15));
    backend.stop();
    // Stop zeroes the outputs before INIT.
    assert_eq!(bus.outputs(DQ16), vec![0, 0]);
}

#[derive(GlobalMemory, Debug, Clone)]
struct Words {
    #[plc(link = "ethercat.io.digital_inputs", direction = "input")]
    inputs: u16,
    #[plc(source = "inputs", bit = 2)]
    ls_lift_neg: bool,
    #[plc(link = "ethercat.io.digital_outputs", direction = "output")]
    outputs: u16,
    #[plc(source = "outputs", bit = 0)]
    cr_lift_brake: bool,
    /// UINT input widens to a DINT variable (IEC 61131-3).
    #[plc(link = "ethercat.io.digital_inputs", direction = "input")]
    inputs_wide: i32,
}

#[test]
fn grouped_channels_are_words_and_consecutive_devices_form_one_module() {
    let bus = sim();
    let config = BusConfig {
        devices: vec![
            devices::ek1100("coupler"),
            devices::el1004("io").grouped(
                PdoDirection::Input,
                "digital_inputs",
                plc_core::IecType::Uint,
            ),
            devices::el2004("lamps"),
            devices::el2889("io"),
        ],
    };
    // `io` is not consecutive here: refused.
    let err = EtherCatBackend::<Words>::new(config.clone(), transport(&bus), options())
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("only consecutive devices may share a name"),
        "{err}"
    );
    let _ = err;
    let bus = SimBus::new(vec![Device::ek1100(), Device::el1004(), Device::el2889()]);
    let config = BusConfig {
        devices: vec![
            devices::ek1100("coupler"),
            devices::el1004("io").grouped(
                PdoDirection::Input,
                "digital_inputs",
                plc_core::IecType::Uint,
            ),
            devices::el2889("io").grouped(
                PdoDirection::Output,
                "digital_outputs",
                plc_core::IecType::Uint,
            ),
        ],
    };
    let mut backend = started::<Words>(&bus, config);
    let mut gm = Words::default();
    bus.set_input_bit(1, 2, true);
    gm.cr_lift_brake = true;
    gm.pack_bits();
    for _ in 0..2 {
        backend.exchange(&mut gm);
    }
    gm.unpack_bits();
    assert_eq!(gm.inputs, 0b100);
    assert_eq!(gm.inputs_wide, 0b100);
    assert!(gm.ls_lift_neg);
    assert!(bus.output_bit(2, 0));
    backend.stop();
}

#[test]
fn a_wrong_terminal_is_an_identity_error_naming_position_expected_and_found() {
    let bus = sim();
    let mut config = description();
    config.devices.swap(DQ4, DQ16);
    let mut backend = EtherCatBackend::<Io>::new(config, transport(&bus), options()).unwrap();
    let err = backend.start().unwrap_err();
    assert!(matches!(err, EtherCatError::Identity(_)), "{err}");
    let text = err.to_string();
    assert!(
        text.contains("position 2: expected `dq16` (vendor 0x2, product 0x0b493052, any revision), found EL2004"),
        "{text}"
    );
    assert!(text.contains("position 3: expected `dq4`"), "{text}");
}

/// Only the EL1004 is linked, so descriptions with fewer or more devices still resolve.
#[derive(GlobalMemory, Debug, Clone)]
struct DiOnly {
    #[plc(link = "ethercat.di.input1", direction = "input")]
    in1: bool,
}

#[test]
fn a_subdevice_missing_from_the_wire_is_an_identity_error() {
    // The EL2889 is not plugged in.
    let bus = SimBus::new(vec![Device::ek1100(), Device::el1004(), Device::el2004()]);
    let mut backend =
        EtherCatBackend::<DiOnly>::new(description(), transport(&bus), options()).unwrap();
    let err = backend.start().unwrap_err();
    assert!(
        matches!(err, EtherCatError::Identity(ref p) if p.len() == 1),
        "{err}"
    );
    let text = err.to_string();
    assert!(
        text.contains(
            "position 3: expected `dq16` (vendor 0x2, product 0x0b493052, any revision), found \
             no SubDevice (the bus has 3)"
        ),
        "{text}"
    );
    assert_eq!(
        bus.al_state(DI),
        ethercat_sim::al::PRE_OP,
        "nothing went to SAFE-OP"
    );
}

#[test]
fn a_subdevice_on_the_wire_the_description_lacks_is_an_identity_error() {
    let bus = sim();
    let mut config = description();
    config.devices.pop();
    let mut backend = EtherCatBackend::<DiOnly>::new(config, transport(&bus), options()).unwrap();
    let err = backend.start().unwrap_err();
    assert!(
        matches!(err, EtherCatError::Identity(ref p) if p.len() == 1),
        "{err}"
    );
    let text = err.to_string();
    assert!(
        text.contains(
            "position 3: found EL2889 (vendor 0x2, product 0x0b493052), which the description \
             does not list: add it"
        ),
        "{text}"
    );
}

#[test]
fn a_revision_other_than_the_described_one_is_an_identity_error() {
    let bus = sim();
    let mut config = description();
    config.devices[DQ4].identity.revision = Some(0x0011_0000);
    let mut backend =
        EtherCatBackend::<Io>::new(config.clone(), transport(&bus), options()).unwrap();
    let text = backend.start().unwrap_err().to_string();
    assert!(
        text.contains(
            "position 2: expected `dq4` (vendor 0x2, product 0x07d43052, revision 0x00110000), \
             found EL2004 (vendor 0x2, product 0x07d43052, revision 0x00100000)"
        ),
        "{text}"
    );
    // The revision the terminal has is accepted.
    config.devices[DQ4].identity.revision = Some(0x0010_0000);
    let bus = sim();
    started::<Io>(&bus, config).stop();
}

#[test]
fn process_data_beyond_the_max_pdi_cap_is_refused_before_the_bus_is_touched() {
    let bus = sim();
    let mut config = description();
    // 129 LWORD inputs: 1032 bytes, beyond MAX_PDI (1024) with the EL2004 and EL2889 bytes.
    config.devices[DI].entries = (0..129)
        .map(|i| {
            plc_io::ethercat::PdoEntry::new(
                &format!("word{i}"),
                PdoDirection::Input,
                64,
                plc_core::IecType::Lword,
            )
        })
        .collect();
    let err = EtherCatBackend::<DiOnly>::new(config, transport(&bus), options()).unwrap_err();
    assert!(matches!(err, EtherCatError::Config(_)), "{err}");
    let text = err.to_string();
    assert!(
        text.contains(&format!(
            "the process data of this bus takes 1035 bytes, more than the {} plc-io is built \
             for (ethercrab's MAX_PDI): raise `plc_io::ethercat::MAX_PDI`",
            plc_io::ethercat::MAX_PDI
        )),
        "{text}"
    );
    assert_eq!(bus.frames(), 0, "nothing was sent");
}

#[test]
fn a_description_with_wrong_pdo_sizes_is_refused_before_op() {
    let bus = sim();
    let mut config = description();
    // Claim the EL2004 has 12 channels: 2 bytes instead of 1.
    config.devices[DQ4]
        .entries
        .extend((5..=12).map(|i| {
            plc_io::ethercat::PdoEntry::bool(&format!("output{i}"), PdoDirection::Output)
        }));
    let mut backend = EtherCatBackend::<Io>::new(config, transport(&bus), options()).unwrap();
    let err = backend.start().unwrap_err().to_string();
    assert!(
        err.contains("position 2 (`dq4`): described 0 input and 2 output bytes, the device has 0 input and 1 output bytes"),
        "{err}"
    );
}

#[derive(GlobalMemory, Debug, Clone)]
struct BadLinks {
    #[plc(link = "ethercat.nope.input1", direction = "input")]
    unknown_device: bool,
    #[plc(link = "ethercat.di.input9", direction = "input")]
    unknown_entry: bool,
    #[plc(link = "ethercat.di.input1", direction = "output")]
    output_on_input: bool,
    #[plc(link = "ethercat.di.input2", direction = "input")]
    wrong_type: u8,
    #[plc(link = "ethercat.dq4.output1", direction = "output")]
    first_writer: bool,
    #[plc(link = "ethercat.dq4.output1", direction = "output")]
    second_writer: bool,
}

#[test]
fn every_link_problem_is_reported_together_before_the_bus_is_touched() {
    let bus = sim();
    let err =
        EtherCatBackend::<BadLinks>::new(description(), transport(&bus), options()).unwrap_err();
    let EtherCatError::Links(links) = &err else {
        panic!("{err}")
    };
    let text = err.to_string();
    assert_eq!(links.problems.len(), 5, "{text}");
    for (var, needle) in [
        ("unknown_device", "the bus has no device `nope`"),
        ("unknown_entry", "device `di` has no entry `input9`"),
        (
            "output_on_input",
            "`input1` is an input entry, but the variable is declared `direction = \"output\"`",
        ),
        ("wrong_type", "BOOL does not widen implicitly to USINT"),
        (
            "second_writer",
            "`first_writer` is written to this output entry already",
        ),
    ] {
        assert!(
            links
                .problems
                .iter()
                .any(|p| p.variable == var && p.message.contains(needle)),
            "missing {var}: {needle} in\n{text}"
        );
    }
}
