//! `plc opcua serve`: the server's configuration (endpoints, certificate, limits), one node
//! manager and two threads per segment, and the run until Ctrl-C or SIGTERM.

use crate::alarms::methods::AlarmMethods;
use crate::alarms::poller::AlarmPoller;
use crate::alarms::{AckJob, AlarmSpace, Registry};
use crate::auth::{PlcAuth, RefusePlainTextPasswords};
use crate::gate::{Gate, GateLimits};
use crate::node_manager::{self, SegmentManager};
use crate::sampler::Sampler;
use crate::shared::Shared;
use crate::users_file::UsersFile;
use crate::writer::Writer;
use opcua::crypto::SecurityPolicy;
use opcua::server::{ANONYMOUS_USER_TOKEN_ID, ServerBuilder, ServerEndpoint};
use opcua::types::{MessageSecurityMode, TypeLoaderCollection};
use plc_shm::DynSegment;
use std::fmt;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex, mpsc};
use std::time::Duration;

/// What `plc opcua serve` was asked for.
#[derive(Clone, Debug)]
pub struct ServeOptions {
    /// The segments to serve (running programs).
    pub segments: Vec<String>,
    /// The address to listen on (`0.0.0.0`: every interface).
    pub host: String,
    /// The TCP port (4840, OPC UA's registered port).
    pub port: u16,
    /// The users file (`plc opcua user add`); without one, nobody may write.
    pub users: Option<PathBuf>,
    /// The certificate store: `own/cert.der`, `private/private.pem` (made on first start),
    /// `trusted/` (client certificates allowed to connect with Sign or SignAndEncrypt),
    /// `rejected/` (certificates of clients that tried; move one to `trusted/` to allow it).
    pub pki: PathBuf,
    /// What one client, and all of them, may hold; whether users may write over None.
    pub limits: ServeLimits,
}

/// What clients may hold, with defaults that serve a plant of 10,000 variables (every one in
/// one subscription, one Read or one Browse) while no one address can take what the others
/// need. `plc opcua serve` has a flag for each.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ServeLimits {
    /// Users sign in and write over None too (`--allow-unsigned-writes`): only for a closed
    /// network, where nobody on the path could read or change a write.
    pub allow_unsigned_writes: bool,
    /// Sessions in all (`--max-sessions`).
    pub sessions: usize,
    /// Sessions from one client address (`--max-sessions-per-address`).
    pub sessions_per_address: usize,
    /// Connections in all (`--max-connections`).
    pub connections: usize,
    /// Connections from one client address (`--max-connections-per-address`).
    pub connections_per_address: usize,
    /// Monitored items in one subscription (`--max-monitored-items`); a session has at most
    /// [`SUBSCRIPTIONS_PER_SESSION`] subscriptions.
    pub monitored_items: usize,
    /// Nodes in one Read, Write, Browse, RegisterNodes or CreateMonitoredItems
    /// (`--max-nodes-per-call`).
    pub nodes_per_call: usize,
    /// Refused client certificates kept in `pki/rejected/`, the newest (`--max-rejected`).
    pub rejected_certificates: usize,
}

/// Subscriptions one session may hold.
pub const SUBSCRIPTIONS_PER_SESSION: usize = 4;

/// The longest a session lives without its client (the server's longest session timeout).
pub const SESSION_TIMEOUT: Duration = Duration::from_secs(60);

impl Default for ServeLimits {
    fn default() -> Self {
        ServeLimits {
            allow_unsigned_writes: false,
            sessions: 100,
            sessions_per_address: 10,
            connections: 200,
            connections_per_address: 20,
            monitored_items: 10_000,
            nodes_per_call: 10_000,
            rejected_certificates: 64,
        }
    }
}

/// Why the server could not start.
#[derive(Debug)]
pub struct ServeError(pub String);

impl fmt::Display for ServeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for ServeError {}

impl From<String> for ServeError {
    fn from(s: String) -> Self {
        ServeError(s)
    }
}

/// A served segment before the server runs: its first attachment and its job queues.
struct Pending {
    name: String,
    period: Duration,
    reads: mpsc::Receiver<crate::shared::ReadJob>,
    writes: mpsc::Receiver<crate::shared::WriteJob>,
    shared: Arc<Mutex<Option<Arc<Shared>>>>,
    /// The alarms the conditions were first built from.
    alarms: Vec<plc_shm::AlarmDescriptor>,
}

/// Serves the segments until Ctrl-C or SIGTERM.
pub fn serve(options: &ServeOptions) -> Result<(), ServeError> {
    if options.segments.is_empty() {
        return Err(ServeError("name at least one segment to serve".into()));
    }
    let users =
        Arc::new(UsersFile::open(options.users.as_deref()).map_err(|e| ServeError(e.to_string()))?);
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        .enable_all()
        .build()
        .map_err(|e| ServeError(format!("cannot start the server's threads: {e}")))?;
    runtime.block_on(run(options, users))
}

async fn run(options: &ServeOptions, users: Arc<UsersFile>) -> Result<(), ServeError> {
    prepare_private_dir(&options.pki)?;
    let registry = Arc::new(Registry::default());
    let mut builder = configure(options, users.clone(), registry.clone())?;
    let mut pending = Vec::new();
    let mut fastest = Duration::from_secs(1);
    for name in &options.segments {
        let seg = DynSegment::attach(name)
            .map_err(|e| ServeError(format!("cannot serve segment `{name}`: {e}")))?;
        let period = seg.status().stats.period;
        fastest = fastest.min(period);
        let (read_tx, reads) = mpsc::channel();
        let (write_tx, writes) = mpsc::channel();
        let slot = Arc::new(Mutex::new(None));
        let fill = slot.clone();
        let segment = name.clone();
        builder = builder.with_node_manager(node_manager::builder(
            name.clone(),
            seg.descriptor().clone(),
            period,
            users.clone(),
            options.limits.allow_unsigned_writes,
            registry.clone(),
            move |layout, alarms: Arc<AlarmSpace>| {
                let shared = Arc::new(Shared::new(segment, layout, alarms, read_tx, write_tx));
                *fill.lock().unwrap_or_else(|e| e.into_inner()) = Some(shared.clone());
                shared
            },
        ));
        pending.push(Pending {
            name: name.clone(),
            period,
            reads,
            writes,
            shared: slot,
            alarms: seg.alarms().to_vec(),
        });
    }
    // Sampling and publishing down to the fastest owner's period, in whole milliseconds.
    let fastest_ms = (fastest.as_secs_f64() * 1000.0).max(1.0);
    {
        let asked = &options.limits;
        let limits = builder.limits_mut();
        limits.subscriptions.min_sampling_interval_ms = fastest_ms;
        limits.subscriptions.min_publishing_interval_ms = fastest_ms;
        limits.subscriptions.max_monitored_items_per_sub = asked.monitored_items;
        limits.subscriptions.max_subscriptions_per_session = SUBSCRIPTIONS_PER_SESSION;
        limits.subscriptions.max_queued_notifications = asked.monitored_items.max(20);
        // An alarm client's event queue: a ConditionRefresh of many active alarms, or a flood
        // of transitions, arrives between two publishes. Values keep async-opcua's queue of
        // 10 at most (each node manager revises their items down to it).
        limits.subscriptions.max_monitored_item_queue_size = crate::alarms::EVENT_QUEUE;
        limits.max_sessions = asked.sessions;
        let per_call = asked.nodes_per_call;
        limits.operational.max_nodes_per_read = per_call;
        limits.operational.max_nodes_per_write = per_call;
        limits.operational.max_monitored_items_per_call = per_call;
        limits.operational.max_nodes_per_browse = per_call;
        limits.operational.max_nodes_per_register_nodes = per_call;
        // One Read (or CreateMonitoredItems) of every variable of a plant: 10,000 nodes are a
        // request of about 300 KB holding an array of 10,000, which async-opcua's defaults
        // (arrays of 1,000 elements, messages of 5 chunks of 64 KiB) refuse. Its answer, or a
        // Browse of as many nodes, takes a few MiB: 8 MiB a message at most.
        limits.max_array_length = per_call.max(1000);
        limits.max_message_size = 8 << 20;
        limits.max_chunk_count = 128;
    }
    builder = builder
        .subscription_poll_interval_ms(fastest_ms as u64)
        .max_session_timeout_ms(SESSION_TIMEOUT.as_millis() as u64);
    let (server, handle) = builder.build().map_err(ServeError)?;
    refuse_plain_text_passwords(&handle);
    protect_private_key(&options.pki)?;
    let stop = Arc::new(AtomicBool::new(false));
    let mut threads = Vec::new();
    for p in pending {
        let shared = p
            .shared
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .take()
            .ok_or_else(|| {
                ServeError(format!(
                    "segment `{}`: its node manager was not built",
                    p.name
                ))
            })?;
        let manager = handle
            .node_managers()
            .get_by_name::<SegmentManager>(&crate::mapping::namespace_uri(&p.name))
            .ok_or_else(|| {
                ServeError(format!("segment `{}`: its node manager is missing", p.name))
            })?;
        let space = manager.address_space().clone();
        let subscriptions = handle.subscriptions().clone();
        let (stop, reads, writes, period) = (stop.clone(), p.reads, p.writes, p.period);
        let for_sampler = shared.clone();
        let (ack_tx, acks) = mpsc::sync_channel::<AckJob>(crate::alarms::ACK_QUEUE);
        shared.alarms.set_ack_queue(ack_tx);
        let poller = AlarmPoller::new(
            shared.alarms.clone(),
            p.alarms,
            shared.clone(),
            space.clone(),
            subscriptions.clone(),
        );
        let alarm_stop = stop.clone();
        threads.push(spawn(&format!("opcua-a-{}", p.name), move || {
            poller.run(acks, alarm_stop)
        })?);
        // A segment handle stays in the thread that attached it: each thread makes its own.
        threads.push(spawn(&format!("opcua-{}", p.name), move || {
            Sampler::new(for_sampler, period, space, subscriptions).run(reads, stop)
        })?);
        spawn(&format!("opcua-w-{}", p.name), move || {
            Writer::new(shared).run(writes)
        })?;
    }
    log::info!(
        "OPC UA server on opc.tcp://{}:{}/ serving {} ({} users may write); certificates in {}",
        options.host,
        options.port,
        options.segments.join(", "),
        users.current().len(),
        options.pki.display()
    );
    let cancel = handle.clone();
    tokio::spawn(async move {
        let mut term =
            tokio::signal::unix::signal(tokio::signal::unix::SignalKind::terminate()).ok();
        tokio::select! {
            _ = tokio::signal::ctrl_c() => {}
            _ = async { match term.as_mut() { Some(t) => { t.recv().await; } None => std::future::pending().await } } => {}
        }
        log::info!("OPC UA server stopping");
        cancel.cancel();
    });
    if options.limits.allow_unsigned_writes {
        log::warn!(
            "OPC UA: users sign in and write over None too (--allow-unsigned-writes): anyone on \
             the network path can read and change their writes; use it on a closed network only"
        );
    }
    // The public port is the gate's; the server listens on a loopback port of its own behind
    // it, and announces the public one in its endpoints.
    let public = listen(&options.host, options.port).await?;
    let public_port = public
        .local_addr()
        .map_err(|e| ServeError(format!("the listener has no address: {e}")))?
        .port();
    let inner = listen("127.0.0.1", 0).await?;
    let inner_addr = inner
        .local_addr()
        .map_err(|e| ServeError(format!("the server's own listener has no address: {e}")))?;
    let info = handle.info().clone();
    let serving = tokio::spawn(server.run_with(inner));
    // `run_with` writes its listener's port into the server's info first: write the public
    // port over it once it has.
    while info.port.load(Ordering::Relaxed) != inner_addr.port() && !serving.is_finished() {
        tokio::time::sleep(Duration::from_millis(5)).await;
    }
    info.port.store(public_port, Ordering::Relaxed);
    let gate = Arc::new(Gate::new(GateLimits {
        connections: options.limits.connections,
        connections_per_address: options.limits.connections_per_address,
        sessions_per_address: options.limits.sessions_per_address,
        session_hold: SESSION_TIMEOUT,
    }));
    let door = tokio::spawn(gate.run(public, inner_addr));
    let sweeper = tokio::spawn(crate::rejected::keep_newest(
        options.pki.join("rejected"),
        options.limits.rejected_certificates,
    ));
    let result = match serving.await {
        Ok(r) => r.map_err(ServeError),
        Err(e) => Err(ServeError(format!("the server stopped: {e}"))),
    };
    door.abort();
    sweeper.abort();
    stop.store(true, Ordering::Relaxed);
    for t in threads {
        let _ = t.join();
    }
    result
}

/// The server's socket, with TCP_NODELAY, which the connections it accepts inherit.
/// async-opcua leaves Nagle's algorithm on: a small message (a Publish response with one
/// changed value) written while the previous one is not yet acknowledged waits for the
/// client's delayed acknowledgement, up to 40 ms on Linux; plc-bench measured notification
/// latencies of 20-30 ms in a repeating pattern where the cycles and the publishing interval
/// are 1 ms.
async fn listen(host: &str, port: u16) -> Result<tokio::net::TcpListener, ServeError> {
    use std::os::fd::AsRawFd;
    let listener = tokio::net::TcpListener::bind((host, port))
        .await
        .map_err(|e| ServeError(format!("cannot listen on {host}:{port}: {e}")))?;
    let on: libc::c_int = 1;
    // SAFETY: setsockopt on the listener's own open descriptor, with a pointer to a c_int
    // that lives through the call and its size.
    let set = unsafe {
        libc::setsockopt(
            listener.as_raw_fd(),
            libc::IPPROTO_TCP,
            libc::TCP_NODELAY,
            (&on as *const libc::c_int).cast(),
            std::mem::size_of::<libc::c_int>() as libc::socklen_t,
        )
    };
    if set != 0 {
        // Still a working server, only with slower notifications.
        log::warn!(
            "TCP_NODELAY not set on {host}:{port} ({}): notifications may wait for \
             acknowledgements",
            std::io::Error::last_os_error()
        );
    }
    Ok(listener)
}

/// The server's endpoints, certificate store, users and decoding rules.
fn configure(
    options: &ServeOptions,
    users: Arc<UsersFile>,
    registry: Arc<Registry>,
) -> Result<ServerBuilder, ServeError> {
    let anonymous = [ANONYMOUS_USER_TOKEN_ID.to_string()];
    let mut none = ServerEndpoint::new_none("/", &anonymous);
    // A user name token on the None endpoint is encrypted under Basic256Sha256 (RSA-OAEP).
    none.password_security_policy = Some(SecurityPolicy::Basic256Sha256.to_uri().to_string());
    let secure = |mode| ServerEndpoint::new("/", SecurityPolicy::Basic256Sha256, mode, &anonymous);
    let host = hostname();
    let methods = AlarmMethods::new(
        registry,
        users.clone(),
        options.limits.allow_unsigned_writes,
    );
    // The core node manager behind the front that answers the condition methods, then the
    // diagnostics one: async-opcua's two, in its order.
    Ok(ServerBuilder::new()
        .without_node_managers()
        .with_node_manager(crate::alarms::front::builder(methods))
        .with_node_manager(opcua::server::diagnostics::DiagnosticsNodeManagerBuilder)
        .application_name("plc-vars OPC UA server")
        .application_uri(format!("urn:plc-vars:opcua-server:{host}"))
        .product_uri("urn:plc-vars:opcua-server")
        .host(options.host.clone())
        .port(options.port)
        .pki_dir(&options.pki)
        .create_sample_keypair(true)
        .certificate_path("own/cert.der")
        .private_key_path("private/private.pem")
        .trust_client_certs(false)
        .discovery_urls(vec!["/".to_string()])
        .add_endpoint("none", none)
        .add_endpoint("basic256sha256_sign", secure(MessageSecurityMode::Sign))
        .add_endpoint(
            "basic256sha256_sign_encrypt",
            secure(MessageSecurityMode::SignAndEncrypt),
        )
        .with_authenticator(Arc::new(PlcAuth::new(
            users,
            options.limits.allow_unsigned_writes,
        )))
        .diagnostics_enabled(false))
}

/// Puts [`RefusePlainTextPasswords`] ahead of every other type loader: async-opcua's own
/// decoder of the core types has the highest priority there is, and a loader added the usual
/// way is asked only after it.
fn refuse_plain_text_passwords(handle: &opcua::server::ServerHandle) {
    let mut loaders = TypeLoaderCollection::new_empty();
    loaders.add(Arc::new(RefusePlainTextPasswords));
    for loader in handle.info().type_loaders.read().iter() {
        loaders.add(loader.clone());
    }
    *handle.info().type_loaders.write() = loaders;
}

/// `pki/private` made (or checked) mode 0700 before the store writes the private key into it.
fn prepare_private_dir(pki: &Path) -> Result<(), ServeError> {
    use std::os::unix::fs::{DirBuilderExt, PermissionsExt};
    let private = pki.join("private");
    std::fs::DirBuilder::new()
        .recursive(true)
        .mode(0o700)
        .create(&private)
        .map_err(|e| ServeError(format!("cannot create {}: {e}", private.display())))?;
    let meta = std::fs::symlink_metadata(&private)
        .map_err(|e| ServeError(format!("{}: {e}", private.display())))?;
    if !meta.is_dir() {
        return Err(ServeError(format!(
            "{} is not a directory (a symbolic link is not followed): remove it",
            private.display()
        )));
    }
    std::fs::set_permissions(&private, std::fs::Permissions::from_mode(0o700))
        .map_err(|e| ServeError(format!("cannot restrict {}: {e}", private.display())))
}

/// The private key readable by its owner only (the store writes it with the default mode).
fn protect_private_key(pki: &Path) -> Result<(), ServeError> {
    use std::os::unix::fs::PermissionsExt;
    for (path, mode) in [
        (pki.join("private"), 0o700),
        (pki.join("private/private.pem"), 0o600),
    ] {
        let meta = std::fs::symlink_metadata(&path)
            .map_err(|e| ServeError(format!("{}: {e}", path.display())))?;
        if meta.file_type().is_symlink() {
            return Err(ServeError(format!(
                "{} is a symbolic link: the server's private key must be a file of its own",
                path.display()
            )));
        }
        std::fs::set_permissions(&path, std::fs::Permissions::from_mode(mode))
            .map_err(|e| ServeError(format!("cannot restrict {}: {e}", path.display())))?;
    }
    Ok(())
}

/// This machine's name, for the application URI in the certificate.
fn hostname() -> String {
    std::fs::read_to_string("/proc/sys/kernel/hostname")
        .map(|s| s.trim().to_string())
        .ok()
        .filter(|s| {
            !s.is_empty()
                && s.bytes()
                    .all(|b| b.is_ascii_alphanumeric() || b"-.".contains(&b))
        })
        .unwrap_or_else(|| "localhost".to_string())
}

fn spawn(
    name: &str,
    f: impl FnOnce() + Send + 'static,
) -> Result<std::thread::JoinHandle<()>, ServeError> {
    std::thread::Builder::new()
        .name(name.to_string())
        .spawn(f)
        .map_err(|e| ServeError(format!("cannot start thread {name}: {e}")))
}
