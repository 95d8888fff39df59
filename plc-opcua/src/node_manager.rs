//! A segment's node manager: async-opcua's in-memory node manager keeps the nodes and answers
//! Browse and every attribute but Value; Value reads, monitored items and writes come here and
//! go to the segment's threads, which alone touch its shared memory.

use crate::address::Layout;
use crate::alarms::{self, AlarmSpace, Registry};
use crate::mapping;
use crate::shared::{ReadJob, Shared, WriteJob};
use crate::users_file::UsersFile;
use crate::writer::log_refusal;
use opcua::server::CreateMonitoredItem;
use opcua::server::address_space::AddressSpace;
use opcua::server::diagnostics::NamespaceMetadata;
use opcua::server::node_manager::memory::{
    InMemoryNodeManager, InMemoryNodeManagerBuilder, InMemoryNodeManagerImpl,
};
use opcua::server::node_manager::{
    MonitoredItemRef, NodeManagerBuilder, ParsedReadValueId, RequestContext, ServerContext,
    WriteNode,
};
use opcua::sync::RwLock;
use opcua::types::{
    AttributeId, DataValue, MonitoringMode, NumericRange, StatusCode, TimestampsToReturn,
};
use std::sync::Arc;
use std::time::Duration;
use tokio::sync::oneshot;

/// The node manager type async-opcua builds for a segment.
pub type SegmentManager = InMemoryNodeManager<SegmentNodes>;

/// The part of a segment's node manager that plc-opcua writes.
pub struct SegmentNodes {
    shared: Arc<Shared>,
    users: Arc<UsersFile>,
    /// Writes allowed over channels without signing (`--allow-unsigned-writes`).
    unsigned_writes: bool,
    namespace: NamespaceMetadata,
}

/// The builder of a segment's node manager: registers the namespace `urn:plc-vars:<segment>`
/// and inserts the nodes of the segment's first layout, and the conditions of its alarms
/// (added to `registry`, where the condition methods find them).
pub fn builder(
    segment: String,
    first: plc_shm::LayoutDescriptor,
    period: Duration,
    users: Arc<UsersFile>,
    unsigned_writes: bool,
    registry: Arc<Registry>,
    make_shared: impl FnOnce(Layout, Arc<AlarmSpace>) -> Arc<Shared> + Send + 'static,
) -> impl NodeManagerBuilder {
    InMemoryNodeManagerBuilder::new(move |context: ServerContext, space: &mut AddressSpace| {
        let uri = mapping::namespace_uri(&segment);
        let ns = {
            let mut type_tree = context.type_tree.write();
            alarms::register_condition_id(&mut type_tree);
            type_tree.namespaces_mut().add_namespace(&uri)
        };
        space.add_namespace(&uri, ns);
        let alarms = Arc::new(AlarmSpace::new(segment.clone(), ns, &first.alarms));
        let layout = Layout::new(first, ns);
        layout.insert_into(space, &segment, period);
        alarms::nodes::insert(space, &alarms);
        registry.add(alarms.clone());
        SegmentNodes {
            shared: make_shared(layout, alarms),
            users,
            unsigned_writes,
            namespace: NamespaceMetadata {
                namespace_uri: uri,
                namespace_index: ns,
                ..Default::default()
            },
        }
    })
}

impl SegmentNodes {
    /// The shared state, for the segment's threads.
    pub fn shared(&self) -> &Arc<Shared> {
        &self.shared
    }

    /// Values of nodes already validated, from the sampler.
    async fn values(
        &self,
        items: Vec<(opcua::types::NodeId, NumericRange)>,
        timestamps: TimestampsToReturn,
    ) -> Vec<DataValue> {
        let n = items.len();
        let (reply, answer) = oneshot::channel();
        let sent = self.shared.send_read(ReadJob {
            items,
            timestamps,
            reply,
        });
        match sent {
            Some(()) => answer.await.ok(),
            None => None,
        }
        .unwrap_or_else(|| vec![mapping::status_only(StatusCode::BadServerHalted); n])
    }

    /// The status of one Write of a Value attribute.
    async fn write_one(&self, context: &RequestContext, write: &WriteNode) -> StatusCode {
        let value = write.value();
        let layout = self.shared.layout();
        let user = if context.token.is_anonymous() {
            "anonymous".to_string()
        } else {
            context.token.0.clone()
        };
        let Some(node) = layout.var(&value.node_id) else {
            return StatusCode::BadNodeIdUnknown;
        };
        let var = &node.var;
        let target = format!("{}.{}", self.shared.segment, node.path);
        let refuse = |why: &str, status| log_refusal(&user, &target, &why, status);
        if value.attribute_id != AttributeId::Value {
            return refuse(
                "only the Value attribute can be written",
                StatusCode::BadNotWritable,
            );
        }
        if !node.writable {
            return refuse(
                "the variable is read-only, an input or a status",
                StatusCode::BadNotWritable,
            );
        }
        if !crate::auth::may_write(&self.users, &context.token) {
            return refuse(
                "only users of the server's users file may write",
                StatusCode::BadUserAccessDenied,
            );
        }
        // The session's mode, as it was made (a user signs in only on a signed endpoint
        // unless unsigned writes are allowed; this holds if that ever changes).
        let mode = context.session.read().message_security_mode();
        if !crate::auth::users_allowed(mode, self.unsigned_writes) {
            return refuse(
                "writes travel over Sign or SignAndEncrypt channels only",
                StatusCode::BadSecurityModeInsufficient,
            );
        }
        let Some(variant) = value.value.value.as_ref() else {
            return refuse("the write carries no value", StatusCode::BadTypeMismatch);
        };
        let elements = mapping::written_range(var, variant, &value.index_range);
        let elements = match elements {
            Ok(e) => e,
            Err(status) => return refuse("the value does not fit the variable", status),
        };
        // What the program takes in one cycle: a larger array is written in parts (index
        // ranges), each landing whole.
        let most = plc_shm::protocol::MAX_WRITES;
        if elements.len() > most {
            return refuse(
                &format!(
                    "{} elements in one write, more than the {most} a cycle takes: write it in \
                     parts with index ranges",
                    elements.len()
                ),
                StatusCode::BadTooManyOperations,
            );
        }
        let (reply, answer) = oneshot::channel();
        let sent = self.shared.send_write(WriteJob {
            node: value.node_id.clone(),
            elements,
            user,
            reply,
        });
        match sent {
            Some(()) => answer.await.unwrap_or(StatusCode::BadServerHalted),
            None => StatusCode::BadServerHalted,
        }
    }
}

#[async_trait::async_trait]
impl InMemoryNodeManagerImpl for SegmentNodes {
    async fn init(&self, _space: &mut AddressSpace, _context: ServerContext) {}

    fn name(&self) -> &str {
        &self.namespace.namespace_uri
    }

    fn namespaces(&self) -> Vec<NamespaceMetadata> {
        vec![self.namespace.clone()]
    }

    async fn read_values(
        &self,
        context: &RequestContext,
        space: &RwLock<AddressSpace>,
        nodes: &[&ParsedReadValueId],
        _max_age: f64,
        timestamps: TimestampsToReturn,
    ) -> Vec<DataValue> {
        let mut results: Vec<Option<DataValue>> = Vec::with_capacity(nodes.len());
        let mut wanted = Vec::new();
        {
            let space = space.read();
            for node in nodes {
                match space.validate_node_read(context, node) {
                    // A condition's variable: from the mirror of the alarm table.
                    Ok(_) if alarms::parse_node_id(&node.node_id).is_some() => {
                        let value = alarms::nodes::value(&self.shared.alarms, &node.node_id)
                            .map(|dv| ranged(dv, &node.index_range, timestamps));
                        results.push(Some(value.unwrap_or_else(|| {
                            mapping::status_only(StatusCode::BadNodeIdUnknown)
                        })));
                    }
                    Ok(_) => {
                        wanted.push((node.node_id.clone(), node.index_range.clone()));
                        results.push(None);
                    }
                    Err(status) => results.push(Some(mapping::status_only(status))),
                }
            }
        }
        let mut values = self.values(wanted, timestamps).await.into_iter();
        results
            .into_iter()
            .map(|r| {
                r.or_else(|| values.next())
                    .unwrap_or_else(|| mapping::status_only(StatusCode::BadInternalError))
            })
            .collect()
    }

    async fn create_value_monitored_items(
        &self,
        context: &RequestContext,
        space: &RwLock<AddressSpace>,
        items: &mut [&mut &mut CreateMonitoredItem],
    ) {
        // The long queue is for events (alarm clients): a value's item keeps 10 at most.
        for item in items.iter_mut() {
            item.revise_queue_size(alarms::VALUE_QUEUE);
        }
        let to_read: Vec<_> = items.iter().map(|i| i.item_to_monitor()).collect();
        let values = self
            .read_values(context, space, &to_read, 0.0, TimestampsToReturn::Both)
            .await;
        for (value, item) in values.into_iter().zip(items.iter_mut()) {
            let status = value.status();
            if matches!(
                status,
                StatusCode::BadNodeIdUnknown | StatusCode::BadUserAccessDenied
            ) {
                item.set_status(status);
                continue;
            }
            item.set_initial_value(value);
            item.set_status(StatusCode::Good);
            // As the server revised it (never below the program's period).
            let ms = item.sampling_interval();
            let interval = if ms.is_finite() && ms > 0.0 {
                Duration::from_secs_f64((ms / 1000.0).min(3600.0))
            } else {
                Duration::ZERO
            };
            let sampling = item.monitoring_mode() != MonitoringMode::Disabled;
            self.shared.monitor(
                item.handle(),
                &item.item_to_monitor().node_id,
                sampling,
                interval,
            );
        }
    }

    async fn set_monitoring_mode(
        &self,
        _context: &RequestContext,
        mode: MonitoringMode,
        items: &[&MonitoredItemRef],
    ) {
        // A Disabled item is not sampled (async-opcua also stops its notifications).
        for item in items {
            if item.attribute() == AttributeId::Value {
                self.shared
                    .set_sampling(item.handle(), mode != MonitoringMode::Disabled);
            }
        }
    }

    async fn delete_monitored_items(&self, _context: &RequestContext, items: &[&MonitoredItemRef]) {
        for item in items {
            if item.attribute() == AttributeId::Value {
                self.shared.unmonitor(item.handle());
            }
        }
    }

    async fn write(
        &self,
        context: &RequestContext,
        _space: &RwLock<AddressSpace>,
        nodes_to_write: &mut [&mut WriteNode],
    ) -> Result<(), StatusCode> {
        for write in nodes_to_write {
            let status = self.write_one(context, write).await;
            write.set_status(status);
        }
        Ok(())
    }
}

/// A condition variable's value with an index range and the timestamps asked for applied.
fn ranged(mut dv: DataValue, range: &NumericRange, timestamps: TimestampsToReturn) -> DataValue {
    if *range != NumericRange::None {
        match dv.value.as_ref().map(|v| v.range_of(range)) {
            Some(Ok(v)) => dv.value = Some(v),
            Some(Err(status)) => return mapping::status_only(status),
            None => {}
        }
    }
    mapping::keep_timestamps(dv, timestamps)
}
