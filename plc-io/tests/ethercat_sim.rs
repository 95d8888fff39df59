//! End-to-end tests of `plc_io::ethercat` on the simulated bus of `ethercat-sim`: real ethercrab
//! drives simulated EK1100 + EL1004 + EL2004 + EL2889 through the in-process transport. The
//! EL3004's CoE-configured PDOs and start-up SDOs: `ethercat_sim_coe.rs`.

#[path = "common/sim_bench.rs"]
mod sim_bench;

use ethercat_sim::{Device, SimBus};
use plc_core::GlobalMemory;
use plc_io::ethercat::{
    BusConfig, BusState, EtherCatBackend, EtherCatError, InputsOnFault, Options, PdoDirection,
    devices,
};
use sim_bench::{description, sim, started, transport};
use std::time::{Duration, Instant};

/// Ring positions of the simulated bus.
const COUPLER: usize = 0;
const DI: usize = 1;
const DQ4: usize = 2;
const DQ16: usize = 3;

#[derive(GlobalMemory, Debug, Clone)]
struct Io {
    #[plc(link = "ethercat.di.input1", direction = "input")]
    in1: bool,
    #[plc(link = "ethercat.di.input4", direction = "input")]
    in4: bool,
    /// A second variable on an input entry: both receive it.
    #[plc(link = "ethercat.di.input4", direction = "input")]
    in4_again: bool,
    #[plc(link = "ethercat.dq4.output2", direction = "output")]
    q4_2: bool,
    #[plc(link = "ethercat.dq16.output1", direction = "output")]
    q16_1: bool,
    #[plc(link = "ethercat.dq16.output10", direction = "output")]
    q16_10: bool,
    #[plc(link = "ethercat.dq16.output16", direction = "output")]
    q16_16: bool,
}

fn options() -> Options {
    Options::simulated()
}

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

#[test]
fn a_silent_subdevice_is_a_bus_fault_not_stale_data_and_the_bus_recovers() {
    let bus = sim();
    let mut backend = started::<Io>(&bus, description());
    let mut gm = Io::default();
    bus.set_input_bit(DI, 0, true);
    backend.exchange(&mut gm);
    backend.exchange(&mut gm);
    assert!(gm.in1);

    bus.set_responding(DQ4, false);
    let status = backend.exchange(&mut gm);
    assert!(status.bus_fault && !status.inputs_valid, "{status:?}");
    assert_ne!(status.working_counter, status.expected_working_counter);
    // The default policy zeroes the inputs: the program never sees the old `true` as fresh.
    assert!(!gm.in1, "stale input kept while the bus is faulty");

    bus.set_responding(DQ4, true);
    let mut recovered = false;
    for _ in 0..10 {
        let status = backend.exchange(&mut gm);
        if status.inputs_valid {
            assert_eq!(status.state, BusState::Op);
            recovered = true;
            break;
        }
    }
    assert!(recovered, "the bus did not recover");
    assert!(gm.in1);
    backend.stop();
}

/// Runs exchanges until the inputs are valid again (at most 10 s: the machine may be busy),
/// checking that every exchange before that flagged them invalid. The number of exchanges.
fn exchange_until_valid(backend: &mut EtherCatBackend<Io>, gm: &mut Io) -> usize {
    let deadline = Instant::now() + Duration::from_secs(10);
    let mut n = 0;
    loop {
        n += 1;
        let status = backend.exchange(gm);
        if status.inputs_valid {
            assert!(
                !status.bus_fault && status.state == BusState::Op,
                "{status:?}"
            );
            return n;
        }
        assert!(status.bus_fault, "{status:?}");
        assert!(
            Instant::now() < deadline,
            "not back in OP: {:?}",
            backend.problems()
        );
        std::thread::sleep(Duration::from_millis(2));
    }
}

#[test]
fn a_subdevice_that_lost_power_is_readdressed_reconfigured_and_back_in_op() {
    let bus = sim();
    let mut backend = started::<Io>(&bus, description());
    let mut gm = Io {
        q4_2: true,
        q16_16: true,
        ..Io::default()
    };
    bus.set_input_bit(DI, 0, true);
    exchange_until_valid(&mut backend, &mut gm);
    backend.exchange(&mut gm);
    assert!(gm.in1 && bus.output_bit(DQ4, 1));

    // The EL2004 loses power: it and the EL2889 behind it drop off the ring.
    bus.set_responding(DQ4, false);
    bus.power_cycle(DQ4);
    for _ in 0..3 {
        let status = backend.exchange(&mut gm);
        assert!(status.bus_fault && !status.inputs_valid, "{status:?}");
    }
    assert!(!gm.in1, "stale input while the bus is faulty");
    let problems = backend.problems().join("\n");
    assert!(
        problems.contains("position 2 (`dq4`, EL2004) does not answer: check its power"),
        "{problems}"
    );

    // Power is back: the EL2004 answers in INIT with station address 0.
    bus.set_responding(DQ4, true);
    assert_eq!(
        (bus.al_state(DQ4), bus.device(DQ4).station_address()),
        (1, 0)
    );
    exchange_until_valid(&mut backend, &mut gm);
    assert!(backend.problems().is_empty(), "{:?}", backend.problems());
    assert_eq!(bus.device(DQ4).station_address(), 0x1002);
    assert_eq!(bus.al_state(DQ4), ethercat_sim::al::OP);
    backend.exchange(&mut gm);
    assert!(gm.in1, "inputs flow again");
    assert!(
        bus.output_bit(DQ4, 1) && bus.output_bit(DQ16, 15),
        "outputs reach the restarted EL2004 (its SyncManager and FMMU are configured again)"
    );
    backend.stop();
    assert_eq!(bus.al_state(DQ4), ethercat_sim::al::INIT);
}

#[test]
fn a_different_terminal_restarting_in_the_slot_is_not_configured_and_is_reported() {
    let bus = sim();
    let mut backend = started::<Io>(&bus, description());
    let mut gm = Io::default();
    exchange_until_valid(&mut backend, &mut gm);
    // The EL2004 is swapped for an EL2828 while the program runs.
    bus.set_responding(DQ4, false);
    bus.power_cycle(DQ4);
    bus.set_identity(DQ4, 2, 0x0B0C_3052, 0x0011_0000);
    bus.set_responding(DQ4, true);
    let start = Instant::now();
    while start.elapsed() < Duration::from_millis(300) {
        let status = backend.exchange(&mut gm);
        assert!(status.bus_fault && !status.inputs_valid, "{status:?}");
        std::thread::sleep(Duration::from_millis(5));
    }
    let problems = backend.problems().join("\n");
    assert!(
        problems.contains(
            "position 2 (`dq4`, EL2004) is in INIT after a restart, as another device (vendor 0x2, product \
             0x0b0c3052; it was vendor 0x2, product 0x07d43052)"
        ),
        "{problems}"
    );
    assert_eq!(bus.al_state(DQ4), ethercat_sim::al::INIT);
    backend.stop();
}

#[test]
fn a_tripped_watchdog_is_acknowledged_and_the_subdevice_returns_to_op() {
    let bus = sim();
    let mut backend = started::<Io>(&bus, description());
    let mut gm = Io {
        q16_1: true,
        ..Io::default()
    };
    exchange_until_valid(&mut backend, &mut gm);
    bus.trip_watchdog(DQ16);
    assert!(!bus.output_bit(DQ16, 0), "outputs off in SAFE-OP");
    let status = backend.exchange(&mut gm);
    assert!(status.bus_fault && !status.inputs_valid, "{status:?}");
    assert_eq!(status.state, BusState::Mixed);
    exchange_until_valid(&mut backend, &mut gm);
    assert_eq!(bus.al_status_code(DQ16), 0);
    backend.exchange(&mut gm);
    assert!(bus.output_bit(DQ16, 0));
    backend.stop();
}

#[test]
fn a_subdevice_that_refuses_op_again_is_reported_persistently_with_its_al_status_code() {
    let bus = sim();
    let mut backend = started::<Io>(&bus, description());
    let mut gm = Io::default();
    exchange_until_valid(&mut backend, &mut gm);
    bus.refuse_transition(
        DQ16,
        ethercat_sim::al::OP,
        ethercat_sim::al::INVALID_OUTPUT_CONFIGURATION,
    );
    bus.trip_watchdog(DQ16);
    let start = Instant::now();
    // Several recovery attempts (every 100 ms): each is refused, the report stays.
    while start.elapsed() < Duration::from_millis(400) {
        let status = backend.exchange(&mut gm);
        assert!(status.bus_fault && !status.inputs_valid, "{status:?}");
        std::thread::sleep(Duration::from_millis(5));
    }
    let problems = backend.problems().join("\n");
    assert!(
        problems.contains(
            "position 3 (`dq16`, EL2889) is in SAFE-OP, AL status code 0x001d: Invalid Output \
             Configuration"
        ),
        "{problems}"
    );
    assert!(
        problems.contains("inputs stay invalid until it is back in OP"),
        "{problems}"
    );
    assert_eq!(backend.problems().len(), 1, "{problems}");
    bus.accept_transition(DQ16, ethercat_sim::al::OP);
    exchange_until_valid(&mut backend, &mut gm);
    backend.stop();
}

#[test]
fn keep_last_inputs_on_fault_keeps_values_but_flags_them_invalid() {
    let bus = sim();
    let mut backend = EtherCatBackend::<Io>::new(
        description(),
        transport(&bus),
        Options {
            inputs_on_fault: InputsOnFault::KeepLast,
            ..options()
        },
    )
    .unwrap();
    backend.start().unwrap();
    let mut gm = Io::default();
    bus.set_input_bit(DI, 0, true);
    backend.exchange(&mut gm);
    backend.exchange(&mut gm);
    bus.set_responding(DI, false);
    bus.set_input_bit(DI, 0, false);
    let status = backend.exchange(&mut gm);
    assert!(!status.inputs_valid && gm.in1);
    backend.stop();
}

#[test]
fn the_fault_hook_zeroes_outputs_and_drops_to_safe_op() {
    let bus = sim();
    let mut backend = started::<Io>(&bus, description());
    let mut gm = Io {
        q16_16: true,
        ..Io::default()
    };
    backend.exchange(&mut gm);
    backend.exchange(&mut gm);
    assert!(bus.output_bit(DQ16, 15));
    backend.fault();
    assert!(!bus.output_bit(DQ16, 15));
    let status = backend.exchange(&mut gm);
    assert_eq!(status.state, BusState::SafeOp);
    assert!(status.bus_fault && !status.inputs_valid);
    backend.stop();
    let _ = COUPLER;
}
