//! `EtherCatBackend` under `plc_io::Runtime` on the simulated bus: what a panicking program
//! and a clean stop leave on the SubDevices.

#[path = "common/sim_bench.rs"]
mod sim_bench;

use ethercat_sim::{SimBus, al};
use plc_core::GlobalMemory;
use plc_io::ethercat::EtherCatBackend;
use plc_io::{Runtime, RuntimeError};
use sim_bench::sim;
use std::time::Duration;

const DI: usize = 1;
const DQ4: usize = 2;
const DQ16: usize = 3;

#[derive(GlobalMemory, Debug, Clone)]
struct Io {
    #[plc(link = "ethercat.di.input1", direction = "input")]
    in1: bool,
    #[plc(link = "ethercat.dq4.output1", direction = "output")]
    q4_1: bool,
    #[plc(link = "ethercat.dq16.output9", direction = "output")]
    q16_9: bool,
}

fn backend(bus: &SimBus) -> EtherCatBackend<Io> {
    sim_bench::backend(bus, sim_bench::description())
}

/// The bytes in the output SyncManager memory of the device at `pos` (what it drives once
/// in OP), whatever its state: `SimBus::outputs` reads zero outside OP anyway.
fn output_memory(bus: &SimBus, pos: usize, len: usize) -> Vec<u8> {
    let mut out = vec![0xEE; len];
    bus.device(pos).register(0x0F00, &mut out);
    out
}

fn runtime(bus: &SimBus, cycles: u64) -> plc_io::RuntimeBuilder<Io> {
    Runtime::<Io>::builder()
        .period(Duration::from_millis(2))
        .backend(backend(bus))
        .handle_signals(false)
        .max_cycles(cycles)
}

#[test]
fn a_program_panic_zeroes_the_outputs_and_leaves_the_subdevices_in_safe_op() {
    let bus = sim();
    bus.set_input_bit(DI, 0, true);
    let mut seen_on_bus = false;
    let probe = bus.clone();
    let result = runtime(&bus, 1000)
        .build()
        .expect("the runtime's settings are valid")
        .run(|ctx| {
            ctx.gm.q4_1 = true;
            ctx.gm.q16_9 = true;
            // The outputs of earlier cycles are on the terminals before the program fails.
            seen_on_bus |= probe.output_bit(DQ4, 0) && probe.output_bit(DQ16, 8);
            if seen_on_bus && ctx.gm.in1 {
                panic!("program bug");
            }
        });
    let err = result.unwrap_err();
    assert!(
        matches!(&err, RuntimeError::Panicked { message, .. } if message == "program bug"),
        "{err}"
    );
    assert!(seen_on_bus, "outputs never reached the bus");
    for pos in [DI, DQ4, DQ16] {
        assert_eq!(bus.al_state(pos), al::SAFE_OP, "device {pos}");
    }
    assert_eq!(output_memory(&bus, DQ4, 1), [0]);
    assert_eq!(output_memory(&bus, DQ16, 2), [0, 0]);
}

#[test]
fn a_clean_stop_zeroes_the_outputs_and_returns_the_subdevices_to_init() {
    let bus = sim();
    bus.set_input_bit(DI, 0, true);
    let mut outputs_seen = false;
    let mut inputs_seen = false;
    let probe = bus.clone();
    let gm = runtime(&bus, 50)
        .build()
        .expect("the runtime's settings are valid")
        .run(|ctx| {
            ctx.gm.q16_9 = true;
            outputs_seen |= probe.output_bit(DQ16, 8);
            inputs_seen |= ctx.inputs_valid && ctx.gm.in1;
        })
        .unwrap();
    assert!(gm.q16_9);
    assert!(
        outputs_seen && inputs_seen,
        "outputs {outputs_seen}, inputs {inputs_seen}"
    );
    for pos in 0..4 {
        assert_eq!(bus.al_state(pos), al::INIT, "device {pos}");
    }
    assert_eq!(output_memory(&bus, DQ16, 2), [0, 0]);
}
