//! Group `sparkplug`: the real edge node (`plc mqtt serve`, a release build) publishing a
//! running program to a real mosquitto on loopback, read by a measuring host in this process
//! (an MQTT client that decodes every payload). The program is [`super::owner`]'s
//! `Mixed10k` (10,000 basic values, about 340 of them changing every 1 ms cycle) and the main
//! example (`tensile_tester` on its simulated bus). The owner runs on a CPU of its own, the
//! broker, the node and the host on the others ([`crate::placement`]).
//!
//! mosquitto runs with `set_tcp_nodelay true` (without it, Nagle's algorithm now and then
//! held the DDATA of 30 ms towards the host and delivered three at once: p99 33 ms).
//!
//! - `spb_dbirth_10k_bytes`, `spb_dbirth_10k_metrics`: the 10,000-value program's DBIRTH.
//!   `spb_dbirth_10k_ms`: from the host's rebirth request (NCMD) to the decoded DBIRTH, median
//!   of requests.
//! - `spb_values_per_s_10k`: the live values the host decoded from DDATA per second, over the
//!   windows in which the node ran; `spb_latency_p50_ms_10k`, `spb_latency_p99_ms_10k`: each
//!   value's latency from its cycle's time (the metric's timestamp, whole milliseconds, so
//!   the figure reads up to 1 ms high) to its decoding in the host. `spb_ddata_bytes_per_s_10k`,
//!   `spb_ddata_per_s_10k`: the DDATA payloads' bytes and messages per second; `spb_node_cpu_percent_10k`,
//!   `spb_broker_cpu_percent_10k`: the node's and mosquitto's CPU time meanwhile, in percent
//!   of one CPU (one subscriber: the host).
//! - `cycle_with_mqtt_ratio`: the main example's cycle time (its own `stats.last`, sampled
//!   about once a millisecond, median of a window) while the edge node publishes it, against
//!   windows without the node; alternating windows of 2 s, the median of each side's windows
//!   (as `cycle_with_opcua_clients_ratio`). `_mean_ratio`: the same with each window's mean.
//!   `cycle_with_mqtt_ratio_10k`: the same on the 10,000-value program.
//! - The store while the broker is away (`spb_store_outage_s`, the 10,000-value program's
//!   changes kept for later with `--store-max` 1 MiB): `spb_store_peak_bytes`, the most the
//!   store directory held (sampled every 50 ms; the bound is `spb_store_max_bytes`);
//!   `spb_store_dropped_records`, what the full store dropped (the node's log says so);
//!   `spb_store_forwarded_values`, the historical values the host got after the births;
//!   `spb_store_drain_ms`, from the DBIRTH to the first live DDATA after them;
//!   `spb_node_peak_rss_mb`, the node's peak resident memory over the whole run.

mod host;
mod processes;

use super::owner::{self, Owner};
use crate::owner_cycle::{self, Cycles};
use crate::placement::Placement;
use host::{Birth, Host, Seen};
use plc_io::shm::DynSegment;
use plc_sparkplug::topic::MessageType;
use processes::{Broker, Node, cpu_time, dir_bytes, peak_rss};
use std::fmt::Write;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// The store's bound in the outage.
const STORE_MAX: u64 = 1 << 20;
/// One window of cycle samples.
const WINDOW: Duration = Duration::from_secs(2);
/// How long a birth may take to arrive.
const BIRTH_WAIT: Duration = Duration::from_secs(60);

/// Runs the group; its `name: value` lines. Where mosquitto cannot run, the figures say
/// `unavailable (why)`.
pub fn run(quick: bool) -> Result<String, String> {
    let binary = owner::build()?;
    let plc = owner::plc_binary()?;
    let work = Path::new(env!("CARGO_MANIFEST_DIR")).join("../target/plc-bench/sparkplug");
    let _ = std::fs::remove_dir_all(&work);
    std::fs::create_dir_all(&work).map_err(|e| format!("{}: {e}", work.display()))?;
    let placement = Placement::split();
    let mut out = format!("sparkplug_placement: {}\n", placement.describe());
    let mut broker = match Broker::start(&work, &placement) {
        Ok(b) => b,
        Err(why) => {
            let _ = writeln!(out, "spb_dbirth_10k_ms: unavailable ({why})");
            let _ = writeln!(out, "cycle_with_mqtt_ratio: unavailable ({why})");
            return Ok(out);
        }
    };
    // The host's thread and this one (which samples the owner's cycle every millisecond)
    // run on the tools' CPUs: on the owner's, the sampler would be what the figure measures.
    placement.others_here()?;
    let host = Host::connect(broker.port, "bench", "n1", "bench");
    let rounds = if quick { 5 } else { 15 };
    let mut run = Run {
        plc: &plc,
        host: &host,
        port: broker.port,
        placement: &placement,
        peak_rss: 0,
    };

    let segment = format!("plc_bench_spb_{}", std::process::id());
    let program = Owner::spawn(
        placement.owner(Command::new(&binary).args(["10k", &segment]))?,
        &segment,
    )?;
    let seg = DynSegment::attach(&segment).map_err(|e| e.to_string())?;
    let store = work.join("store-10k");
    run.births(&segment, &store, &mut out)?;
    run.ratio(&seg, &store, &broker, rounds, true)?
        .write(&mut out, "_10k");
    let outage = if quick { 5 } else { 10 };
    run.outage(&segment, &store, &mut broker, outage, &mut out)?;
    drop((seg, program));

    let main = work.join("tensile_tester");
    let binary = owner::workspace_binary("examples", "tensile_tester")?;
    let segment = format!("plc_bench_spb_tensile_{}", std::process::id());
    let program = Owner::spawn(
        placement.owner(
            Command::new(binary)
                .args(["--segment", &segment, "--retain"])
                .arg(main.join("retain"))
                .stdout(Stdio::null()),
        )?,
        &segment,
    )?;
    let seg = DynSegment::attach(&segment).map_err(|e| e.to_string())?;
    run.ratio(&seg, &main.join("store"), &broker, rounds, false)?
        .write(&mut out, "");
    drop((seg, program));
    let _ = writeln!(
        out,
        "spb_node_peak_rss_mb: {:.1}",
        run.peak_rss as f64 / 1e6
    );
    placement.restore()?;
    Ok(out)
}

/// What every part of the group uses.
struct Run<'a> {
    plc: &'a Path,
    host: &'a Host,
    port: u16,
    placement: &'a Placement,
    /// The largest peak resident memory of the nodes so far.
    peak_rss: u64,
}

impl Run<'_> {
    /// The edge node on `segment`, once its DBIRTH has arrived.
    fn node(&self, segment: &str, store: &Path) -> Result<(Node, Birth), String> {
        self.host.drain();
        let node = Node::start(
            self.plc,
            segment,
            self.port,
            store,
            STORE_MAX,
            self.placement,
        )?;
        let born = self
            .host
            .birth(MessageType::DBirth, BIRTH_WAIT)
            .map_err(|e| format!("{e} (the node's log: {})", node.log.display()))?;
        Ok((node, born))
    }

    /// Notes the node's peak memory before it goes.
    fn retire(&mut self, node: Node) {
        self.peak_rss = self.peak_rss.max(peak_rss(node.pid()).unwrap_or(0));
        drop(node);
    }

    /// The DBIRTH's size and how long a rebirth takes.
    fn births(&mut self, segment: &str, store: &Path, out: &mut String) -> Result<(), String> {
        let (node, born) = self.node(segment, store)?;
        let mut times = Vec::new();
        for _ in 0..7 {
            std::thread::sleep(Duration::from_millis(300));
            self.host.drain();
            let asked = Instant::now();
            self.host.rebirth()?;
            let reborn = self.host.birth(MessageType::DBirth, BIRTH_WAIT)?;
            times.push((reborn.at - asked).as_secs_f64() * 1e3);
        }
        self.retire(node);
        times.sort_by(f64::total_cmp);
        let _ = writeln!(out, "spb_dbirth_10k_bytes: {}", born.bytes);
        let _ = writeln!(out, "spb_dbirth_10k_metrics: {}", born.metrics);
        let _ = writeln!(out, "spb_dbirth_10k_ms: {:.1}", times[times.len() / 2]);
        Ok(())
    }

    /// The owner's cycle with the node publishing it against without, and what the host got
    /// meanwhile (`data`: figure the values and their latencies).
    fn ratio(
        &mut self,
        seg: &DynSegment,
        store: &Path,
        broker: &Broker,
        rounds: usize,
        data: bool,
    ) -> Result<Load, String> {
        let (mut idle, mut busy) = (Vec::new(), Vec::new());
        let (mut values, mut bytes, mut messages) = (0usize, 0usize, 0usize);
        let mut latencies = Vec::new();
        let (mut node_cpu, mut broker_cpu) = (Duration::ZERO, Duration::ZERO);
        let cpu = |pid: Option<u32>| pid.and_then(cpu_time).unwrap_or_default();
        for _ in 0..rounds {
            idle.push(owner_cycle::sample(seg, WINDOW));
            let (node, _) = self.node(seg.name(), store)?;
            std::thread::sleep(Duration::from_millis(500));
            self.host.drain();
            let (node_before, broker_before) = (cpu(Some(node.pid())), cpu(broker.pid()));
            let start = Instant::now();
            busy.push(owner_cycle::sample(seg, WINDOW));
            let end = Instant::now();
            node_cpu += cpu(Some(node.pid())).saturating_sub(node_before);
            broker_cpu += cpu(broker.pid()).saturating_sub(broker_before);
            while let Ok(seen) = self.host.next(Duration::ZERO) {
                if let Seen::Data {
                    latencies_ms,
                    bytes: size,
                    at,
                    ..
                } = seen
                    && at >= start
                    && at <= end
                {
                    values += latencies_ms.len();
                    bytes += size;
                    messages += 1;
                    latencies.extend(latencies_ms);
                }
            }
            self.retire(node);
            std::thread::sleep(Duration::from_millis(200));
        }
        latencies.sort_by(f64::total_cmp);
        let at = |q: f64| {
            latencies
                .get((latencies.len() as f64 * q) as usize)
                .copied()
        };
        let busy_s = (WINDOW * rounds as u32).as_secs_f64();
        Ok(Load {
            idle: Cycles::of(&idle),
            busy: Cycles::of(&busy),
            data: data.then(|| Data {
                values_per_s: values as f64 / busy_s,
                bytes_per_s: bytes as f64 / busy_s,
                messages_per_s: messages as f64 / busy_s,
                p50_ms: at(0.5).unwrap_or(f64::NAN),
                p99_ms: at(0.99).unwrap_or(f64::NAN),
                node_cpu: node_cpu.as_secs_f64() / busy_s,
                broker_cpu: broker_cpu.as_secs_f64() / busy_s,
            }),
        })
    }

    /// The broker away for `seconds` while the program's values change: what the store held
    /// and dropped, and what came back.
    fn outage(
        &mut self,
        segment: &str,
        store: &Path,
        broker: &mut Broker,
        seconds: u64,
        out: &mut String,
    ) -> Result<(), String> {
        let (node, _) = self.node(segment, store)?;
        broker.stop();
        let (mut peak, end) = (0, Instant::now() + Duration::from_secs(seconds));
        while Instant::now() < end {
            peak = peak.max(dir_bytes(store));
            std::thread::sleep(Duration::from_millis(50));
        }
        broker.restart(self.placement)?;
        let born = self.host.birth(MessageType::DBirth, BIRTH_WAIT)?.at;
        let mut forwarded = 0;
        let live = loop {
            match self.host.next(Duration::from_secs(30))? {
                Seen::Data {
                    historical,
                    latencies_ms,
                    at,
                    ..
                } => {
                    forwarded += historical;
                    if !latencies_ms.is_empty() {
                        break at;
                    }
                }
                _ => continue,
            }
        };
        self.retire(node);
        let log = std::fs::read_to_string(store.with_extension("log")).unwrap_or_default();
        let _ = writeln!(out, "spb_store_outage_s: {seconds}");
        let _ = writeln!(out, "spb_store_max_bytes: {STORE_MAX}");
        let _ = writeln!(out, "spb_store_peak_bytes: {peak}");
        let _ = writeln!(out, "spb_store_dropped_records: {}", dropped(&log));
        let _ = writeln!(out, "spb_store_forwarded_values: {forwarded}");
        let _ = writeln!(
            out,
            "spb_store_drain_ms: {:.0}",
            (live - born).as_secs_f64() * 1e3
        );
        Ok(())
    }
}

/// The records the node's full store dropped since start, from the last line of its log that
/// says so (`... dropped (N since start)`).
fn dropped(log: &str) -> u64 {
    log.lines()
        .rev()
        .find_map(|l| {
            let (head, _) = l.rsplit_once(" since start)")?;
            head.rsplit('(').next()?.trim().parse().ok()
        })
        .unwrap_or(0)
}

/// The cycle with and without the node, and what the host got.
struct Load {
    idle: Cycles,
    busy: Cycles,
    data: Option<Data>,
}

/// The values the host decoded while the node ran.
struct Data {
    values_per_s: f64,
    bytes_per_s: f64,
    messages_per_s: f64,
    p50_ms: f64,
    p99_ms: f64,
    /// The node's and the broker's CPU time per second of the windows.
    node_cpu: f64,
    broker_cpu: f64,
}

impl Load {
    /// Its figures, each name ending in `suffix`.
    fn write(&self, out: &mut String, suffix: &str) {
        let (idle, busy) = (&self.idle, &self.busy);
        let _ = writeln!(out, "cycle_without_mqtt{suffix}_us: {:.1}", idle.median_us);
        let _ = writeln!(out, "cycle_with_mqtt{suffix}_us: {:.1}", busy.median_us);
        let ratio = busy.median_us / idle.median_us;
        let _ = writeln!(out, "cycle_with_mqtt_ratio{suffix}: {ratio:.2}");
        let mean = busy.mean_us / idle.mean_us;
        let _ = writeln!(out, "cycle_with_mqtt_mean_ratio{suffix}: {mean:.2}");
        if let Some(d) = &self.data {
            let _ = writeln!(out, "spb_values_per_s{suffix}: {:.0}", d.values_per_s);
            let _ = writeln!(out, "spb_ddata_bytes_per_s{suffix}: {:.0}", d.bytes_per_s);
            let _ = writeln!(out, "spb_ddata_per_s{suffix}: {:.1}", d.messages_per_s);
            let _ = writeln!(
                out,
                "spb_node_cpu_percent{suffix}: {:.1}",
                d.node_cpu * 100.0
            );
            let _ = writeln!(
                out,
                "spb_broker_cpu_percent{suffix}: {:.1}",
                d.broker_cpu * 100.0
            );
            let _ = writeln!(out, "spb_latency_p50_ms{suffix}: {:.1}", d.p50_ms);
            let _ = writeln!(out, "spb_latency_p99_ms{suffix}: {:.1}", d.p99_ms);
        }
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_dropped_count_is_read_from_the_last_line_that_gives_it() {
        let log = "x\nthe store is full (1048576 bytes): its 12 oldest records dropped (12 since \
                   start)\nthe store is full (1048576 bytes): its 30 oldest records dropped (42 \
                   since start)\nreconnected\n";
        assert_eq!(super::dropped(log), 42);
        assert_eq!(super::dropped("nothing"), 0);
    }
}
