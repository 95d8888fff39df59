//! A Sparkplug B 3.0 edge node for the variables of running plc-vars programs: each program's
//! shared-memory segment is a device, every basic value a metric named by its path, sent to an
//! MQTT broker by exception. What it publishes and takes is described in `docs/sparkplug.md`.
//!
//! ```no_run
//! let options = plc_sparkplug::ServeOptions {
//!     segments: vec!["tensile_tester".into()],
//!     broker: "mqtt://127.0.0.1:1883".into(),
//!     group: "plant".into(),
//!     node: "line1".into(),
//!     ..plc_sparkplug::ServeOptions::default()
//! };
//! let stop = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
//! plc_sparkplug::serve(&options, &stop)?;
//! # Ok::<(), String>(())
//! ```
#![deny(missing_docs)]

pub mod alarm_counts;
pub mod alarm_states;
pub mod device;
pub mod forward;
pub mod metric;
pub mod node;
pub mod proto;
pub mod session;
pub mod store;
pub mod tls;
pub mod topic;

use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::AtomicBool;

/// What `plc mqtt serve` was asked for.
#[derive(Clone, Debug, Default)]
pub struct ServeOptions {
    /// The segments to publish, each a device named by the segment's name.
    pub segments: Vec<String>,
    /// `mqtt://HOST[:PORT]` (port 1883 by default).
    pub broker: String,
    /// The Sparkplug group id.
    pub group: String,
    /// The edge node id.
    pub node: String,
    /// The primary host's id: no birth before its STATE says it is online.
    pub primary_host: Option<String>,
    /// Whether device commands (DCMD) may write.
    pub commands: bool,
    /// The default deadband of numbers (0: every change).
    pub deadband: f64,
    /// At most this many values per second per metric.
    pub max_rate: Option<f64>,
    /// The store directory (bdSeq, data waiting for a birth); `None` for the user's state
    /// directory.
    pub store: Option<PathBuf>,
    /// The bound of the data waiting in the store, in bytes; `None` for
    /// [`forward::DEFAULT_MAX`].
    pub store_max: Option<u64>,
    /// The MQTT user name.
    pub user: Option<String>,
    /// The file whose first line is the MQTT password.
    pub password_file: Option<PathBuf>,
    /// The CA certificate (PEM) of an `mqtts://` broker.
    pub ca: Option<PathBuf>,
    /// The client certificate (PEM) for an `mqtts://` broker that asks for one.
    pub cert: Option<PathBuf>,
    /// The client certificate's private key (PEM).
    pub key: Option<PathBuf>,
}

/// Runs the edge node until `stop` is set (then it publishes its death and disconnects).
/// Errors are about the options or the store; a broker away is waited for, a program away
/// is a dead device until it comes back.
pub fn serve(options: &ServeOptions, stop: &Arc<AtomicBool>) -> Result<(), String> {
    let broker = check(options)?;
    let dir = options
        .store
        .clone()
        .unwrap_or_else(|| store::default_dir(&options.group, &options.node));
    let store = store::Store::open(&dir)?;
    log::info!(target: "plc_sparkplug",
        "edge node {}/{}: {} device(s), store {}", options.group, options.node,
        options.segments.len(), dir.display());
    let forward = forward::Forward::open(&dir, options.store_max.unwrap_or(forward::DEFAULT_MAX));
    node::Node::new(options.clone(), broker, store, forward).run(stop)
}

/// Checks the options: ids, broker address, deadband, rate, password file.
fn check(o: &ServeOptions) -> Result<session::Broker, String> {
    topic::check_id("group (--group)", &o.group)?;
    topic::check_id("node (--node)", &o.node)?;
    if let Some(h) = &o.primary_host {
        topic::check_id("primary host (--primary-host)", h)?;
    }
    if o.segments.is_empty() {
        return Err("name at least one segment to publish (`plc list` shows them)".into());
    }
    for (i, s) in o.segments.iter().enumerate() {
        topic::check_id("segment", s)?;
        if o.segments[..i].contains(s) {
            return Err(format!("segment `{s}` is named twice: name each once"));
        }
    }
    if !(o.deadband >= 0.0 && o.deadband.is_finite()) {
        return Err(format!(
            "--deadband must be a number 0 or above, not {}",
            o.deadband
        ));
    }
    if let Some(r) = o.max_rate
        && !(r > 0.0 && r <= 1000.0)
    {
        return Err(format!(
            "--max-rate must be above 0 and at most 1000 values per second, not {r}"
        ));
    }
    if let Some(m) = o.store_max
        && m < forward::MIN_MAX
    {
        return Err(format!(
            "--store-max {m} is too small: give at least {} bytes",
            forward::MIN_MAX
        ));
    }
    let (host, port, secure) = parse_broker(&o.broker)?;
    let tls = if secure {
        Some(tls::client_config(&tls::TlsFiles {
            ca: o.ca.as_deref(),
            cert: o.cert.as_deref(),
            key: o.key.as_deref(),
        })?)
    } else if o.ca.is_some() || o.cert.is_some() || o.key.is_some() {
        return Err(format!(
            "--ca, --cert and --key are for TLS: give the broker as mqtts://, not {}",
            o.broker
        ));
    } else {
        None
    };
    let login = match (&o.user, &o.password_file) {
        (Some(u), Some(f)) => Some((u.clone(), read_password(f)?)),
        (Some(u), None) => Some((u.clone(), String::new())),
        (None, Some(_)) => return Err("--password-file needs --user".into()),
        (None, None) => None,
    };
    Ok(session::Broker {
        host,
        port,
        client_id: format!("plc-sparkplug-{}-{}", o.group, o.node),
        login,
        tls,
    })
}

/// `mqtt://HOST[:PORT]` (port 1883 by default) or `mqtts://HOST[:PORT]` (TLS, port 8883) as
/// host, port and whether it is TLS.
///
/// ```
/// use plc_sparkplug::parse_broker;
/// assert_eq!(parse_broker("mqtt://10.0.0.5:1884"), Ok(("10.0.0.5".into(), 1884, false)));
/// assert_eq!(parse_broker("mqtt://broker"), Ok(("broker".into(), 1883, false)));
/// assert_eq!(parse_broker("mqtts://broker"), Ok(("broker".into(), 8883, true)));
/// assert_eq!(parse_broker("mqtt://[::1]:1884"), Ok(("::1".into(), 1884, false)));
/// assert!(parse_broker("tcp://broker").unwrap_err().contains("mqtt://HOST:PORT"));
/// ```
pub fn parse_broker(url: &str) -> Result<(String, u16, bool), String> {
    let (rest, secure, default_port) = if let Some(r) = url.strip_prefix("mqtts://") {
        (r, true, 8883)
    } else if let Some(r) = url.strip_prefix("mqtt://") {
        (r, false, 1883)
    } else {
        return Err(format!(
            "--broker {url}: give the broker as mqtt://HOST:PORT, or mqtts://HOST:PORT for TLS \
             (e.g. mqtt://127.0.0.1:1883)"
        ));
    };
    let rest = rest.trim_end_matches('/');
    let (host, port) = match rest.rsplit_once(':') {
        // An IPv6 address is bracketed: [::1]:1883.
        Some((h, p)) if !p.contains(']') && (!h.contains(':') || h.ends_with(']')) => {
            let port = p.parse::<u16>().ok().filter(|&p| p > 0).ok_or_else(|| {
                format!("--broker {url}: the port `{p}` is not a number 1..65535")
            })?;
            (h, port)
        }
        _ => (rest, default_port),
    };
    let host = host.trim_start_matches('[').trim_end_matches(']');
    if host.is_empty() || host.contains(['/', '?', '@']) {
        return Err(format!(
            "--broker {url}: give the broker as mqtt://HOST:PORT (user and password go in \
             --user and --password-file)"
        ));
    }
    Ok((host.to_string(), port, secure))
}

/// The password: the file's first line (never the command line, which others can see).
fn read_password(path: &std::path::Path) -> Result<String, String> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read the password file {}: {e}", path.display()))?;
    let line = text.lines().next().unwrap_or("");
    if line.is_empty() {
        return Err(format!(
            "the password file {} is empty: put the password on its first line",
            path.display()
        ));
    }
    Ok(line.to_string())
}
