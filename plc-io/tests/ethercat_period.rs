//! Measurement, not a test: the period `plc_io::Runtime` achieves with the EtherCAT backend on
//! the simulated bus (EK1100 + EL1004 + EL2004 + EL2889 through the in-process transport),
//! 1 ms for 10 s. Ignored by default because its figures depend on the machine and nothing
//! about them is asserted; run it explicitly, on an idle machine, in release mode:
//!
//! ```sh
//! cargo test --release -p plc-io --test ethercat_period -- --ignored
//! ```
//!
//! `PLC_BUS_PERIOD_US` and `PLC_BUS_SECS` change the period (default 1000) and the duration
//! (default 10). It prints the achieved period (time between the starts of consecutive ticks)
//! min/mean/p99/max, the runtime's overruns (cycles whose work took longer than the period)
//! and the cycles whose inputs were not valid. The period includes the exchange's jitter
//! (the tick starts after it), and after a late cycle the runtime starts the next one at
//! once, so a very short period follows a long one.

#[path = "common/sim_bench.rs"]
mod sim_bench;

use plc_core::GlobalMemory;
use plc_io::Runtime;
use std::io::Write;
use std::time::{Duration, Instant};

#[derive(GlobalMemory, Debug, Clone)]
struct Io {
    #[plc(link = "ethercat.di.input1", direction = "input")]
    in1: bool,
    #[plc(link = "ethercat.dq4.output1", direction = "output")]
    q4_1: bool,
    #[plc(link = "ethercat.dq16.output16", direction = "output")]
    q16_16: bool,
}

fn env_u64(name: &str, default: u64) -> u64 {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

#[test]
#[ignore = "a measurement: run with --ignored (see the file's documentation)"]
fn bus_period_through_the_runtime_on_the_simulated_bus() {
    let period = Duration::from_micros(env_u64("PLC_BUS_PERIOD_US", 1000).max(1));
    let secs = env_u64("PLC_BUS_SECS", 10);
    let cycles = (secs * 1_000_000 / period.as_micros() as u64).max(2);

    let bus = sim_bench::sim();
    let backend = sim_bench::backend::<Io>(&bus, sim_bench::description());

    let mut starts: Vec<Instant> = Vec::with_capacity(cycles as usize);
    let mut invalid = 0u64;
    let mut overruns = 0u64;
    let began = Instant::now();
    Runtime::<Io>::builder()
        .period(period)
        .backend(backend)
        .handle_signals(false)
        .max_cycles(cycles)
        .build()
        .expect("the runtime's settings are valid")
        .run(|ctx| {
            starts.push(Instant::now());
            invalid += u64::from(!ctx.inputs_valid);
            overruns = ctx.stats.overruns;
            ctx.gm.q4_1 = ctx.cycle % 2 == 0;
            ctx.gm.q16_16 = ctx.gm.in1;
        })
        .unwrap();
    let elapsed = began.elapsed();

    let mut periods: Vec<Duration> = starts.windows(2).map(|w| w[1] - w[0]).collect();
    periods.sort();
    let n = periods.len();
    let mean = periods.iter().sum::<Duration>() / n as u32;
    let p99 = periods[(n * 99 / 100).min(n - 1)];
    let late = periods.iter().filter(|p| **p > period + period / 2).count();
    // Straight to the terminal: the harness captures `println!`.
    let _ = writeln!(
        std::io::stderr(),
        "bus period {} us on the simulated bus through plc_io::Runtime, {cycles} cycles in \
         {:.2} s: achieved period min {} us, mean {} us, p99 {} us, max {} us; periods over \
         1.5x the target {late}; runtime overruns (work > period) {overruns}; cycles with \
         invalid inputs {invalid}",
        period.as_micros(),
        elapsed.as_secs_f64(),
        periods[0].as_micros(),
        mean.as_micros(),
        p99.as_micros(),
        periods[n - 1].as_micros(),
    );
}
