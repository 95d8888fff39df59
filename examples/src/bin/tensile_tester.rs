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
//! (directory of the retain file, default `plc-vars/tensile_tester` in the user's state
//! directory, `/var/lib` for root; created private, and refused if others may write it),
//! `--cpu N` (run the cycle and the bus on CPU N, the runtime's other threads elsewhere),
//! `--realtime-priority P` (SCHED_FIFO at P, 1 to 99: root or CAP_SYS_NICE).
//!
//! Without `--interface` the bus is simulated, made from the bus description alone (the
//! built-in one: EK1100, EL1004, EL2889, EL2004 and an AKD servo drive moving the test
//! crosshead), and a model of the machine runs on a thread: it reads the drive outputs and the
//! crosshead's position and sets the limit switches and the break detector by their link
//! names, so the program runs one test after another. A status line is printed each second: the machine's state,
//! the crosshead's position and PLCopen state, the force, and the signal tower's lamps.

use examples::tensile;

use plc_io::Runtime;
use plc_io::ethercat::sim::SimBus;
use plc_io::ethercat::{BusConfig, EtherCatBackend, Options, Transport};
use plc_io::shm::DynSegment;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Duration;
use tensile::{Gm, TickInfo, process_tick};

struct Args {
    bus: Option<PathBuf>,
    interface: Option<String>,
    period: Duration,
    cycles: Option<u64>,
    segment: String,
    retain: Option<PathBuf>,
    cpu: Option<usize>,
    realtime_priority: Option<i32>,
}

const USAGE: &str = "usage: tensile_tester [--bus FILE] [--interface NAME] [--period-us N] \
                     [--cycles N] [--segment NAME] [--retain DIR] [--cpu N] \
                     [--realtime-priority P]";

fn parse_args() -> Result<Args, String> {
    let mut args = Args {
        bus: None,
        interface: None,
        period: Duration::from_millis(1),
        cycles: None,
        segment: "tensile_tester".into(),
        retain: None,
        cpu: None,
        realtime_priority: None,
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
            "--cpu" => args.cpu = Some(number(value()?)? as usize),
            "--realtime-priority" => match number(value()?)? {
                p @ 1..=99 => args.realtime_priority = Some(p as i32),
                p => return Err(format!("--realtime-priority: {p} is not within 1 to 99")),
            },
            other => return Err(format!("unknown option `{other}`\n{USAGE}")),
        }
    }
    Ok(args)
}

/// The retain directory when none is given: the user's own state directory (never the shared
/// temporary directory, where another user could create it first).
fn default_retain_dir() -> PathBuf {
    // SAFETY: geteuid has no preconditions and cannot fail.
    let base = if unsafe { libc::geteuid() } == 0 {
        PathBuf::from("/var/lib")
    } else if let Some(state) = std::env::var_os("XDG_STATE_HOME").filter(|s| !s.is_empty()) {
        PathBuf::from(state)
    } else if let Some(home) = std::env::var_os("HOME").filter(|s| !s.is_empty()) {
        PathBuf::from(home).join(".local/state")
    } else {
        PathBuf::from(".")
    };
    base.join("plc-vars/tensile_tester")
}

fn main() -> ExitCode {
    init_logging();
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("tensile_tester: {e}");
            ExitCode::FAILURE
        }
    }
}

/// The runtime's messages (retained values, EtherCAT problems) on stderr as plain lines, from
/// level info on. `RUST_LOG` chooses others: `RUST_LOG=plc_io=warn` for fewer,
/// `RUST_LOG=info` to add ethercrab's own.
fn init_logging() {
    use std::io::Write;
    env_logger::Builder::from_env(env_logger::Env::default().default_filter_or("plc_io=info"))
        .format(|out, record| writeln!(out, "{}", record.args()))
        .init();
}

fn run() -> Result<(), Box<dyn std::error::Error>> {
    let args = parse_args()?;
    let config = match &args.bus {
        Some(path) => BusConfig::load(path)?,
        None => BusConfig::from_toml_str(tensile::BUS_TOML)?,
    };
    let (transport, tower, options) = match &args.interface {
        Some(name) => (Transport::Interface(name.clone()), None, Options::default()),
        None => {
            let (transport, sim) = Transport::simulated(&config).map_err(|e| match &args.bus {
                Some(path) => e.with_origin(path.display().to_string()),
                None => e.with_origin("the built-in bus description"),
            })?;
            (transport, Some(sim), Options::simulated())
        }
    };
    let backend = EtherCatBackend::<Gm>::new(config, transport, options)?;
    // The machine's model, once the program's links are known to be good on this bus.
    let _plant = match &tower {
        Some(sim) => Some(tensile::plant::Plant::spawn(sim.clone())?),
        None => None,
    };
    let links = backend.bindings().count();
    let retain_dir = args.retain.clone().unwrap_or_else(default_retain_dir);
    let retain = retain_dir.join("tensile_tester.retain");
    println!(
        "tensile_tester: {} with {links} links, period {} us; segment `{}` (try `plc watch {}`), \
         retain file {}; Ctrl-C stops",
        args.interface.as_deref().unwrap_or("simulated bus"),
        args.period.as_micros(),
        args.segment,
        args.segment,
        retain.display(),
    );
    let mut builder = Runtime::<Gm>::builder()
        .period(args.period)
        .segment(&args.segment)
        .retain(&retain)
        .backend(backend);
    if let Some(n) = args.cycles {
        builder = builder.max_cycles(n);
    }
    if let Some(cpu) = args.cpu {
        builder = builder.cpu(cpu);
    }
    if let Some(priority) = args.realtime_priority {
        builder = builder.realtime_priority(priority);
    }
    let stop = builder.stop_handle();
    let monitor = status_line(args.segment.clone(), tower, stop.clone());
    let period = args.period;
    let result = builder.build().and_then(|runtime| {
        runtime.run(|ctx| {
            let info = TickInfo {
                period,
                inputs_valid: ctx.inputs_valid,
                now: ctx.now(),
            };
            process_tick(&mut ctx.gm, info);
        })
    });
    stop.stop();
    let _ = monitor.join();
    let gm = result?;
    println!(
        "tensile_tester: stopped, {} tests completed; bus back in INIT, retained values saved",
        gm.tests_completed
    );
    Ok(())
}

/// What the simulated signal tower (the EL2004's four outputs) shows: `G y r h`, a capital
/// for a lamp that is on, read from the terminal itself by the program's link names, as a
/// look at the machine would (`plc force tensile_tester lamp_red=true` lights `R` whatever
/// the program writes).
fn tower_text(bus: &SimBus) -> String {
    ["green", "yellow", "red", "horn"]
        .iter()
        .map(|lamp| {
            let letter = &lamp[..1];
            match bus.output::<bool>(&format!("ethercat.lamps.{lamp}")) {
                Ok(true) => letter.to_uppercase(),
                Ok(false) => letter.to_string(),
                Err(_) => "?".into(),
            }
        })
        .collect::<Vec<_>>()
        .join(" ")
}

/// Prints a status line each second, read from the program's own segment as any HMI would,
/// with the simulated tower's lamps as the terminal shows them.
fn status_line(
    segment: String,
    tower: Option<SimBus>,
    stop: plc_io::StopHandle,
) -> std::thread::JoinHandle<()> {
    std::thread::spawn(move || {
        let mut seg = None;
        while !stop.is_stopped() {
            std::thread::sleep(Duration::from_secs(1));
            if seg.is_none() {
                seg = DynSegment::attach(&segment).ok();
            }
            let Some(s) = &seg else { continue };
            let st = s.status();
            let Ok(image) = s.snapshot_bytes() else { break };
            let read = |n: &str| {
                let i = s.descriptor().index_of(n);
                match i.and_then(|i| s.descriptor().variables[i].value_in(&image, 0)) {
                    Some(plc_core::Value::Real(r)) => format!("{r:.1}"),
                    Some(v) => v.to_string(),
                    None => "?".into(),
                }
            };
            let member = |path: &str| {
                s.locate(path)
                    .ok()
                    .and_then(|at| at.var.value_in(&image, 0))
            };
            let position = match member("crosshead.actual_position") {
                Some(plc_core::Value::Real(mm)) => format!("{mm:.2} mm"),
                _ => "?".into(),
            };
            let axis_state = match member("crosshead.state") {
                Some(plc_core::Value::UInt(n)) => {
                    u8::try_from(n).map_or("?", tensile::crosshead::state_name)
                }
                _ => "?",
            };
            let fault = match read("fault_text") {
                t if t.is_empty() || t == "?" => String::new(),
                t => format!(" ({t})"),
            };
            let lamps = tower
                .as_ref()
                .map(|t| format!(" | tower {}", tower_text(t)))
                .unwrap_or_default();
            let forced = match st.forces {
                0 => String::new(),
                n => format!(" | {n} forced"),
            };
            println!(
                "cycle {:>7} | work last/mean/max {}/{}/{} us | overruns {} | bus {}{} | {} {}{fault} \
                 | crosshead {position} {axis_state} | force {} kN | tests {}{lamps}{forced}",
                st.cycle_count,
                st.stats.last.as_micros(),
                st.stats.mean.as_micros(),
                st.stats.max.as_micros(),
                st.stats.overruns,
                st.bus_state,
                if st.inputs_valid {
                    ""
                } else {
                    " INPUTS INVALID"
                },
                read("info_test_id"),
                read("machine_state_name"),
                read("force_kn"),
                read("tests_completed"),
            );
        }
    })
}
