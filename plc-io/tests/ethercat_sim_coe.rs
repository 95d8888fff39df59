//! End-to-end tests of `plc_io::ethercat` on the simulated bus of `ethercat-sim` with an EL3004
//! analog terminal: real ethercrab configures its PDOs through CoE, start-up SDOs set it up
//! before OP, and a refused one names device, object and abort code.

#[path = "common/sim_bench.rs"]
mod sim_bench;

use ethercat_sim::{Device, SimBus};
use plc_core::GlobalMemory;
use plc_io::ethercat::{BusConfig, EtherCatBackend, Options, StartupSdo, devices};
use sim_bench::{started, transport};
use std::time::{Duration, Instant};

#[derive(GlobalMemory, Debug, Clone)]
struct Analog {
    #[plc(link = "ethercat.ai.ch2_value", direction = "input")]
    ch2: i16,
    /// INT widens to REAL (IEC 61131-3).
    #[plc(link = "ethercat.ai.ch2_value", direction = "input")]
    ch2_real: f32,
    #[plc(link = "ethercat.ai.ch2_underrange", direction = "input")]
    ch2_under: bool,
    #[plc(link = "ethercat.ai.ch4_value", direction = "input")]
    ch4: i16,
}

#[test]
fn el3004_analog_values_reach_int_and_real_variables_through_its_coe_configured_pdos() {
    let bus = SimBus::new(vec![Device::ek1100(), Device::el3004()]);
    let config = BusConfig {
        devices: vec![devices::ek1100("coupler"), devices::el3004("ai")],
    };
    let mut backend = started::<Analog>(&bus, config);
    let mut inputs = [0u8; 16];
    inputs[4] = 0b0000_0001; // channel 2 underrange
    inputs[6..8].copy_from_slice(&(-1234i16).to_le_bytes());
    inputs[14..16].copy_from_slice(&0x7FFFi16.to_le_bytes());
    bus.set_inputs(1, &inputs);
    let mut gm = Analog::default();
    for _ in 0..2 {
        assert!(backend.exchange(&mut gm).inputs_valid);
    }
    assert_eq!(
        (gm.ch2, gm.ch2_real, gm.ch2_under, gm.ch4),
        (-1234, -1234.0, true, 0x7FFF)
    );
    backend.stop();
}

/// An EL3004 configured by start-up SDOs (filter on and its setting for channel 1, unsigned
/// presentation for channel 2): written in PRE-OP by real ethercrab and read back over CoE,
/// in the device's own object dictionary afterwards.
#[test]
fn start_up_sdos_configure_the_el3004_before_op() {
    let bus = SimBus::new(vec![Device::ek1100(), Device::el3004()]);
    let sdo = |index, subindex, value, bits| StartupSdo {
        index,
        subindex,
        value,
        bits,
    };
    let mut ai = devices::el3004("ai");
    ai.startup = vec![
        sdo(0x8000, 0x06, 1, 8),
        sdo(0x8000, 0x15, 2, 16),
        sdo(0x8010, 0x02, 1, 8),
    ];
    let config = BusConfig {
        devices: vec![devices::ek1100("coupler"), ai],
    };
    config.validate().unwrap();
    assert_eq!(bus.device(1).sdo(0x8000, 0x06), Some(0), "off at power-on");
    let mut backend = started::<Analog>(&bus, config);
    let d = bus.device(1);
    assert_eq!(
        (
            d.sdo(0x8000, 0x06),
            d.sdo(0x8000, 0x15),
            d.sdo(0x8010, 0x02)
        ),
        (Some(1), Some(2), Some(1))
    );
    assert_eq!(d.sdo(0x8020, 0x06), Some(0), "other channels untouched");
    let mut gm = Analog::default();
    assert!(
        backend.exchange(&mut gm).inputs_valid,
        "and the bus is in OP"
    );

    // The EL3004 loses power, and with it its settings: the recovery writes them again in
    // PRE-OP before the device goes on to OP.
    bus.set_responding(1, false);
    bus.power_cycle(1);
    assert!(backend.exchange(&mut gm).bus_fault);
    bus.set_responding(1, true);
    assert_eq!(
        bus.device(1).sdo(0x8000, 0x06),
        Some(0),
        "reset by the power cycle"
    );
    let deadline = Instant::now() + Duration::from_secs(10);
    while !backend.exchange(&mut gm).inputs_valid {
        assert!(
            Instant::now() < deadline,
            "not back in OP: {:?}",
            backend.problems()
        );
        std::thread::sleep(Duration::from_millis(2));
    }
    let d = bus.device(1);
    assert_eq!(
        (
            d.sdo(0x8000, 0x06),
            d.sdo(0x8000, 0x15),
            d.sdo(0x8010, 0x02)
        ),
        (Some(1), Some(2), Some(1)),
        "written again after the power cycle"
    );
    assert_eq!(bus.al_state(1), ethercat_sim::al::OP);
    backend.stop();
}

/// A start-up SDO the device refuses stops the bring-up before OP, with an error that names the
/// device, its position, the object and the device's abort code; a value too wide for its
/// object is refused by the description's checks before the bus is touched.
#[test]
fn a_refused_start_up_sdo_names_device_object_and_abort_code() {
    let bus = SimBus::new(vec![Device::ek1100(), Device::el3004()]);
    let mut ai = devices::el3004("ai");
    ai.startup = vec![StartupSdo {
        index: 0x8000,
        subindex: 0x30,
        value: 1,
        bits: 8,
    }];
    let config = BusConfig {
        devices: vec![devices::ek1100("coupler"), ai.clone()],
    };
    let mut backend =
        EtherCatBackend::<Analog>::new(config, transport(&bus), Options::simulated()).unwrap();
    let err = backend.start().unwrap_err().to_string();
    for needle in [
        "start-up SDO 0x8000:30",
        "device `ai` (position 1)",
        "0x06090011",
    ] {
        assert!(err.contains(needle), "{needle} missing in {err}");
    }
    assert_ne!(bus.al_state(1), 8, "not switched to OP");

    ai.startup[0].value = 300;
    let e = BusConfig {
        devices: vec![devices::ek1100("coupler"), ai],
    }
    .validate()
    .unwrap_err()
    .to_string();
    assert!(
        e.contains("start-up SDO 0x8000:30: 300 does not fit 8 bits"),
        "{e}"
    );
}
