//! Recovery on a bus with distributed clocks, through real ethercrab on the simulated bus: a
//! DC SubDevice that lost its power comes back with its clock and its SYNC0 at power-on
//! values; the backend's recovery gives it its system time offset and SYNC0 again (the
//! description's period, a start on the SYNC0 grid of the reference clock, as ethercrab's
//! `configure_dc_sync` at start-up) before it goes on to SAFE-OP and OP.

#[path = "common/servo.rs"]
mod servo;
#[path = "common/sim_bench.rs"]
mod sim_bench;

use ethercat_sim::{Device, SimBus};
use plc_core::GlobalMemory;
use plc_core::Time;
use plc_core::motion::AxisState;
use plc_io::ethercat::{BusConfig, DcConfig, DeviceConfig, EtherCatBackend, devices};
use servo::Machine;
use sim_bench::{backend, description, sim};
use std::time::{Duration, Instant};

/// Ring positions of the simulated bench.
const COUPLER: usize = 0;
const DQ4: usize = 2;
const DQ16: usize = 3;

const PERIOD: Duration = Duration::from_millis(1);

/// The difference every clock must stay below (Beckhoff specifies < 100 ns).
const LIMIT_NS: u32 = 100;

fn dc() -> DcConfig {
    DcConfig {
        sync0: Time::from_millis(1),
        shift: Time::from_micros(250),
    }
}

#[derive(GlobalMemory, Debug, Clone)]
struct Io {
    #[plc(link = "ethercat.di.input1", direction = "input")]
    in1: bool,
    #[plc(link = "ethercat.dq4.output2", direction = "output")]
    q4_2: bool,
    #[plc(link = "ethercat.dq16.output1", direction = "output")]
    q16_1: bool,
}

/// Exchanges every millisecond for `cycles` cycles, or until `done` holds for a status
/// (then true).
fn cycle<T: GlobalMemory + Clone + Send + 'static>(
    backend: &mut EtherCatBackend<T>,
    gm: &mut T,
    cycles: u32,
    mut done: impl FnMut(&plc_io::ethercat::BusStatus) -> bool,
) -> bool {
    let began = Instant::now();
    for i in 0..cycles {
        let status = backend.exchange(gm);
        if done(&status) {
            return true;
        }
        std::thread::sleep((began + PERIOD * (i + 1)).saturating_duration_since(Instant::now()));
    }
    false
}

#[test]
fn a_dc_terminal_that_lost_power_comes_back_to_op_with_its_clock_and_sync0() {
    let bus = sim();
    let mut config = description();
    for pos in [DQ4, DQ16] {
        config.devices[pos].dc = Some(dc());
    }
    let mut backend = backend::<Io>(&bus, config);
    backend.start().unwrap();
    let mut gm = Io {
        q4_2: true,
        q16_1: true,
        ..Io::default()
    };
    // SYNC0 starts 100 ms after configuration.
    cycle(&mut backend, &mut gm, 200, |_| false);
    assert!(bus.sync0(DQ4).active && bus.sync0(DQ4).pulses > 50);

    // The EL2004 loses power: it and the EL2889 behind it drop off the ring, and it comes
    // back in INIT with its SYNC unit off and its clock without offset.
    bus.set_responding(DQ4, false);
    bus.power_cycle(DQ4);
    cycle(&mut backend, &mut gm, 20, |_| false);
    assert!(!bus.sync0(DQ4).active);
    bus.set_responding(DQ4, true);
    let back = cycle(&mut backend, &mut gm, 5_000, |s| s.inputs_valid);
    assert!(back, "not back in OP: {:?}", backend.problems());
    assert!(backend.problems().is_empty(), "{:?}", backend.problems());
    assert_eq!(bus.al_state(DQ4), ethercat_sim::al::OP);
    let restarted = bus.sync0(DQ4);
    assert!(restarted.active, "SYNC0 configured again: {restarted:?}");

    // Its first pulse comes 100 ms after the recovery configured it, on the reference
    // clock's SYNC0 grid; its clock follows the reference's time again within 100 ns once
    // its time control loop has settled on the cyclic FRMW (about a hundred received
    // times, as at start-up, where ethercrab's static drift compensation sends them).
    let mut status = backend.status();
    let settled = cycle(&mut backend, &mut gm, 3_000, |s| {
        status = *s;
        bus.sync0(DQ4).pulses > restarted.pulses + 100
            && s.dc
                .and_then(|d| d.max_time_difference_ns)
                .is_some_and(|ns| ns < LIMIT_NS)
    });
    assert!(status.inputs_valid, "{status:?}");
    let s4 = bus.sync0(DQ4);
    let s16 = bus.sync0(DQ16);
    println!(
        "{s4:?} {s16:?} {:?}; system times {:?}",
        status.dc,
        bus.system_times()
    );
    assert!(
        s4.pulses > restarted.pulses + 100,
        "SYNC0 pulses again: {restarted:?} then {s4:?}"
    );
    assert_eq!(
        s4.last_pulse.map(|t| t % 1_000_000),
        Some(0),
        "on the SYNC0 grid: {s4:?}"
    );
    // Pulses on the same instants of the system time as the EL2889's, which kept its
    // SYNC0 (their last pulses are whole periods apart).
    let (Some(a), Some(b)) = (s4.last_pulse, s16.last_pulse) else {
        panic!("{s4:?} {s16:?}");
    };
    assert_eq!(a.abs_diff(b) % 1_000_000, 0, "{s4:?} {s16:?}");
    let times = bus.system_times();
    let (Some(reference), Some(restarted_time)) = (times[COUPLER], times[DQ4]) else {
        panic!("{times:?}");
    };
    assert!(
        reference.abs_diff(restarted_time) < 10_000,
        "the restarted clock follows the reference's time: {times:?}"
    );
    assert!(
        settled,
        "within 3 s: {:?}, largest difference {:?}",
        bus.sync0(DQ4),
        status.dc
    );
    assert!(
        bus.output_bit(DQ4, 1) && bus.output_bit(DQ16, 0),
        "the outputs flow again"
    );
    backend.stop();
}

/// Ring positions of the servo bench: an EK1100 (the DC reference clock) and the AKD.
const SERVO: usize = 1;

/// One cycle of the program with valid inputs: the power block enabled (and `reset` asked).
fn program(gm: &mut Machine, reset: bool) {
    gm.cycle(|gm| {
        gm.power.call(&mut gm.axis, true);
        gm.reset.call(&mut gm.axis, reset);
    });
}

/// Exchanges and runs the program every millisecond (the program only on valid inputs,
/// resetting while `reset` says so) for at most `cycles` cycles, until `done`; whether it
/// came.
fn run(
    backend: &mut EtherCatBackend<Machine>,
    gm: &mut Machine,
    cycles: u32,
    reset: impl Fn(&Machine) -> bool,
    mut done: impl FnMut(&Machine, &plc_io::ethercat::BusStatus) -> bool,
) -> bool {
    let began = Instant::now();
    for i in 0..cycles {
        let status = backend.exchange(gm);
        if status.inputs_valid {
            let r = reset(gm);
            program(gm, r);
        }
        if done(gm, &status) {
            return true;
        }
        std::thread::sleep((began + PERIOD * (i + 1)).saturating_duration_since(Instant::now()));
    }
    false
}

#[test]
fn a_servo_drive_that_lost_power_is_back_in_op_synchronised_and_can_be_enabled_again() {
    let bus = SimBus::new(vec![Device::ek1100(), Device::akd()]);
    let config = BusConfig {
        devices: vec![
            devices::ek1100("coupler"),
            DeviceConfig {
                dc: Some(dc()),
                ..devices::akd("servo")
            },
        ],
    };
    let mut backend = backend::<Machine>(&bus, config);
    backend.start().unwrap();
    let mut gm = Machine::new();
    let enabled = |gm: &Machine, _: &plc_io::ethercat::BusStatus| {
        gm.power.Status && gm.axis.state() == AxisState::Standstill && gm.mode_display == 8
    };
    assert!(
        run(&mut backend, &mut gm, 1_000, |_| false, enabled),
        "{:?}",
        gm.axis
    );
    // SYNC0 runs (it starts 100 ms after configuration) and drives the cyclic mode.
    assert!(run(
        &mut backend,
        &mut gm,
        1_000,
        |_| false,
        |_, _| bus.sync0(SERVO).pulses > 50
    ));

    // The drive loses its power and comes back: INIT, station address 0, SYNC unit off.
    bus.set_responding(SERVO, false);
    bus.power_cycle(SERVO);
    run(&mut backend, &mut gm, 20, |_| false, |_, _| false);
    assert!(!bus.sync0(SERVO).active);
    bus.set_responding(SERVO, true);
    let back = run(
        &mut backend,
        &mut gm,
        5_000,
        |_| false,
        |_, s| s.inputs_valid,
    );
    assert!(back, "not back in OP: {:?}", backend.problems());
    assert!(backend.problems().is_empty(), "{:?}", backend.problems());
    let restarted = bus.sync0(SERVO);
    assert!(restarted.active, "SYNC0 configured again: {restarted:?}");

    // The axis saw its drive go away while enabled; reset, it is enabled again in cyclic
    // synchronous position, now with SYNC0 pulsing on the reference's grid.
    let again = run(
        &mut backend,
        &mut gm,
        3_000,
        |gm| gm.axis.state() == AxisState::ErrorStop,
        |gm, s| enabled(gm, s) && bus.sync0(SERVO).pulses > 100,
    );
    let s = bus.sync0(SERVO);
    assert!(again, "{:?}; SYNC0 {s:?}", gm.axis);
    assert_eq!(s.last_pulse.map(|t| t % 1_000_000), Some(0), "{s:?}");
    assert_eq!(gm.error_code, 0, "no fault: {:#06x}", gm.error_code);
    backend.stop();
}
