//! `plc opcua serve`: the server's configuration (endpoints, certificate, limits), one node
//! manager and two threads per segment, and the run until Ctrl-C or SIGTERM.

use crate::auth::{PlcAuth, RefusePlainTextPasswords};
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
    let mut builder = configure(options, users.clone())?;
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
            move |layout| {
                let shared = Arc::new(Shared::new(segment, layout, read_tx, write_tx));
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
        });
    }
    // Sampling and publishing down to the fastest owner's period, in whole milliseconds.
    let fastest_ms = (fastest.as_secs_f64() * 1000.0).max(1.0);
    {
        let limits = builder.limits_mut();
        limits.subscriptions.min_sampling_interval_ms = fastest_ms;
        limits.subscriptions.min_publishing_interval_ms = fastest_ms;
        limits.subscriptions.max_monitored_items_per_sub = 100_000;
        limits.subscriptions.max_queued_notifications = 1_000_000;
        limits.operational.max_nodes_per_read = 100_000;
        limits.operational.max_monitored_items_per_call = 100_000;
        limits.operational.max_nodes_per_browse = 100_000;
        // One Read (or CreateMonitoredItems) of every variable of a large program: 10,000
        // nodes are a request of about 300 KB holding an array of 10,000, which
        // async-opcua's defaults (arrays of 1,000 elements, messages of 5 chunks of 64 KiB)
        // refuse. Up to the node limits above, still bounded: 16 MiB a message.
        limits.max_array_length = 100_000;
        limits.max_message_size = 16 << 20;
        limits.max_chunk_count = 256;
    }
    builder = builder.subscription_poll_interval_ms(fastest_ms as u64);
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
    let listener = listen(&options.host, options.port).await?;
    let result = server.run_with(listener).await.map_err(ServeError);
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
fn configure(options: &ServeOptions, users: Arc<UsersFile>) -> Result<ServerBuilder, ServeError> {
    let anonymous = [ANONYMOUS_USER_TOKEN_ID.to_string()];
    let mut none = ServerEndpoint::new_none("/", &anonymous);
    // A user name token on the None endpoint is encrypted under Basic256Sha256 (RSA-OAEP).
    none.password_security_policy = Some(SecurityPolicy::Basic256Sha256.to_uri().to_string());
    let secure = |mode| ServerEndpoint::new("/", SecurityPolicy::Basic256Sha256, mode, &anonymous);
    let host = hostname();
    Ok(ServerBuilder::new()
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
        .with_authenticator(Arc::new(PlcAuth::new(users)))
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
