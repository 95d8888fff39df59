//! `opcua_alarm_event_p50_ms`, `opcua_alarm_event_p99_ms`: how long after the program's
//! transition of an alarm a subscriber of the Server object's events has its event. A tool
//! forces the main example's `guard_door_open` true and releases it (each a transition, raised
//! and returned); each event's latency is the client's wall-clock time when the client library
//! hands it over, less its Time (the UTC time of the program's cycle that saw the transition).
//! The path: the program's cycle, the server's alarm poll (every 10 ms), its publishing
//! (1 ms), the client.

use crate::owner::PERIOD;
use opcua::client::{EventCallback, Session};
use opcua::types::{
    AttributeId, ContentFilter, EventFilter, ExtensionObject, MonitoredItemCreateRequest,
    MonitoringMode, MonitoringParameters, NodeId, NumericRange, ObjectId, ObjectTypeId,
    QualifiedName, ReadValueId, SimpleAttributeOperand, TimestampsToReturn, Variant,
};
use plc_core::Value;
use plc_core::write::Write;
use plc_io::shm::DynSegment;
use std::sync::{Arc, Mutex};
use std::time::{Duration, SystemTime, UNIX_EPOCH};

/// Ticks (100 ns) from 1601-01-01, OPC UA's epoch, to 1970-01-01.
const UNIX_EPOCH_TICKS: i64 = 116_444_736_000_000_000;

/// The latency of the alarm's events.
pub(super) struct AlarmEvents {
    pub(super) p50: Duration,
    pub(super) p99: Duration,
    pub(super) count: usize,
}

/// Forces the bool alarm at `path` of `seg` true and releases it `toggles` times, 50 ms
/// apart, and measures its events' latency at a subscriber of the Server object.
pub(super) async fn alarm_event_latency(
    session: &Session,
    seg: &DynSegment,
    path: &str,
    toggles: usize,
) -> Result<AlarmEvents, String> {
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
            EventCallback::new(move |fields, _| {
                if let Some(Variant::DateTime(time)) = fields.as_ref().and_then(|f| f.first()) {
                    let ns = (time.ticks() - UNIX_EPOCH_TICKS).saturating_mul(100);
                    let mut l = sink.lock().unwrap_or_else(|e| e.into_inner());
                    l.push(utc_ns() - ns);
                }
            }),
        )
        .await
        .map_err(|e| format!("create subscription: {e}"))?;
    let filter = EventFilter {
        select_clauses: Some(vec![SimpleAttributeOperand {
            type_definition_id: ObjectTypeId::BaseEventType.into(),
            browse_path: Some(vec![QualifiedName::new(0, "Time")]),
            attribute_id: AttributeId::Value as u32,
            index_range: NumericRange::None,
        }]),
        where_clause: ContentFilter { elements: None },
    };
    let item = MonitoredItemCreateRequest::new(
        ReadValueId {
            node_id: NodeId::from(ObjectId::Server),
            attribute_id: AttributeId::EventNotifier as u32,
            ..Default::default()
        },
        MonitoringMode::Reporting,
        MonitoringParameters {
            client_handle: 1,
            sampling_interval: 0.0,
            filter: ExtensionObject::from_message(filter),
            queue_size: 1_000,
            discard_oldest: true,
        },
    );
    let created = session
        .create_monitored_items(subscription, TimestampsToReturn::Neither, vec![item])
        .await
        .map_err(|e| format!("create monitored item: {e}"))?;
    if created.iter().any(|c| !c.result.status_code.is_good()) {
        return Err("the event monitored item was refused".into());
    }
    let index = seg
        .index_of(path)
        .ok_or_else(|| format!("the program has no `{path}`"))?;
    let force = seg
        .check_force(Write {
            index,
            leaf: 0,
            value: Value::Bool(true),
        })
        .map_err(|e| e.to_string())?;
    for _ in 0..toggles {
        seg.force(std::slice::from_ref(&force))
            .map_err(|e| e.to_string())?;
        tokio::time::sleep(Duration::from_millis(50)).await;
        seg.release(&[(index, 0)], false)
            .map_err(|e| e.to_string())?;
        tokio::time::sleep(Duration::from_millis(50)).await;
    }
    tokio::time::sleep(Duration::from_millis(500)).await;
    let _ = session.delete_subscription(subscription).await;
    let mut l = latencies.lock().unwrap_or_else(|e| e.into_inner()).clone();
    if l.len() < toggles {
        return Err(format!("{} events of {} transitions", l.len(), 2 * toggles));
    }
    l.sort_unstable();
    let at = |q: usize| Duration::from_nanos(l[(l.len() * q / 100).min(l.len() - 1)].max(0) as u64);
    Ok(AlarmEvents {
        p50: at(50),
        p99: at(99),
        count: l.len(),
    })
}

/// The wall clock in ns since the Unix epoch.
fn utc_ns() -> i64 {
    SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| d.as_nanos() as i64)
}
