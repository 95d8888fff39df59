//! `opcua_read_10k_ms`: the median time of one Read request of the variable nodes, every
//! value checked Good.

use opcua::client::Session;
use opcua::types::{DataValue, NodeId, ReadValueId, TimestampsToReturn};
use std::time::{Duration, Instant};

/// The median time of one Read of `nodes`, each value checked Good.
pub(super) async fn read_all(
    session: &Session,
    nodes: &[NodeId],
    runs: usize,
) -> Result<Duration, String> {
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
