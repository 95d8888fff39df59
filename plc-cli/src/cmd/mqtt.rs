//! `plc mqtt serve SEGMENT...`: a Sparkplug B edge node (plc-sparkplug) publishing running
//! programs to an MQTT broker until Ctrl-C.

use super::Error;
use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::AtomicBool;

/// `plc mqtt ...`.
#[derive(clap::Subcommand)]
pub enum MqttCommand {
    /// Publishes running programs to an MQTT broker as a Sparkplug B edge node until Ctrl-C:
    /// each program a device named by its segment, every value a metric named by its path,
    /// sent when it changes (docs/sparkplug.md).
    Serve {
        /// Segment names of running programs.
        #[arg(required = true)]
        segments: Vec<String>,
        /// The broker, mqtt://HOST:PORT, or mqtts://HOST:PORT for TLS (with --ca).
        #[arg(long)]
        broker: String,
        /// The Sparkplug group id.
        #[arg(long)]
        group: String,
        /// The edge node id.
        #[arg(long)]
        node: String,
        /// The primary host application's id: births wait until its STATE says online.
        #[arg(long)]
        primary_host: Option<String>,
        /// Let device commands (DCMD) write, through the programs' own write checks.
        #[arg(long)]
        commands: bool,
        /// Send a number only when it moved by more than this since it was last sent (0:
        /// every change).
        #[arg(long, default_value_t = 0.0)]
        deadband: f64,
        /// At most this many values per second of one metric.
        #[arg(long)]
        max_rate: Option<f64>,
        /// The store directory (bdSeq, and data that changed while no birth was out); default
        /// under $XDG_STATE_HOME or ~/.local/state.
        #[arg(long)]
        store: Option<PathBuf>,
        /// The bound of the data kept in the store, in bytes (default 64 MiB); when full the
        /// oldest half is dropped and counted.
        #[arg(long)]
        store_max: Option<u64>,
        /// MQTT user name.
        #[arg(long)]
        user: Option<String>,
        /// A file whose first line is the MQTT password (never on the command line).
        #[arg(long)]
        password_file: Option<PathBuf>,
        /// The CA certificate (PEM) that signed an mqtts:// broker's certificate.
        #[arg(long)]
        ca: Option<PathBuf>,
        /// A client certificate (PEM) for a broker that asks for one (with --key).
        #[arg(long)]
        cert: Option<PathBuf>,
        /// The client certificate's private key (PEM).
        #[arg(long)]
        key: Option<PathBuf>,
    },
}

pub fn run(command: MqttCommand) -> Result<(), Error> {
    let MqttCommand::Serve {
        segments,
        broker,
        group,
        node,
        primary_host,
        commands,
        deadband,
        max_rate,
        store,
        store_max,
        user,
        password_file,
        ca,
        cert,
        key,
    } = command;
    let options = plc_sparkplug::ServeOptions {
        segments,
        broker,
        group,
        node,
        primary_host,
        commands,
        deadband,
        max_rate,
        store,
        store_max,
        user,
        password_file,
        ca,
        cert,
        key,
    };
    let stop = Arc::new(AtomicBool::new(false));
    plc_shm::stop_on_signals(&stop).map_err(|e| format!("cannot take SIGINT and SIGTERM: {e}"))?;
    plc_sparkplug::serve(&options, &stop)?;
    Ok(())
}
