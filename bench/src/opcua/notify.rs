//! `opcua_notify_*`: the latency of a subscription's notifications of `event_utc_ns`, and
//! meanwhile how late a sleeping thread wakes on this machine.

use super::client::parameters;
use crate::owner::PERIOD;
use opcua::client::{DataChangeCallback, Session};
use opcua::types::{
    MonitoredItemCreateRequest, MonitoringMode, NodeId, TimestampsToReturn, Variant,
};
use std::sync::atomic::Ordering;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant, SystemTime, UNIX_EPOCH};

/// The notification latency of `event` (see the `opcua` module's docs) over `seconds`.
pub(super) struct Notify {
    pub(super) p99: Duration,
    pub(super) p50: Duration,
    pub(super) count: usize,
}

pub(super) async fn notify_latency(
    session: &Session,
    event: NodeId,
    seconds: u64,
) -> Result<Notify, String> {
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
pub(super) struct Wakeups {
    stop: Arc<std::sync::atomic::AtomicBool>,
    thread: std::thread::JoinHandle<Vec<Duration>>,
}

impl Wakeups {
    pub(super) fn start() -> Wakeups {
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
    pub(super) fn stop(self) -> Duration {
        self.stop.store(true, Ordering::Relaxed);
        let mut late = self.thread.join().unwrap_or_default();
        late.sort();
        late.get(late.len() * 99 / 100).copied().unwrap_or_default()
    }
}

/// The wall clock in ns since the Unix epoch, as the owner stamps `event_utc_ns`.
fn utc_ns() -> u64 {
    SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| d.as_nanos() as u64)
}
