//! `plc`: the variables of running plc-vars programs, from the command line.
//!
//! ```sh
//! plc list                          # running programs
//! plc list tensile_tester           # their variables (--json for scripts)
//! plc get tensile_tester force_kn info_test_id
//! plc get tensile_tester force_kn --digits 4 --hex   # reals to 4 digits, integers as 16#00FF
//! plc set tensile_tester info_specimen_name="S235 bar" auto_start=false
//! plc watch tensile_tester --filter ls_
//! plc log tensile_tester force_kn elongation_mm --csv run.csv --rate 100
//! plc export tensile_tester > project.json
//! plc export tensile_tester --csv > variables.csv
//! plc import project.json -o src/gm.rs --struct Gm
//! plc import --csv variables.csv -o src/gm.rs
//! plc bus show bus/machine.toml     # the process image of a bus description
//! plc bus scan --interface eth0 --out bus/machine.toml   # a description from the devices
//! plc bus scan --sim EK1100,EL1004,EL2889                # the same on the simulated bus
//! plc alarms tensile_tester          # alarms active or unacknowledged (--history: the journal)
//! plc ack tensile_tester guard_door_open --comment "door closed"
//! plc shelve tensile_tester specimen_not_centred --for 1h
//! plc opcua serve tensile_tester --users users.txt   # an OPC UA server on port 4840
//! plc opcua user add users.txt operator              # password from standard input
//! plc new conveyor                  # a program module crate to start from
//! plc run target/release/libtensile_tester.so   # a program module, on the simulated bus
//! plc change tensile_tester target/release/libtensile_tester.so --dry-run   # what a change would do
//! plc mqtt serve tensile_tester --broker mqtt://127.0.0.1:1883 --group plant --node line1
//! ```

mod cmd;
mod display;
mod trace;

use clap::{Parser, Subcommand};
use plc_shm::protocol::AlarmAction;
use std::path::PathBuf;
use std::process::ExitCode;

/// Inspect and control running plc-vars programs through their shared-memory segments, and
/// import JSON or CSV variable lists.
#[derive(Parser)]
#[command(name = "plc", version)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Running programs, or the variables of one program; a program on a bus with distributed
    /// clocks also shows them (SYNC0 period, largest clock difference, the cycle's offset to
    /// SYNC0).
    List {
        /// Segment name (as the program gave it, or the path of its socket).
        segment: Option<String>,
        /// Machine-readable output: the running programs (with `dc`), or the layout
        /// descriptor as JSON.
        #[arg(long)]
        json: bool,
    },
    /// Current values; reals at full precision unless --digits.
    Get {
        /// Segment name.
        segment: String,
        /// Variable names (case-insensitive); `name[3]` for one array element. None: every
        /// variable.
        names: Vec<String>,
        #[command(flatten)]
        format: display::FormatArgs,
    },
    /// Writes values: all are checked first, then sent as one request the program applies in one cycle, all or none.
    Set {
        /// Segment name.
        segment: String,
        /// `name=value`: bools true/false/1/0, numbers, strings plain or in double quotes.
        #[arg(required = true)]
        assignments: Vec<String>,
    },
    /// A live, full-screen view of the variables; select one and press Enter to write it.
    /// Reals show 6 significant digits (or --digits); `p` toggles full precision.
    Watch {
        /// Segment name.
        segment: String,
        /// Show only variables whose name contains this text (case-insensitive).
        #[arg(long)]
        filter: Option<String>,
        /// Refreshes per second.
        #[arg(long, default_value_t = 10.0)]
        rate: f64,
        #[command(flatten)]
        format: display::FormatArgs,
    },
    /// Holds values at both of the program's cycle boundaries until released: the program
    /// reads a forced input, the bus gets a forced output whatever the program writes. Any
    /// basic value or element; writes to a forced value are refused.
    Force {
        /// Segment name.
        segment: String,
        /// `path=value`, as `plc set` takes them (inputs, outputs and status too).
        #[arg(required = true)]
        assignments: Vec<String>,
    },
    /// Releases forces: the program's next value stands (or, with --restore, the value from
    /// before the force comes back).
    Unforce {
        /// Segment name.
        segment: String,
        /// The forced values to release.
        #[arg(required_unless_present = "all", conflicts_with = "all")]
        paths: Vec<String>,
        /// Release every force.
        #[arg(long)]
        all: bool,
        /// Put back each value as it was before its force.
        #[arg(long)]
        restore: bool,
    },
    /// The forces held: path, value, who forced it and since when.
    Forces {
        /// Segment name.
        segment: String,
        #[command(flatten)]
        format: display::FormatArgs,
    },
    /// A program's alarms: those active or waiting for an acknowledgement, most severe first
    /// (path, state, since when, text); --all every one; --history the journal.
    Alarms(cmd::alarms::AlarmsArgs),
    /// An online change: what a new build of the program (a module, `lib<name>.so`) would do
    /// to each value of the running one (`--dry-run`): kept, converted, added, reset, removed.
    Change(cmd::change::ChangeArgs),
    /// Runs a program module (`lib<name>.so` of a crate that uses `plc_io::program!`): the
    /// cycle, its bus (simulated unless --interface), shared memory and retained values.
    Run(cmd::run::RunArgs),
    /// Writes a new program module crate: `cargo build --release` in it, then `plc run
    /// target/release/lib<NAME>.so` runs it on the simulated bus.
    New(cmd::new::NewArgs),
    /// Acknowledges alarms, as this user (who may is the write policy's, as for `plc set`).
    Ack(cmd::alarm_actions::ActArgs),
    /// Resets latched alarms whose condition has cleared (a reset acknowledges too).
    Reset(cmd::alarm_actions::ActArgs),
    /// Shelves alarms for a while: not shown, back by themselves when the shelf expires.
    Shelve(cmd::alarm_actions::ShelveArgs),
    /// Takes alarms off their shelf.
    Unshelve(cmd::alarm_actions::ActArgs),
    /// Records values every cycle (or every Nth), as the program runs them, to a CSV file
    /// and optionally an SVG plot; with a trigger, --pre rows before it and --post after.
    Trace(cmd::trace::Options),
    /// Records values to a CSV file.
    Log {
        /// Segment name.
        segment: String,
        /// Variable names.
        #[arg(required = true)]
        names: Vec<String>,
        /// The CSV file to write.
        #[arg(long)]
        csv: PathBuf,
        /// Samples per second.
        #[arg(long, default_value_t = 10.0)]
        rate: f64,
        /// Stop after this many seconds (default: until Ctrl-C or the program stops).
        #[arg(long)]
        seconds: Option<f64>,
    },
    /// A JSON variable list, or a CSV one, to the equivalent Rust struct.
    Import {
        /// The JSON file (a whole project file works: only its "variables" are read), or the
        /// CSV file with --csv (a name ending in .csv is read as CSV anyway).
        project: PathBuf,
        /// Read a CSV table: one row per variable under a header line naming the columns,
        /// RFC 4180 quoting. Columns, in any order:
        /// name,type,direction,link,description,initial,source,bit,max_length,nonvolatile,read_only,at,dims,ux,quantity,unit,deadband
        #[arg(long)]
        csv: bool,
        /// Write the module here instead of standard output.
        #[arg(short, long)]
        output: Option<PathBuf>,
        /// Name of the generated struct.
        #[arg(long = "struct", default_value = "Gm")]
        struct_name: String,
    },
    /// The declaration of a running program as a JSON variable list, or CSV.
    Export {
        /// Segment name.
        segment: String,
        /// Write a CSV table instead (the columns `plc import --csv` reads).
        #[arg(long)]
        csv: bool,
    },
    /// Bus descriptions.
    Bus {
        #[command(subcommand)]
        command: BusCommand,
    },
    /// The OPC UA server for running programs, and its users.
    Opcua {
        #[command(subcommand)]
        command: OpcuaCommand,
    },
    /// A Sparkplug B edge node publishing running programs to an MQTT broker.
    Mqtt {
        #[command(subcommand)]
        command: cmd::mqtt::MqttCommand,
    },
}

#[derive(Subcommand)]
enum OpcuaCommand {
    /// Serves running programs' variables over OPC UA until Ctrl-C: a namespace
    /// `urn:plc-vars:<segment>` per segment; anonymous sessions browse and read, users of
    /// --users also write.
    Serve {
        /// Segment names of running programs.
        #[arg(required = true)]
        segments: Vec<String>,
        /// TCP port.
        #[arg(long, default_value_t = 4840)]
        port: u16,
        /// Address to listen on and to announce in the endpoints.
        #[arg(long, default_value = "0.0.0.0")]
        host: String,
        /// The users who may write (`plc opcua user add`); without it nobody writes.
        #[arg(long)]
        users: Option<PathBuf>,
        /// Certificate store: the server's self-signed certificate is made here on first start;
        /// client certificates go in its trusted/ directory.
        #[arg(long, default_value = "pki")]
        pki: PathBuf,
        #[command(flatten)]
        limits: OpcuaLimits,
    },
    /// Users of the OPC UA server.
    User {
        #[command(subcommand)]
        command: OpcuaUserCommand,
    },
}

/// What OPC UA clients may hold (defaults serve a plant of 10,000 variables).
#[derive(clap::Args)]
struct OpcuaLimits {
    /// Let users sign in and write over None (unsigned) too: on a closed network only, as
    /// anyone on the path can read and change those writes.
    #[arg(long)]
    allow_unsigned_writes: bool,
    /// Sessions in all.
    #[arg(long, default_value_t = plc_opcua::ServeLimits::default().sessions)]
    max_sessions: usize,
    /// Sessions from one client address.
    #[arg(long, default_value_t = plc_opcua::ServeLimits::default().sessions_per_address)]
    max_sessions_per_address: usize,
    /// Connections in all.
    #[arg(long, default_value_t = plc_opcua::ServeLimits::default().connections)]
    max_connections: usize,
    /// Connections from one client address.
    #[arg(long, default_value_t = plc_opcua::ServeLimits::default().connections_per_address)]
    max_connections_per_address: usize,
    /// Monitored items in one subscription (a session holds at most 4 subscriptions).
    #[arg(long, default_value_t = plc_opcua::ServeLimits::default().monitored_items)]
    max_monitored_items: usize,
    /// Nodes in one Read, Write, Browse or CreateMonitoredItems.
    #[arg(long, default_value_t = plc_opcua::ServeLimits::default().nodes_per_call)]
    max_nodes_per_call: usize,
    /// Refused client certificates kept in the pki's rejected/ directory (the newest).
    #[arg(long, default_value_t = plc_opcua::ServeLimits::default().rejected_certificates)]
    max_rejected: usize,
}

impl From<OpcuaLimits> for plc_opcua::ServeLimits {
    fn from(l: OpcuaLimits) -> Self {
        plc_opcua::ServeLimits {
            allow_unsigned_writes: l.allow_unsigned_writes,
            sessions: l.max_sessions,
            sessions_per_address: l.max_sessions_per_address,
            connections: l.max_connections,
            connections_per_address: l.max_connections_per_address,
            monitored_items: l.max_monitored_items,
            nodes_per_call: l.max_nodes_per_call,
            rejected_certificates: l.max_rejected,
        }
    }
}

#[derive(Subcommand)]
enum OpcuaUserCommand {
    /// Adds a user (or sets a new password): the password is read from standard input and
    /// stored as a salted argon2 hash, never as itself.
    Add {
        /// The users file (created, mode 0600, if missing).
        file: PathBuf,
        /// User name: letters, digits, `_`, `-`, `.`, `@`.
        name: String,
    },
}

#[derive(Subcommand)]
enum BusCommand {
    /// The resolved process image of a bus description: each device's PDO entries with
    /// direction, byte and bit, width and type, to check against the wiring.
    Show {
        /// The bus description (TOML, or JSON if the name ends in .json).
        file: PathBuf,
    },
    /// A bus description read from the SubDevices themselves (identity, EEPROM, CoE PDO
    /// mapping), printed as TOML or written to --out. The SubDevices go to PRE-OP and back to
    /// INIT; nothing is switched to OP.
    Scan {
        /// The network interface of the bus (needs root or CAP_NET_RAW).
        #[arg(long, required_unless_present = "sim", conflicts_with = "sim")]
        interface: Option<String>,
        /// Scan a simulated bus of these terminals instead, in ring order
        /// (EK1100, EL1004, EL2004, EL2828, EL2889, EL3004).
        #[arg(long, value_delimiter = ',')]
        sim: Vec<String>,
        /// Write the description to this file (replaced if it exists) instead of stdout.
        #[arg(long)]
        out: Option<PathBuf>,
    },
}

fn main() -> ExitCode {
    // `plc` is also the short-lived child that tries a program module before it is trusted
    // (`plc change`): that child does only this and exits.
    plc_module::trial::serve_if_asked();
    // Die quietly on a closed pipe (`plc list x | head`), as command-line tools do.
    // SAFETY: setting a signal disposition to the default before any thread starts.
    unsafe { libc::signal(libc::SIGPIPE, libc::SIG_DFL) };
    // Whatever plc-io logs while a command runs, as plain lines on stderr; `RUST_LOG`
    // chooses other levels and crates.
    env_logger::Builder::from_env(
        env_logger::Env::default()
            .default_filter_or("plc_io=info,plc_opcua=info,plc_sparkplug=info"),
    )
    .format(|out, record| {
        use std::io::Write;
        writeln!(out, "{}", record.args())
    })
    .init();
    let cli = Cli::parse();
    let result = match cli.command {
        Command::List { segment, json } => cmd::list::run(segment.as_deref(), json),
        Command::Get {
            segment,
            names,
            format,
        } => cmd::get::run(&segment, &names, &format.format()),
        Command::Set {
            segment,
            assignments,
        } => cmd::set::run(&segment, &assignments),
        Command::Watch {
            segment,
            filter,
            rate,
            format,
        } => cmd::watch::run(&segment, filter, rate, format.format()),
        Command::Log {
            segment,
            names,
            csv,
            rate,
            seconds,
        } => cmd::log::run(&segment, &names, &csv, rate, seconds),
        Command::Force {
            segment,
            assignments,
        } => cmd::force::force(&segment, &assignments),
        Command::Unforce {
            segment,
            paths,
            all,
            restore,
        } => cmd::force::unforce(&segment, &paths, all, restore),
        Command::Forces { segment, format } => cmd::force::list(&segment, &format.format()),
        Command::Trace(options) => cmd::trace::run(&options),
        Command::Alarms(args) => cmd::alarms::run(&args),
        Command::Change(args) => cmd::change::run(&args),
        Command::Run(args) => cmd::run::run(&args),
        Command::New(args) => cmd::new::run(&args),
        Command::Ack(args) => cmd::alarm_actions::run(AlarmAction::Acknowledge, &args),
        Command::Reset(args) => cmd::alarm_actions::run(AlarmAction::Reset, &args),
        Command::Shelve(args) => cmd::alarm_actions::shelve(&args),
        Command::Unshelve(args) => cmd::alarm_actions::run(AlarmAction::Unshelve, &args),
        Command::Import {
            project,
            csv,
            output,
            struct_name,
        } => cmd::import::run(&project, csv, output.as_deref(), &struct_name),
        Command::Export { segment, csv } => cmd::export::run(&segment, csv),
        Command::Bus {
            command: BusCommand::Show { file },
        } => cmd::bus::show(&file),
        Command::Bus {
            command:
                BusCommand::Scan {
                    interface,
                    sim,
                    out,
                },
        } => cmd::bus::scan(interface, &sim, out.as_deref()),
        Command::Opcua {
            command:
                OpcuaCommand::Serve {
                    segments,
                    port,
                    host,
                    users,
                    pki,
                    limits,
                },
        } => cmd::opcua::serve(&plc_opcua::ServeOptions {
            segments,
            host,
            port,
            users,
            pki,
            limits: limits.into(),
        }),
        Command::Opcua {
            command:
                OpcuaCommand::User {
                    command: OpcuaUserCommand::Add { file, name },
                },
        } => cmd::opcua::add_user(&file, &name),
        Command::Mqtt { command } => cmd::mqtt::run(command),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("plc: {e}");
            ExitCode::FAILURE
        }
    }
}
