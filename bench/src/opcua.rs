//! Group `opcua`: the real `plc opcua serve` on a running program of 10,000 variables
//! ([`super::owner`]'s `Mixed10k`, a real owner process at 1 ms) and on the main example
//! (`tensile_tester`, its own process on its simulated bus), asked by real OPC UA clients:
//! async-opcua's client crate (the library the server is built on), in this process, over
//! TCP on localhost, security None, anonymous. The clients' own cost is in the figures, and
//! they run on the same machine as the server and the program.
//!
//! - `opcua_read_10k_ms`: one Read request of the 10,000 variable nodes (Value attribute,
//!   both timestamps), from sending the request to the decoded response, every value checked
//!   Good; median of requests.
//! - `opcua_notify_p99_ms`: a subscription at the owner's period (publishing and sampling
//!   1 ms, queue 1) on `event_utc_ns`, which the owner sets to the wall-clock time of the cycle
//!   that changes it (every 20th cycle): each notification's latency is the client's
//!   wall-clock time when the client library hands it over, less that value. Target < 20 ms
//!   at publishing and sampling intervals of 10 ms; at these intervals of 1 ms, <= 2 x the
//!   publishing interval + 1 cycle = 3 ms is what the path allows.
//!   `opcua_notify_wakeup_late_p99_ms`: meanwhile, how late a thread that sleeps 1 ms wakes
//!   on this machine (context: a notification crosses four sleeping threads).
//! - `cycle_with_opcua_clients_ratio`: the main example's cycle time (`tensile_tester` on its
//!   simulated bus at 1 ms, its own `stats.last` in the status block, sampled about once a
//!   millisecond, median of a window) while 10 clients each hold a subscription of every
//!   variable node of it (sampling at the owner's period, publishing every 100 ms, queue 1),
//!   against windows in which the same sessions hold no subscription; alternating windows of
//!   2 s, the median of each side's windows. `..._mean_ratio`: the same with each window's
//!   mean cycle (from the owner's running mean), which a preempted cycle moves.
//!   `cycle_with_opcua_clients_ratio_10k`: the same on the 10,000-variable program, the 10
//!   clients monitoring 1,000 nodes each (about 340 of the values change every cycle).
//!
//! The owner runs on a CPU of its own (the last this process may use), the server and the
//! clients on the others, as a machine builder gives the program its own core
//! (`opcua_placement` says which); with one CPU all share it. Without that the figure measures
//! the scheduler: whatever runs on the owner's core between two cycles evicts its caches.

use super::owner::{self, Owner, PERIOD};
use super::place;
use opcua::client::{ClientBuilder, DataChangeCallback, IdentityToken, Session};
use opcua::types::{
    DataValue, EndpointDescription, ExtensionObject, MessageSecurityMode,
    MonitoredItemCreateRequest, MonitoringMode, MonitoringParameters, NodeId, ReadValueId,
    TimestampsToReturn, UserTokenPolicy, VariableId, Variant,
};
use plc_io::shm::DynSegment;
use std::fmt::Write;
use std::path::{Path, PathBuf};
use std::process::{Child, Command};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant, SystemTime, UNIX_EPOCH};

/// Runs the group; its `name: value` lines. Where the server cannot run, the figures say
/// `unavailable (why)`.
pub fn run(quick: bool) -> Result<String, String> {
    let binary = owner::build()?;
    let plc = owner::plc_binary()?;
    let segment = format!("plc_bench_opcua_{}", std::process::id());
    let placement = Placement::split();
    let program = Owner::spawn(
        placement.owner(Command::new(&binary).args(["10k", &segment]))?,
        &segment,
    )?;
    let seg = DynSegment::attach(&segment).map_err(|e| e.to_string())?;
    let paths = owner::leaf_paths(&seg);
    if paths.len() != 10_000 {
        return Err(format!(
            "the 10k program has {} variables, not 10,000",
            paths.len()
        ));
    }
    let work = Path::new(env!("CARGO_MANIFEST_DIR")).join("../target/plc-bench/opcua");
    // The clients' threads (the runtime's workers) start on the others' CPUs.
    placement.others_here()?;
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        .enable_all()
        .build()
        .map_err(|e| format!("tokio: {e}"));
    placement.restore()?;
    let runtime = runtime?;
    let result = Server::start(&plc, &segment, &work, &placement).and_then(|server| {
        let lines = runtime.block_on(measure(&server, &seg, &paths, &work, quick));
        drop(server);
        lines
    });
    drop(seg);
    drop(program);
    let unavailable = |names: &[&str], why: String| -> String {
        names
            .iter()
            .map(|name| format!("{name}: unavailable ({why})\n"))
            .collect()
    };
    let mut out = format!("opcua_placement: {}\n", placement.describe());
    out += &result.unwrap_or_else(|why| {
        unavailable(
            &[
                "opcua_read_10k_ms",
                "opcua_notify_p99_ms",
                "cycle_with_opcua_clients_ratio_10k",
            ],
            why,
        )
    });
    let main = runtime.block_on(main_example(
        &plc,
        &work.join("tensile_tester"),
        &placement,
        quick,
    ));
    out.push_str(&main.unwrap_or_else(|why| unavailable(&["cycle_with_opcua_clients_ratio"], why)));
    Ok(out)
}

/// `cycle_with_opcua_clients_ratio`: the main example (`tensile_tester` on its simulated bus)
/// with 10 clients each monitoring every variable node of it, against the same sessions
/// monitoring nothing.
async fn main_example(
    plc: &Path,
    work: &Path,
    placement: &Placement,
    quick: bool,
) -> Result<String, String> {
    let binary = owner::workspace_binary("examples", "tensile_tester")?;
    let segment = format!("plc_bench_tensile_{}", std::process::id());
    let program = Owner::spawn(
        placement.owner(
            Command::new(binary)
                .args(["--segment", &segment, "--retain"])
                .arg(work.join("retain"))
                .stdout(std::process::Stdio::null()),
        )?,
        &segment,
    )?;
    let seg = DynSegment::attach(&segment).map_err(|e| e.to_string())?;
    let paths = owner::variable_node_paths(&seg);
    let server = Server::start(plc, &segment, work, placement)?;
    let mut clients = Vec::new();
    while clients.len() < 10 {
        clients.push(Client::connect(&server.url, work).await?);
    }
    let ns = namespace(&clients[0].session, &format!("urn:plc-vars:{segment}")).await?;
    let nodes: Vec<NodeId> = paths.iter().map(|p| NodeId::new(ns, p.as_str())).collect();
    let shares = vec![&nodes[..]; clients.len()];
    let load = cycle_ratio(&clients, &seg, &shares, if quick { 5 } else { 15 }).await;
    for c in clients {
        c.close().await;
    }
    drop((server, seg, program));
    let mut out = format!("opcua_main_example_nodes: {}\n", nodes.len());
    load?.write(&mut out, "");
    Ok(out)
}

async fn measure(
    server: &Server,
    seg: &DynSegment,
    paths: &[String],
    work: &Path,
    quick: bool,
) -> Result<String, String> {
    let mut out = String::new();
    let first = Client::connect(&server.url, work).await?;
    let ns = namespace(&first.session, &format!("urn:plc-vars:{}", seg.name())).await?;
    let nodes: Vec<NodeId> = paths.iter().map(|p| NodeId::new(ns, p.as_str())).collect();

    let read = read_all(&first.session, &nodes, if quick { 9 } else { 31 }).await?;
    let _ = writeln!(out, "opcua_read_10k_ms: {:.1}", read.as_secs_f64() * 1e3);

    let event = NodeId::new(ns, "event_utc_ns");
    let seconds = if quick { 5 } else { 20 };
    let wakeups = Wakeups::start();
    let notify = notify_latency(&first.session, event, seconds).await?;
    let late = wakeups.stop();
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    let _ = writeln!(out, "opcua_notify_p99_ms: {:.2}", ms(notify.p99));
    let _ = writeln!(out, "opcua_notify_p50_ms: {:.2}", ms(notify.p50));
    let _ = writeln!(out, "opcua_notify_count: {}", notify.count);
    let _ = writeln!(out, "opcua_notify_wakeup_late_p99_ms: {:.2}", ms(late));

    let mut clients = vec![first];
    while clients.len() < 10 {
        clients.push(Client::connect(&server.url, work).await?);
    }
    let rounds = if quick { 5 } else { 15 };
    let shares: Vec<&[NodeId]> = nodes.chunks(nodes.len() / clients.len()).collect();
    let load = cycle_ratio(&clients, seg, &shares, rounds).await?;
    load.write(&mut out, "_10k");
    for c in clients {
        c.close().await;
    }
    Ok(out)
}

/// The index of namespace `uri` on the server.
async fn namespace(session: &Session, uri: &str) -> Result<u16, String> {
    let array: ReadValueId = NodeId::from(VariableId::Server_NamespaceArray).into();
    let values = session
        .read(&[array], TimestampsToReturn::Neither, 0.0)
        .await
        .map_err(|e| format!("reading the namespace array: {e}"))?;
    if let Some(Some(Variant::Array(a))) = values.first().map(|v| v.value.as_ref()) {
        for (i, v) in a.values.iter().enumerate() {
            if let Variant::String(s) = v
                && s.as_ref() == uri
            {
                return u16::try_from(i).map_err(|_| "namespace index out of range".into());
            }
        }
    }
    Err(format!("the server has no namespace {uri}"))
}

/// The median time of one Read of `nodes`, each value checked Good.
async fn read_all(session: &Session, nodes: &[NodeId], runs: usize) -> Result<Duration, String> {
    let ids: Vec<ReadValueId> = nodes.iter().map(ReadValueId::from).collect();
    let mut times = Vec::new();
    // The first read is not counted: the session's buffers grow to the response's size.
    for run in 0..=runs {
        let start = Instant::now();
        let values = session
            .read(&ids, TimestampsToReturn::Both, 0.0)
            .await
            .map_err(|e| format!("Read of {} nodes: {e}", ids.len()))?;
        let took = start.elapsed();
        let good = values.iter().filter(|v| is_good(v)).count();
        if good != ids.len() {
            let bad = values.iter().find(|v| !is_good(v)).and_then(|v| v.status);
            return Err(format!(
                "Read of {} nodes: {good} values Good (first other status: {bad:?})",
                ids.len()
            ));
        }
        if run > 0 {
            times.push(took);
        }
    }
    times.sort();
    Ok(times[times.len() / 2])
}

fn is_good(v: &DataValue) -> bool {
    v.value.is_some() && v.status.is_none_or(|s| s.is_good())
}

/// The notification latency of `event` (see the module's docs) over `seconds`.
struct Notify {
    p99: Duration,
    p50: Duration,
    count: usize,
}

async fn notify_latency(session: &Session, event: NodeId, seconds: u64) -> Result<Notify, String> {
    let latencies: Arc<Mutex<Vec<i64>>> = Arc::default();
    let sink = latencies.clone();
    let subscription = session
        .create_subscription(
            PERIOD,
            30_000,
            1_000,
            0,
            0,
            true,
            DataChangeCallback::new(move |value, _| {
                if let Some(Variant::UInt64(stamp)) = value.value
                    && stamp > 0
                {
                    let now = utc_ns();
                    let mut l = sink.lock().unwrap_or_else(|e| e.into_inner());
                    l.push(now as i64 - stamp as i64);
                }
            }),
        )
        .await
        .map_err(|e| format!("create subscription: {e}"))?;
    let item =
        MonitoredItemCreateRequest::new(event.into(), MonitoringMode::Reporting, parameters(1));
    let created = session
        .create_monitored_items(subscription, TimestampsToReturn::Both, vec![item])
        .await
        .map_err(|e| format!("create monitored item: {e}"))?;
    if created.iter().any(|c| !c.result.status_code.is_good()) {
        return Err("the monitored item was refused".into());
    }
    tokio::time::sleep(Duration::from_secs(seconds)).await;
    let _ = session.delete_subscription(subscription).await;
    let mut l = latencies.lock().unwrap_or_else(|e| e.into_inner()).clone();
    // The first notification is the value as it was when the item was created, not a change.
    if l.len() < 10 {
        return Err(format!("only {} notifications in {seconds} s", l.len()));
    }
    l.remove(0);
    l.sort_unstable();
    let at = |q: usize| Duration::from_nanos(l[(l.len() * q / 100).min(l.len() - 1)].max(0) as u64);
    Ok(Notify {
        p99: at(99),
        p50: at(50),
        count: l.len(),
    })
}

/// A thread that sleeps a period at a time and notes how late it wakes, beside the latency
/// measurement: how long this machine makes a woken thread wait (each notification crosses
/// four of them: the owner, the server's sampler, the server's publishing, the client).
struct Wakeups {
    stop: Arc<std::sync::atomic::AtomicBool>,
    thread: std::thread::JoinHandle<Vec<Duration>>,
}

impl Wakeups {
    fn start() -> Wakeups {
        let stop = Arc::new(std::sync::atomic::AtomicBool::new(false));
        let flag = stop.clone();
        let thread = std::thread::spawn(move || {
            let mut late = Vec::new();
            while !flag.load(Ordering::Relaxed) {
                let t = Instant::now();
                std::thread::sleep(PERIOD);
                late.push(t.elapsed().saturating_sub(PERIOD));
            }
            late
        });
        Wakeups { stop, thread }
    }

    /// The 99th percentile of the lateness.
    fn stop(self) -> Duration {
        self.stop.store(true, Ordering::Relaxed);
        let mut late = self.thread.join().unwrap_or_default();
        late.sort();
        late.get(late.len() * 99 / 100).copied().unwrap_or_default()
    }
}

/// Monitoring at the owner's period, the newest value only.
fn parameters(handle: u32) -> MonitoringParameters {
    MonitoringParameters {
        client_handle: handle,
        sampling_interval: PERIOD.as_secs_f64() * 1e3,
        filter: ExtensionObject::null(),
        queue_size: 1,
        discard_oldest: true,
    }
}

/// The owner's cycle time with and without the clients' subscriptions.
struct Load {
    idle: Cycles,
    busy: Cycles,
    values_per_s: f64,
}

impl Load {
    /// Its figures, each name ending in `suffix`.
    fn write(&self, out: &mut String, suffix: &str) {
        let (idle, busy) = (&self.idle, &self.busy);
        let _ = writeln!(
            out,
            "cycle_without_opcua_clients{suffix}_us: {:.1}",
            idle.median_us
        );
        let _ = writeln!(
            out,
            "cycle_with_opcua_clients{suffix}_us: {:.1}",
            busy.median_us
        );
        let _ = writeln!(
            out,
            "cycle_with_opcua_clients_ratio{suffix}: {:.2}",
            busy.median_us / idle.median_us
        );
        let _ = writeln!(
            out,
            "cycle_with_opcua_clients_mean_ratio{suffix}: {:.2}",
            busy.mean_us / idle.mean_us
        );
        let _ = writeln!(
            out,
            "opcua_clients_values_per_s{suffix}: {:.0}",
            self.values_per_s
        );
    }
}

/// The owner's cycle time over some windows: the median of the windows' medians and means.
struct Cycles {
    median_us: f64,
    mean_us: f64,
}

impl Cycles {
    fn of(windows: &[Window]) -> Cycles {
        let median = |mut v: Vec<f64>| {
            v.sort_by(f64::total_cmp);
            v[v.len() / 2]
        };
        Cycles {
            median_us: median(windows.iter().map(|w| w.median_us).collect()),
            mean_us: median(windows.iter().map(|w| w.mean_us).collect()),
        }
    }
}

/// `shares[i]`: the nodes client `i` monitors.
async fn cycle_ratio(
    clients: &[Client],
    seg: &DynSegment,
    shares: &[&[NodeId]],
    rounds: usize,
) -> Result<Load, String> {
    const WINDOW: Duration = Duration::from_secs(2);
    let values = Arc::new(AtomicU64::new(0));
    let (mut idle, mut busy) = (Vec::new(), Vec::new());
    let mut received = (0u64, Duration::ZERO);
    for _ in 0..rounds.max(1) {
        idle.push(owner_cycle_us(seg, WINDOW).await);
        let mut subscriptions = Vec::new();
        for (c, share) in clients.iter().zip(shares) {
            let counter = values.clone();
            let id = c
                .session
                .create_subscription(
                    Duration::from_millis(100),
                    300,
                    10,
                    0,
                    0,
                    true,
                    DataChangeCallback::new(move |_, _| {
                        counter.fetch_add(1, Ordering::Relaxed);
                    }),
                )
                .await
                .map_err(|e| format!("create subscription: {e}"))?;
            let items: Vec<MonitoredItemCreateRequest> = share
                .iter()
                .enumerate()
                .map(|(i, n)| {
                    MonitoredItemCreateRequest::new(
                        n.into(),
                        MonitoringMode::Reporting,
                        parameters(i as u32 + 1),
                    )
                })
                .collect();
            let created = c
                .session
                .create_monitored_items(id, TimestampsToReturn::Both, items)
                .await
                .map_err(|e| format!("create monitored items: {e}"))?;
            if created.iter().any(|c| !c.result.status_code.is_good()) {
                return Err("a monitored item was refused".into());
            }
            subscriptions.push((c, id));
        }
        // The initial values of every item delivered before the window starts.
        tokio::time::sleep(Duration::from_millis(500)).await;
        let before = values.load(Ordering::Relaxed);
        busy.push(owner_cycle_us(seg, WINDOW).await);
        received.0 += values.load(Ordering::Relaxed) - before;
        received.1 += WINDOW;
        for (c, id) in subscriptions {
            let _ = c.session.delete_subscription(id).await;
        }
        tokio::time::sleep(Duration::from_millis(200)).await;
    }
    Ok(Load {
        idle: Cycles::of(&idle),
        busy: Cycles::of(&busy),
        values_per_s: received.0 as f64 / received.1.as_secs_f64(),
    })
}

/// The owner's cycle times in one window.
struct Window {
    /// The median of the cycles sampled.
    median_us: f64,
    /// The mean of all cycles of the window.
    mean_us: f64,
}

/// The owner's cycle time over the next `window`, from its status block: the time of the
/// last cycle, sampled every millisecond or so (each cycle at most once), and the mean of all
/// the window's cycles from the running mean times the cycle count at both ends. A cycle the
/// machine preempts for milliseconds moves the mean by as much as a thousand cycles of
/// work; the median is the typical cycle.
async fn owner_cycle_us(seg: &DynSegment, window: Duration) -> Window {
    let total = |seg: &DynSegment| {
        let s = seg.status();
        (
            s.cycle_count,
            s.stats.mean.as_secs_f64() * s.cycle_count as f64,
        )
    };
    let (c1, t1) = total(seg);
    let end = Instant::now() + window;
    let mut seen = c1;
    let mut last = Vec::new();
    while Instant::now() < end {
        let s = seg.status();
        if s.cycle_count != seen {
            seen = s.cycle_count;
            last.push(s.stats.last.as_secs_f64() * 1e6);
        }
        tokio::time::sleep(PERIOD).await;
    }
    let (c2, t2) = total(seg);
    last.sort_by(f64::total_cmp);
    Window {
        median_us: last.get(last.len() / 2).copied().unwrap_or(f64::NAN),
        mean_us: if c2 > c1 {
            (t2 - t1) / (c2 - c1) as f64 * 1e6
        } else {
            f64::NAN
        },
    }
}

/// One client session and its event loop.
struct Client {
    session: Arc<Session>,
    event_loop: tokio::task::JoinHandle<opcua::types::StatusCode>,
}

impl Client {
    async fn connect(url: &str, work: &Path) -> Result<Client, String> {
        let mut client = ClientBuilder::new()
            .application_name("plc-bench")
            .application_uri("urn:plc-vars:plc-bench")
            .product_uri("urn:plc-vars:plc-bench")
            .pki_dir(work.join("client-pki"))
            .create_sample_keypair(true)
            .trust_server_certs(true)
            .session_retry_limit(0)
            // A response of 10,000 values: larger than async-opcua's defaults (arrays of
            // 1,000, messages of 5 x 64 KiB), as on the server.
            .max_array_length(100_000)
            .max_message_size(16 << 20)
            .max_chunk_count(256)
            .min_publish_interval(PERIOD)
            .client()
            .map_err(|e| format!("OPC UA client: {}", e.join("; ")))?;
        let endpoint: EndpointDescription = (
            url,
            "http://opcfoundation.org/UA/SecurityPolicy#None",
            MessageSecurityMode::None,
            UserTokenPolicy::anonymous(),
        )
            .into();
        let (session, event_loop) = client
            .connect_to_matching_endpoint(endpoint, IdentityToken::Anonymous)
            .await
            .map_err(|e| format!("connecting to {url}: {e}"))?;
        let event_loop = event_loop.spawn();
        if !session.wait_for_connection().await {
            return Err(format!("no session with {url}"));
        }
        Ok(Client {
            session,
            event_loop,
        })
    }

    async fn close(self) {
        let _ = self.session.disconnect().await;
        self.event_loop.abort();
    }
}

/// `plc opcua serve` on a free port of localhost; stopped with SIGTERM when dropped.
struct Server {
    child: Child,
    url: String,
}

impl Server {
    fn start(
        plc: &Path,
        segment: &str,
        work: &Path,
        placement: &Placement,
    ) -> Result<Server, String> {
        std::fs::create_dir_all(work).map_err(|e| format!("{}: {e}", work.display()))?;
        let port = std::net::TcpListener::bind("127.0.0.1:0")
            .and_then(|l| l.local_addr())
            .map_err(|e| format!("no free port: {e}"))?
            .port();
        let log: PathBuf = work.join("server.log");
        let file = std::fs::File::create(&log).map_err(|e| format!("{}: {e}", log.display()))?;
        let err = file.try_clone().map_err(|e| e.to_string())?;
        let child = placement
            .others(&mut Command::new(plc))?
            .args(["opcua", "serve", segment, "--host", "127.0.0.1", "--port"])
            .arg(port.to_string())
            // Kept between runs: the server makes its key pair once.
            .arg("--pki")
            .arg(work.join("pki"))
            .stdout(file)
            .stderr(err)
            .spawn()
            .map_err(|e| format!("{}: {e}", plc.display()))?;
        let mut server = Server {
            child,
            url: format!("opc.tcp://127.0.0.1:{port}/"),
        };
        let deadline = Instant::now() + Duration::from_secs(60);
        while std::net::TcpStream::connect(("127.0.0.1", port)).is_err() {
            if Instant::now() > deadline || matches!(server.child.try_wait(), Ok(Some(_))) {
                let text = std::fs::read_to_string(&log).unwrap_or_default();
                return Err(format!(
                    "plc opcua serve did not start: {}",
                    text.lines().last().unwrap_or("no output")
                ));
            }
            std::thread::sleep(Duration::from_millis(50));
        }
        Ok(server)
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        owner::stop_child(&mut self.child);
    }
}

/// Where the group's processes run: the owner on a CPU of its own (the last this process may
/// use), the server and the clients on the others, as a machine builder isolates the
/// program's core. With one CPU all share it.
struct Placement {
    all: Vec<usize>,
    owner: Option<usize>,
    others: Vec<usize>,
}

impl Placement {
    fn split() -> Placement {
        let all = place::allowed_cpus();
        match all.split_last() {
            Some((&owner, others)) if !others.is_empty() => Placement {
                owner: Some(owner),
                others: others.to_vec(),
                all,
            },
            _ => Placement {
                owner: None,
                others: all.clone(),
                all,
            },
        }
    }

    fn describe(&self) -> String {
        match self.owner {
            Some(cpu) => format!(
                "owner on CPU {cpu}, server and clients on CPUs {:?}",
                self.others
            ),
            None => "all on one CPU (no CPU to give the owner alone)".into(),
        }
    }

    /// `command` set to start on the owner's CPU.
    fn owner<'c>(&self, command: &'c mut Command) -> Result<&'c mut Command, String> {
        if let Some(cpu) = self.owner {
            place::pin_command(command, &[cpu])?;
        }
        Ok(command)
    }

    /// `command` set to start on the others' CPUs.
    fn others<'c>(&self, command: &'c mut Command) -> Result<&'c mut Command, String> {
        place::pin_command(command, &self.others)?;
        Ok(command)
    }

    /// The calling thread (and the threads it starts) on the others' CPUs.
    fn others_here(&self) -> Result<(), String> {
        place::pin_to(&self.others)
    }

    /// The calling thread back on every CPU it had.
    fn restore(&self) -> Result<(), String> {
        place::pin_to(&self.all)
    }
}

/// The wall clock in ns since the Unix epoch, as the owner stamps `event_utc_ns`.
fn utc_ns() -> u64 {
    SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| d.as_nanos() as u64)
}
