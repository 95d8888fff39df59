// PENDING: written against the announced APIs of `ethercat-sim` (SimBus, Device, inproc::spawn)
// and `#[derive(GlobalMemory)]`, neither of which had landed on main when this was written.
// Move to `examples/src/bin/tensile_tester.rs` (and fix names) when they land; cargo does not build it here.
//! The main example: a tensile tester on EtherCAT.
//!
//! ```sh
//! cargo run --release -p examples --bin tensile_tester                  # simulated bus, until Ctrl-C
//! cargo run --release -p examples --bin tensile_tester -- --cycles 5000
//! sudo target/release/tensile_tester --interface enp3s0                 # real terminals
//! ```
//!
//! Options: `--bus FILE` (bus description, TOML or JSON; default: the built-in
//! `examples/bus/tensile_tester.toml`), `--interface NAME` (real NIC instead of the simulated
//! bus), `--period-us N` (cycle period, default 1000), `--cycles N` (stop after N cycles),
//! `--segment NAME` (shared memory for HMIs, default `tensile_tester`), `--retain DIR`
//! (directory of the retain file, default a temporary directory).
//!
//! On the simulated bus (EK1100, EL1004, EL2889, EL2004) a model of the machine runs on a
//! thread: it reads the drive outputs and sets the limit switches, so the program runs one
//! test after another. A status line is printed each second.

#[path = "../tensile/mod.rs"] // from examples/src/bin/
mod tensile;

use plc_core::GlobalMemory;
use plc_io::ethercat::{BusConfig, EtherCatBackend, Options, Transport};
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::{Duration, Instant};
use tensile::{Gm, TickInfo, process_tick};

struct Args {
    bus: Option<PathBuf>,
    interface: Option<String>,
    period: Duration,
    cycles: Option<u64>,
    segment: String,
    retain: Option<PathBuf>,
}

const USAGE: &str = "usage: tensile_tester [--bus FILE] [--interface NAME] [--period-us N] \
                     [--cycles N] [--segment NAME] [--retain DIR]";

fn parse_args() -> Result<Args, String> {
    let mut args = Args {
        bus: None,
        interface: None,
        period: Duration::from_millis(1),
        cycles: None,
        segment: "tensile_tester".into(),
        retain: None,
    };
    let mut it = std::env::args().skip(1);
    while let Some(flag) = it.next() {
        if flag == "--help" || flag == "-h" {
            return Err(USAGE.into());
        }
        let mut value = || {
            it.next()
                .ok_or_else(|| format!("{flag} needs a value\n{USAGE}"))
        };
        let number = |v: String| -> Result<u64, String> {
            v.parse()
                .map_err(|_| format!("{flag}: `{v}` is not a whole number\n{USAGE}"))
        };
        match flag.as_str() {
            "--bus" => args.bus = Some(value()?.into()),
            "--interface" => args.interface = Some(value()?),
            "--period-us" => {
                let us = number(value()?)?;
                if us == 0 {
                    return Err("--period-us must be at least 1".into());
                }
                args.period = Duration::from_micros(us);
            }
            "--cycles" => args.cycles = Some(number(value()?)?),
            "--segment" => args.segment = value()?,
            "--retain" => args.retain = Some(value()?.into()),
            other => return Err(format!("unknown option `{other}`\n{USAGE}")),
        }
    }
    Ok(args)
}

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("tensile_tester: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run() -> Result<(), Box<dyn std::error::Error>> {
    let args = parse_args()?;
    let config = match &args.bus {
        Some(path) => BusConfig::load(path)?,
        None => BusConfig::from_toml_str(tensile::BUS_TOML)?,
    };
    let mut options = Options::default();
    let mut _plant = None;
    let transport = match &args.interface {
        Some(name) => Transport::Interface(name.clone()),
        None => {
            let sim = tensile::simulated_bus();
            _plant = Some(tensile::plant::Plant::spawn(sim.clone())?);
            options.dc_static_sync_iterations = 100;
            tensile::sim_transport(sim)
        }
    };
    let mut backend = EtherCatBackend::<Gm>::new(config, transport, options)?;
    backend.start()?;
    println!(
        "tensile_tester: bus in OP ({}), {} links, period {} us; segment `{}`, retain {}; Ctrl-C stops",
        args.interface.as_deref().unwrap_or("simulated bus"),
        backend.bindings().count(),
        args.period.as_micros(),
        args.segment,
        args.retain
            .as_ref()
            .map_or("in a temporary directory".into(), |d| d
                .display()
                .to_string()),
    );
    let stop = ctrl_c();
    let mut gm = Gm::default();
    let mut stats = Stats::default();
    let start = Instant::now();
    let mut next = start;
    let mut last_print = start;
    let mut cycle: u64 = 0;
    let mut prev = start;
    while !stop.load(std::sync::atomic::Ordering::Relaxed) && args.cycles.is_none_or(|n| cycle < n)
    {
        next += args.period;
        let now = Instant::now();
        if now < next {
            std::thread::sleep(next - now);
        } else {
            stats.overruns += 1;
            next = now;
        }
        let t0 = Instant::now();
        if cycle > 0 {
            stats.period(t0 - prev);
        }
        prev = t0;
        let status = backend.exchange(&mut gm);
        gm.unpack_bits();
        process_tick(
            &mut gm,
            TickInfo {
                period: args.period,
                inputs_valid: status.inputs_valid,
            },
        );
        gm.pack_bits();
        stats.work(t0.elapsed());
        cycle += 1;
        if last_print.elapsed() >= Duration::from_secs(1) {
            last_print = Instant::now();
            println!(
                "cycle {cycle:>7} | period min/mean/max {} | work max {:>4} us | overruns {} | bus {} wkc {}/{}{} | {} {} force {:5.1} kN | tests {}",
                stats.period_text(),
                stats.work_max.as_micros(),
                stats.overruns,
                status.state,
                status.working_counter,
                status.expected_working_counter,
                if status.inputs_valid {
                    ""
                } else {
                    " INPUTS INVALID"
                },
                gm.info_test_id,
                gm.machine_state_name,
                gm.force_kn,
                gm.tests_completed,
            );
            stats.reset_window();
        }
    }
    backend.stop();
    println!(
        "tensile_tester: stopped after {cycle} cycles, {} tests; bus back in INIT",
        gm.tests_completed
    );
    Ok(())
}

/// Period statistics over the last second.
#[derive(Default)]
struct Stats {
    n: u32,
    min: Option<Duration>,
    max: Duration,
    sum: Duration,
    work_max: Duration,
    overruns: u64,
}

impl Stats {
    fn period(&mut self, d: Duration) {
        self.n += 1;
        self.min = Some(self.min.map_or(d, |m| m.min(d)));
        self.max = self.max.max(d);
        self.sum += d;
    }

    fn work(&mut self, d: Duration) {
        self.work_max = self.work_max.max(d);
    }

    fn period_text(&self) -> String {
        let us = |d: Duration| d.as_secs_f64() * 1e6;
        match self.min {
            Some(min) => format!(
                "{:>6.0}/{:>6.0}/{:>6.0} us",
                us(min),
                us(self.sum) / f64::from(self.n),
                us(self.max)
            ),
            None => "-".into(),
        }
    }

    fn reset_window(&mut self) {
        let overruns = self.overruns;
        *self = Stats {
            overruns,
            ..Stats::default()
        };
    }
}

/// A flag set by Ctrl-C / SIGTERM.
fn ctrl_c() -> std::sync::Arc<std::sync::atomic::AtomicBool> {
    let flag = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
    let _ = STOP.set(flag.clone());
    // SAFETY: `on_signal` only stores to an atomic, which is async-signal-safe.
    unsafe {
        libc_signal(2, on_signal);
        libc_signal(15, on_signal);
    }
    flag
}

static STOP: std::sync::OnceLock<std::sync::Arc<std::sync::atomic::AtomicBool>> =
    std::sync::OnceLock::new();

extern "C" fn on_signal(_: i32) {
    if let Some(f) = STOP.get() {
        f.store(true, std::sync::atomic::Ordering::Relaxed);
    }
}

unsafe extern "C" {
    #[link_name = "signal"]
    fn libc_signal(sig: i32, handler: extern "C" fn(i32)) -> usize;
}
