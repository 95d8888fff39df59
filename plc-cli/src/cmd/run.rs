//! `plc run MODULE`: the host. It loads a program module (checked and tried in a child first)
//! and runs the same cycle a linked program runs (`plc_io::Runtime`): the bus, shared memory,
//! retained values, forces, traces and alarms, over the module's image.
//!
//! Why in `plc` and not a binary of its own: one command to install, and `plc` is the trial
//! child already (`plc change` tries modules the same way).

use super::Error;
use plc_ethercat::{EtherCatBackend, Options, Transport};
use plc_module::trial::Trial;
use plc_module::{Module, ModuleMemory};
use plc_rules::bus::BusConfig;
use plc_runtime::Runtime;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::Duration;

/// `plc run`.
#[derive(clap::Args)]
pub struct RunArgs {
    /// The program: the `lib<name>.so` of a crate that uses `plc_io::program!`.
    pub module: PathBuf,
    /// The bus description (TOML or JSON); default: the one the program was compiled against
    /// (`#[plc(bus = ...)]`). A program without one runs with no I/O.
    #[arg(long)]
    pub bus: Option<PathBuf>,
    /// The network interface of the EtherCAT bus; default: the simulated bus made from the
    /// bus description.
    #[arg(long)]
    pub interface: Option<String>,
    /// The cycle's period in microseconds.
    #[arg(long, default_value_t = 1000)]
    pub period_us: u64,
    /// The shared-memory segment tools find the program by; default: the module's name.
    #[arg(long)]
    pub segment: Option<String>,
    /// Keep retained values in `DIR/<segment>.retain` (and the alarm journal beside it).
    #[arg(long, value_name = "DIR")]
    pub retain: Option<PathBuf>,
    /// Run the cycle on this CPU, and keep the program's other threads off it.
    #[arg(long)]
    pub cpu: Option<usize>,
    /// Run the cycle at this SCHED_FIFO priority.
    #[arg(long)]
    pub realtime_priority: Option<i32>,
    /// Stop after this many cycles (for tests and measurements).
    #[arg(long, hide = true)]
    pub cycles: Option<u64>,
}

pub fn run(args: &RunArgs) -> Result<(), Error> {
    let module = Arc::new(Module::load(&args.module, &Trial::this_program()?)?);
    let segment = args
        .segment
        .clone()
        .unwrap_or_else(|| module.name().to_string());
    let gm = ModuleMemory::initial(module.clone())?;
    let schema = plc_core::memory::Memory::schema(&gm);
    let mut builder = Runtime::for_memory(gm)
        .period(Duration::from_micros(args.period_us))
        .segment(&segment);
    let retain = args
        .retain
        .as_ref()
        .map(|dir| dir.join(format!("{segment}.retain")));
    if let Some(file) = &retain {
        builder = builder.retain(file);
    } else if let Some(v) = schema.variables.iter().find(|v| v.nonvolatile) {
        log::warn!(target: "plc_io::run",
            "plc run: `{}` and the program's other nonvolatile variables start from their \
             initial values at every start: give --retain DIR to keep them",
            v.name);
    }
    if let Some(cpu) = args.cpu {
        builder = builder.cpu(cpu);
    }
    if let Some(priority) = args.realtime_priority {
        builder = builder.realtime_priority(priority);
    }
    if let Some(n) = args.cycles {
        builder = builder.max_cycles(n);
    }
    let description = bus_description(args, &module)?;
    let has_bus = description.is_some();
    let bus = match description {
        Some((config, from)) => {
            let (transport, options, kind) = match &args.interface {
                Some(name) => (
                    Transport::Interface(name.clone()),
                    Options::default(),
                    format!("interface {name}"),
                ),
                None => {
                    let (transport, _sim) =
                        Transport::simulated(&config).map_err(|e| e.with_origin(from.clone()))?;
                    (transport, Options::simulated(), "simulated bus".into())
                }
            };
            let backend = EtherCatBackend::for_schema(config, transport, options, &schema)?;
            let links = backend.bindings().count();
            builder = builder.backend(backend);
            format!("{kind} from {from} with {links} links")
        }
        None => "no I/O (the program names no bus description)".into(),
    };
    log::info!(target: "plc_io::run",
        "plc run: `{}` ({}) as segment `{segment}`, period {} us, {bus}, retain file {}",
        module.name(),
        module.path().display(),
        args.period_us,
        retain.as_ref().map_or("none".into(), |f| f.display().to_string()),
    );
    let (swaps, changes) = std::sync::mpsc::channel();
    builder = builder.swaps(changes);
    let runtime = builder.build()?;
    let _changes = super::change_server::serve(
        &segment,
        &module,
        swaps,
        Duration::from_micros(args.period_us),
        has_bus,
    )?;
    runtime.run(plc_module::tick)?;
    Ok(())
}

/// The bus description `--bus` names, or the one compiled into the module, with where it
/// came from.
fn bus_description(args: &RunArgs, module: &Module) -> Result<Option<(BusConfig, String)>, Error> {
    if let Some(path) = &args.bus {
        let config = BusConfig::load(path).map_err(|e| format!("{}: {e}", path.display()))?;
        return Ok(Some((config, path.display().to_string())));
    }
    let Some((file, text)) = module.bus() else {
        return Ok(None);
    };
    let from = format!("`{file}` as the program was compiled with it");
    let config = if Path::new(file)
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("json"))
    {
        BusConfig::from_json_str(text)
    } else {
        BusConfig::from_toml_str(text)
    }
    .map_err(|e| format!("the bus description {from}: {e}"))?;
    Ok(Some((config, from)))
}
