//! Faults and recovery on the simulated bus of `ethercat-sim`, through real ethercrab: a silent
//! SubDevice is a bus fault (never stale data), one that lost power comes back to OP, a
//! different terminal in its slot is refused, a tripped watchdog is acknowledged, a refusal of
//! OP is reported with its AL status code; inputs kept or outputs zeroed on a fault.

#[path = "common/sim_bench.rs"]
mod sim_bench;

use plc_io::ethercat::{BusState, EtherCatBackend, InputsOnFault, Options};
use sim_bench::{COUPLER, DI, DQ4, DQ16, Io, description, options, sim, started, transport};
use std::time::{Duration, Instant};

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
