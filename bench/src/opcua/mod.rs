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
//! - `opcua_alarm_event_p50_ms`, `opcua_alarm_event_p99_ms`: on the main example, a tool
//!   forces `guard_door_open` true and releases it (25 times, 100 with `--full`; 50 ms
//!   apart); each event's latency at a subscriber of the Server object's events (publishing
//!   1 ms) is its arrival (client wall clock) less its Time, the UTC time of the program's
//!   cycle that saw the transition. The server polls the alarm table every 10 ms, so about
//!   5 ms plus the publishing path is the median to expect, 10 ms plus it the worst.
//!
//! The owner runs on a CPU of its own (the last this process may use), the server and the
//! clients on the others, as a machine builder gives the program its own core
//! (`opcua_placement` says which); with one CPU all share it. Without that the figure measures
//! the scheduler: whatever runs on the owner's core between two cycles evicts its caches.

mod alarm_events;
mod client;
mod notify;
mod ratio;
mod read;
mod server;

use super::owner::{self, Owner};
use crate::placement::Placement;
use client::{Client, namespace};
use notify::{Wakeups, notify_latency};
use opcua::types::NodeId;
use plc_io::shm::DynSegment;
use ratio::cycle_ratio;
use read::read_all;
use server::Server;
use std::fmt::Write;
use std::path::Path;
use std::process::Command;
use std::time::Duration;

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
    let toggles = if quick { 25 } else { 100 };
    let alarms =
        alarm_events::alarm_event_latency(&clients[0].session, &seg, "guard_door_open", toggles)
            .await;
    for c in clients {
        c.close().await;
    }
    drop((server, seg, program));
    let mut out = format!("opcua_main_example_nodes: {}\n", nodes.len());
    load?.write(&mut out, "");
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    match alarms {
        Ok(a) => {
            let _ = writeln!(out, "opcua_alarm_event_p50_ms: {:.2}", ms(a.p50));
            let _ = writeln!(out, "opcua_alarm_event_p99_ms: {:.2}", ms(a.p99));
            let _ = writeln!(out, "opcua_alarm_event_count: {}", a.count);
        }
        Err(why) => {
            let _ = writeln!(out, "opcua_alarm_event_p99_ms: unavailable ({why})");
        }
    }
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
