//! `cycle_with_opcua_clients_*`: the owner's cycle time while the clients hold their
//! subscriptions, against windows in which they hold none, from the owner's status block.

use super::client::{Client, parameters};
use crate::owner_cycle::{self, Cycles, Window};
use opcua::client::DataChangeCallback;
use opcua::types::{MonitoredItemCreateRequest, MonitoringMode, NodeId, TimestampsToReturn};
use plc_io::shm::DynSegment;
use std::fmt::Write;
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::Duration;

/// The owner's cycle time with and without the clients' subscriptions.
pub(super) struct Load {
    idle: Cycles,
    busy: Cycles,
    values_per_s: f64,
}

impl Load {
    /// Its figures, each name ending in `suffix`.
    pub(super) fn write(&self, out: &mut String, suffix: &str) {
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

/// `shares[i]`: the nodes client `i` monitors.
pub(super) async fn cycle_ratio(
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
        idle.push(owner_cycle_us(seg, WINDOW));
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
        busy.push(owner_cycle_us(seg, WINDOW));
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

/// The owner's cycle time over the next `window`, this worker given up meanwhile (the runtime
/// moves the clients' tasks to the other).
fn owner_cycle_us(seg: &DynSegment, window: Duration) -> Window {
    tokio::task::block_in_place(|| owner_cycle::sample(seg, window))
}
