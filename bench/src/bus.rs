//! plc-bench group `bus`: `plc_io::Runtime` driving the simulated tensile-tester bus over a
//! veth pair with raw sockets, as on a real NIC, against the loop a user writes directly on
//! ethercrab instead (`bus/direct.rs`), on the same bus with the same process data and the same
//! tick. The two run in alternating blocks of a fixed number of cycles (so both see the same
//! machine load), each block on a thread of its own pinned to the same CPU, under SCHED_FIFO
//! where it is permitted; each figure is the median over the blocks. The same comparison on
//! ethercat-sim's in-process transport follows, labelled `bus_inproc_*`. Method and figures:
//! BENCHMARKS.md; the runs: docs/benchmarks-history.md, "Bus cycle".

mod direct;
mod jitter;
use super::place;
mod veth;

use direct::Wire;
use examples::tensile::{self, Gm, TickInfo, process_tick};
use jitter::{Block, median};
use plc_io::Runtime;
use plc_io::ethercat::{BusConfig, EtherCatBackend, Options, Transport};
use plc_io::probe::CycleTimes;
use std::fmt::Write;
use std::sync::{Arc, Mutex};
use std::time::Duration;

/// Set (to anything), the figures are taken without SCHED_FIFO even where it is permitted.
pub const NO_FIFO: &str = "PLC_BENCH_BUS_NO_FIFO";

/// Blocks of each side, alternating: the figures are their medians.
const BLOCKS: usize = 5;

/// Cycles run before a block's timed cycles, right after the bus reached OP.
const WARMUP: usize = 100;

/// The rates timed: the figures' name part, the period, and the timed cycles per block
/// (`--quick`, and without it).
const RATES: [(&str, Duration, usize, usize); 2] = [
    ("1khz", Duration::from_micros(1000), 1000, 5000),
    ("4khz", Duration::from_micros(250), 2000, 20000),
];

/// The figure lines of the group. Where the machine cannot show a figure (no veth pair can be
/// made) the line says why instead of a number; an error of the bus itself is an `Err`.
pub fn run(quick: bool) -> Result<String, String> {
    let cpus = place::allowed_cpus();
    // The cycle threads on the last CPU, the simulator on another when there is one: it
    // stands for hardware, which does not take the cycle's CPU.
    let cycle_cpu = *cpus.last().unwrap_or(&0);
    let sim_cpu = cpus
        .iter()
        .copied()
        .find(|&c| c != cycle_cpu)
        .unwrap_or(cycle_cpu);
    // The environment can ask for the figures without realtime scheduling, as a program run
    // by an unprivileged user gets them.
    let fifo = match std::env::var_os(NO_FIFO) {
        Some(_) => Err(format!("SCHED_FIFO not used ({NO_FIFO} is set)")),
        None => place::fifo_permitted(place::CYCLE_PRIORITY),
    };
    let sched = match &fifo {
        Ok(()) => format!("SCHED_FIFO {}", place::CYCLE_PRIORITY),
        Err(why) => format!("SCHED_OTHER: {why}"),
    };
    let segment = format!("plc_bench_bus_{}", std::process::id());
    let mut out = String::new();
    let plan = Plan {
        cycle_cpu,
        fifo: fifo.is_ok(),
        segment: &segment,
        quick,
    };

    match veth::Veth::create() {
        Ok(wire) => {
            let server = wire.serve(tensile::simulated_bus(), sim_cpu, fifo.is_ok())?;
            let _ = writeln!(
                out,
                "bus_setup: raw sockets over the veth pair {}-plcbs0 (network namespace {}), \
                 cycle threads on CPU {cycle_cpu}, simulator on CPU {sim_cpu}, {sched}",
                veth::MAIN,
                wire.namespace()
            );
            let rates = plan.rates(&Place::Veth(&wire));
            server.stop()?;
            report_or_why(&mut out, "bus", rates, &sched);
        }
        Err(why) => {
            let _ = writeln!(out, "bus_setup: no veth pair: {why}");
            for name in figure_names("bus") {
                let _ = writeln!(out, "{name}: unavailable (no veth: {why})");
            }
        }
    }

    let _ = writeln!(
        out,
        "bus_inproc_setup: ethercat-sim's in-process transport (no network), cycle threads and \
         the simulator's thread on CPU {cycle_cpu}, {sched}"
    );
    let rates = plan.rates(&Place::InProcess);
    report_or_why(&mut out, "bus_inproc", rates, &sched);
    Ok(out)
}

/// The framework's own time (the cycle less the bus exchange and the tick) summed over
/// `cycles` cycles of the `Runtime` on ethercat-sim's in-process tensile-tester bus, at period
/// zero, after the warm-up: the criterion bench of the bus cycle's framework code.
pub fn framework_time_in_process(cycles: usize) -> Result<Duration, String> {
    let segment = format!("plc_bench_bus_criterion_{}", std::process::id());
    let plan = Plan {
        cycle_cpu: 0,
        fifo: false,
        segment: &segment,
        quick: true,
    };
    let wire = Wire::InProcess(tensile::simulated_bus());
    let (times, _) = plan.runtime_block(wire, Duration::ZERO, cycles, process_tick)?;
    Ok(times.iter().map(CycleTimes::framework).sum())
}

/// Where the bus is.
enum Place<'a> {
    /// Behind the veth pair, served in its namespace.
    Veth(&'a veth::Veth),
    /// In the process: each block gets a fresh simulated bus.
    InProcess,
}

/// What every block shares.
struct Plan<'a> {
    cycle_cpu: usize,
    fifo: bool,
    segment: &'a str,
    quick: bool,
}

/// One rate's blocks, each side's.
struct Rate {
    name: &'static str,
    cycles: usize,
    runtime: Vec<Block>,
    direct: Vec<Block>,
    /// Timed cycles in which the inputs were not valid (bad working counter, no answer).
    invalid: usize,
}

impl Plan<'_> {
    /// Both rates, [`BLOCKS`] alternating blocks of each side.
    fn rates(&self, place: &Place) -> Result<Vec<Rate>, String> {
        let mut rates = Vec::new();
        for (name, period, quick_cycles, cycles) in RATES {
            let cycles = if self.quick { quick_cycles } else { cycles };
            let mut rate = Rate {
                name,
                cycles,
                runtime: Vec::new(),
                direct: Vec::new(),
                invalid: 0,
            };
            for _ in 0..BLOCKS {
                for framework in [true, false] {
                    let (times, invalid) = self.block(place, framework, period, cycles)?;
                    rate.invalid += invalid;
                    let figures = jitter::analyse(&times, period);
                    if framework {
                        rate.runtime.push(figures);
                    } else {
                        rate.direct.push(figures);
                    }
                }
            }
            rates.push(rate);
        }
        Ok(rates)
    }

    /// One block on a thread of its own: in the namespace, pinned, then the Runtime or the
    /// direct loop from bus start to bus stop.
    fn block(
        &self,
        place: &Place,
        framework: bool,
        period: Duration,
        cycles: usize,
    ) -> Result<(Vec<CycleTimes>, usize), String> {
        std::thread::scope(|s| {
            s.spawn(|| {
                let wire = match place {
                    Place::Veth(v) => {
                        v.enter()?;
                        Wire::Interface(veth::MAIN)
                    }
                    Place::InProcess => Wire::InProcess(tensile::simulated_bus()),
                };
                place::pin(self.cycle_cpu)?;
                if framework {
                    self.runtime_block(wire, period, cycles, process_tick)
                } else {
                    if self.fifo {
                        place::set_fifo(place::CYCLE_PRIORITY)?;
                    }
                    let timeouts = Options::simulated().timeouts;
                    direct::run(wire, timeouts, period, WARMUP, cycles, process_tick)
                }
            })
            .join()
            .unwrap_or_else(|_| Err("a block's thread panicked".into()))
        })
    }

    /// The framework's side: the tensile tester's declaration and the program `tick` in a
    /// `Runtime` with its EtherCAT backend and a shared-memory segment (as the example runs),
    /// the cycle's timestamps from the runtime's probe.
    fn runtime_block(
        &self,
        wire: Wire,
        period: Duration,
        cycles: usize,
        mut tick: impl FnMut(&mut Gm, TickInfo),
    ) -> Result<(Vec<CycleTimes>, usize), String> {
        let config = BusConfig::from_toml_str(tensile::BUS_TOML).map_err(|e| e.to_string())?;
        let transport = match wire {
            Wire::Interface(name) => Transport::Interface(name.into()),
            Wire::InProcess(bus) => tensile::sim_transport(bus),
        };
        let backend = EtherCatBackend::<Gm>::new(config, transport, Options::simulated())
            .map_err(|e| e.to_string())?;
        let times = Arc::new(Mutex::new(Vec::with_capacity(WARMUP + cycles)));
        let sink = times.clone();
        let mut builder = Runtime::<Gm>::builder()
            .period(period)
            .segment(self.segment)
            .backend(backend)
            .max_cycles((WARMUP + cycles) as u64)
            .handle_signals(false)
            .cycle_probe(move |t| {
                if let Ok(mut v) = sink.lock() {
                    v.push(*t);
                }
            });
        if self.fifo {
            builder = builder.realtime_priority(place::CYCLE_PRIORITY);
        }
        let stop = builder.stop_handle();
        let (mut count, mut invalid, mut in_a_row) = (0, 0, 0);
        builder
            .build()
            .expect("the runtime's settings are valid")
            .run(|ctx| {
                count += 1;
                if count > WARMUP && !ctx.inputs_valid {
                    invalid += 1;
                }
                in_a_row = if ctx.inputs_valid { 0 } else { in_a_row + 1 };
                if in_a_row == direct::GIVE_UP {
                    stop.stop();
                }
                let info = TickInfo {
                    period,
                    inputs_valid: ctx.inputs_valid,
                    now: ctx.now(),
                };
                tick(&mut ctx.gm, info);
            })
            .map_err(|e| format!("the Runtime: {e}"))?;
        if in_a_row >= direct::GIVE_UP {
            return Err(format!(
                "the Runtime: the bus stopped answering ({} cycles in a row with invalid inputs)",
                direct::GIVE_UP
            ));
        }
        let times = times.lock().map_err(|_| "the probe panicked".to_string())?;
        Ok((times.get(WARMUP..).unwrap_or_default().to_vec(), invalid))
    }
}

/// The figure lines of one transport, or for each figure why there is none: a bus that
/// stopped answering in a block (on a machine too loaded for the simulator to answer within
/// the timeout, a late answer ends ethercrab's `tx_rx_task`; docs/benchmarks-history.md, "Bus cycle").
fn report_or_why(out: &mut String, label: &str, rates: Result<Vec<Rate>, String>, sched: &str) {
    match rates {
        Ok(rates) => report(out, label, &rates, sched),
        Err(why) => {
            for name in figure_names(label) {
                let _ = writeln!(out, "{name}: unavailable ({why})");
            }
        }
    }
}

/// The figure lines of one transport (`label` `bus` or `bus_inproc`).
fn report(out: &mut String, label: &str, rates: &[Rate], sched: &str) {
    for r in rates {
        let n = r.name;
        let _ = writeln!(
            out,
            "{label}_{n}_blocks: {BLOCKS} of {} cycles each side, alternating",
            r.cycles
        );
        for (side, blocks) in [("", &r.runtime), ("_ethercrab", &r.direct)] {
            for (what, f) in [
                ("p50", (|b: &Block| b.p50) as fn(&Block) -> f64),
                ("p99", |b| b.p99),
                ("max", |b| b.max),
            ] {
                let _ = writeln!(
                    out,
                    "{label}_{n}{side}_jitter_{what}_us: {:.1} ({sched})",
                    median(blocks, f)
                );
            }
            let overruns: usize = blocks.iter().map(|b| b.overruns).sum();
            let _ = writeln!(
                out,
                "{label}_{n}{side}_overruns: {overruns} (of {} cycles)",
                BLOCKS * r.cycles
            );
        }
        let ratio = median(&r.runtime, |b| b.p99) / median(&r.direct, |b| b.p99);
        let _ = writeln!(out, "{label}_{n}_jitter_p99_vs_ethercrab: {ratio:.2}");
        let _ = writeln!(out, "{label}_{n}_invalid_inputs: {}", r.invalid);
    }
    let all = |f: fn(&Rate) -> &Vec<Block>| -> Vec<Block> {
        rates.iter().flat_map(|r| f(r).iter().copied()).collect()
    };
    let (runtime, direct) = (all(|r| &r.runtime), all(|r| &r.direct));
    let _ = writeln!(
        out,
        "{label}_framework_us_per_cycle: {:.2}",
        median(&runtime, |b| b.own)
    );
    let _ = writeln!(
        out,
        "{label}_ethercrab_own_us_per_cycle: {:.2}",
        median(&direct, |b| b.own)
    );
    let _ = writeln!(
        out,
        "{label}_exchange_us: {:.1} (the frame's round trip, framework), {:.1} (ethercrab)",
        median(&runtime, |b| b.exchange),
        median(&direct, |b| b.exchange)
    );
}

/// The names `report` prints for `label`, for the lines that say why there is no number.
fn figure_names(label: &str) -> Vec<String> {
    let mut names = Vec::new();
    for (n, ..) in RATES {
        for side in ["", "_ethercrab"] {
            for what in ["p50", "p99", "max"] {
                names.push(format!("{label}_{n}{side}_jitter_{what}_us"));
            }
            names.push(format!("{label}_{n}{side}_overruns"));
        }
        names.push(format!("{label}_{n}_jitter_p99_vs_ethercrab"));
    }
    names.push(format!("{label}_framework_us_per_cycle"));
    names
}

#[cfg(test)]
mod tests {
    use super::*;
    use ethercat_sim::SimBus;
    use examples::tensile::position;

    /// What one loop's bus and program saw, cycle by cycle: the EL2889's and the EL2004's
    /// outputs as the simulated terminals hold them, and the limit switches the program read.
    type Seen = Vec<Cycle>;

    /// One cycle's EL2889 and EL2004 outputs and the inputs the program read.
    type Cycle = (Vec<u8>, Vec<u8>, [bool; 4]);

    /// A program that depends on its cycle count alone: every output bit from a scrambled
    /// count, and the EL1004's inputs set from it for the next exchange. Each tick records
    /// what the terminals hold (the outputs of the exchange just made) and the inputs it got.
    fn pattern(bus: SimBus, seen: &mut Seen) -> impl FnMut(&mut Gm, TickInfo) + '_ {
        let mut k = 0u32;
        move |gm, _| {
            seen.push((
                bus.outputs(position::OUTPUTS),
                bus.outputs(position::LAMPS),
                [
                    gm.ls_centering_neg,
                    gm.ls_centering_pos,
                    gm.ls_lift_neg,
                    gm.specimen_broken,
                ],
            ));
            k += 1;
            let scrambled = k.wrapping_mul(2_654_435_761);
            let bit = |n: u32| (scrambled >> (8 + n)) & 1 != 0;
            (
                gm.cr_lift_brake,
                gm.cr_centering_drive,
                gm.cr_lift_up,
                gm.cr_test_drive,
            ) = (bit(0), bit(1), bit(2), bit(3));
            (gm.lamp_green, gm.lamp_yellow, gm.lamp_red, gm.horn) =
                (bit(4), bit(5), bit(6), bit(7));
            bus.set_inputs(position::INPUTS, &[(scrambled >> 20) as u8 & 0x0f]);
        }
    }

    // What makes the bus figures a comparison of like with like: with the same program, the
    // Runtime (through the links of the example's declaration) and the direct loop (through
    // its hand-written bit moves) put the same bits on the wire in the same cycles and hand the
    // program the same inputs.
    #[test]
    fn both_loops_exchange_the_same_process_data() {
        let segment = format!("plc_bench_bus_test_{}", std::process::id());
        let plan = Plan {
            cycle_cpu: 0,
            fifo: false,
            segment: &segment,
            quick: true,
        };
        let (period, cycles) = (Duration::from_millis(1), 60);
        let (mut ours, mut theirs) = (Seen::new(), Seen::new());
        let bus = tensile::simulated_bus();
        let tick = pattern(bus.clone(), &mut ours);
        let (_, invalid) = plan
            .runtime_block(Wire::InProcess(bus), period, cycles, tick)
            .expect("the Runtime's block");
        assert_eq!(invalid, 0);
        let bus = tensile::simulated_bus();
        let tick = pattern(bus.clone(), &mut theirs);
        let timeouts = Options::simulated().timeouts;
        let (_, invalid) =
            direct::run(Wire::InProcess(bus), timeouts, period, WARMUP, cycles, tick)
                .expect("the direct loop's block");
        assert_eq!(invalid, 0);
        assert_eq!(ours.len(), WARMUP + cycles);
        assert_eq!(ours, theirs);
        // The pattern reached the terminals and came back as inputs, in many combinations.
        let distinct = |f: fn(&Cycle) -> Vec<u8>| {
            let mut v: Vec<_> = ours.iter().map(f).collect();
            v.sort();
            v.dedup();
            v.len()
        };
        assert!(distinct(|s| s.0.clone()) >= 12, "EL2889 outputs");
        assert!(distinct(|s| s.1.clone()) >= 12, "EL2004 outputs");
        assert!(
            distinct(|s| s.2.map(u8::from).to_vec()) >= 12,
            "EL1004 inputs"
        );
    }
}
