//! The condition methods clients call: Acknowledge (AcknowledgeableConditionType, by EventId
//! with a comment) and ConditionRefresh / ConditionRefresh2 (ConditionType). All three are
//! methods of namespace 0, so [`super::front`] passes them here from the core node manager.
//!
//! Acknowledging is acting on the plant's alarms: like a write, only users of the users file
//! signed in over Sign or SignAndEncrypt may (anonymous sessions: BadUserAccessDenied; a
//! channel without signing: BadSecurityModeInsufficient, unless `--allow-unsigned-writes`). The
//! acknowledgement goes to the program through the segment's socket with the user's name,
//! which the program's alarm journal records.

use super::events::{AlarmEvent, RefreshEvent};
use super::{AckJob, Registry, ack_refusal, nodes};
use crate::users_file::UsersFile;
use opcua::server::node_manager::{MethodCall, RequestContext};
use opcua::types::{AttributeId, MethodId, NodeId, ObjectId, StatusCode, Variant};
use plc_shm::LogLimit;
use std::sync::Arc;
use std::time::Duration;
use tokio::sync::oneshot;

/// The longest an Acknowledge waits for the program (its socket has its own, shorter limit).
const ACK_TIMEOUT: Duration = Duration::from_secs(10);

/// The most event monitored items of one subscription a ConditionRefresh refreshes: each gets
/// every retained condition, so a subscription of thousands of event items cannot make one
/// call cost millions of filter evaluations.
pub const REFRESH_ITEMS: usize = 16;

/// Refused acknowledgements, logged at a bounded rate.
static REFUSED: LogLimit = LogLimit::new("plc_opcua::alarms");

/// Who may acknowledge, and the segments' alarms.
pub struct AlarmMethods {
    registry: Arc<Registry>,
    users: Arc<UsersFile>,
    unsigned_writes: bool,
}

/// The methods this handler answers.
pub fn handles(method: &NodeId) -> bool {
    matches!(
        method.as_method_id(),
        Ok(MethodId::AcknowledgeableConditionType_Acknowledge
            | MethodId::ConditionType_ConditionRefresh
            | MethodId::ConditionType_ConditionRefresh2)
    )
}

/// `text` cut to at most `max` bytes at a character's boundary.
fn cut(text: &str, max: usize) -> &str {
    let mut end = text.len().min(max);
    while !text.is_char_boundary(end) {
        end -= 1;
    }
    &text[..end]
}

impl AlarmMethods {
    /// The handler for `registry`'s segments; users of `users` may acknowledge
    /// (`unsigned_writes`: over None too).
    pub fn new(registry: Arc<Registry>, users: Arc<UsersFile>, unsigned_writes: bool) -> Self {
        AlarmMethods {
            registry,
            users,
            unsigned_writes,
        }
    }

    /// Answers one call of a method [`handles`] accepts.
    pub async fn call(&self, context: &RequestContext, call: &mut MethodCall) {
        let status = match call.method_id().as_method_id() {
            Ok(MethodId::AcknowledgeableConditionType_Acknowledge) => {
                self.acknowledge(context, call).await
            }
            Ok(MethodId::ConditionType_ConditionRefresh2) => self.refresh(context, call, true),
            _ => self.refresh(context, call, false),
        };
        call.set_status(status);
    }

    async fn acknowledge(&self, context: &RequestContext, call: &mut MethodCall) -> StatusCode {
        let args = call.arguments();
        match args.len() {
            0 | 1 => return StatusCode::BadArgumentsMissing,
            2 => {}
            _ => return StatusCode::BadTooManyArguments,
        }
        let event_id = match &args[0] {
            Variant::ByteString(b) => Some(b.clone()),
            _ => None,
        };
        let comment = match &args[1] {
            Variant::LocalizedText(t) => Some(cut(t.text.as_ref(), 255).to_string()),
            Variant::Empty => Some(String::new()),
            _ => None,
        };
        let (Some(event_id), Some(comment)) = (event_id, comment) else {
            let status = |ok: bool| {
                if ok {
                    StatusCode::Good
                } else {
                    StatusCode::BadTypeMismatch
                }
            };
            let results = vec![
                status(matches!(args[0], Variant::ByteString(_))),
                status(matches!(
                    args[1],
                    Variant::LocalizedText(_) | Variant::Empty
                )),
            ];
            call.set_argument_error(results);
            return StatusCode::BadInvalidArgument;
        };
        let object = call.object_id().clone();
        let Some(alarms) = self.registry.by_namespace(object.namespace) else {
            return StatusCode::BadNodeIdUnknown;
        };
        let user = if context.token.is_anonymous() {
            "anonymous".to_string()
        } else {
            context.token.0.clone()
        };
        let (number, path, current, waiting) = {
            let table = alarms.table();
            let Some(c) = table.by_node(&object) else {
                return StatusCode::BadNodeIdUnknown;
            };
            (
                c.number,
                c.path.clone(),
                c.event_id.clone(),
                c.entry.state.unacknowledged(),
            )
        };
        let target = format!("{}.{path}", alarms.segment);
        let refuse = |why: &str, status: StatusCode| {
            REFUSED.warn(|| {
                format!("OPC UA acknowledgement by `{user}` refused: {target}: {why} ({status})")
            });
            status
        };
        if !crate::auth::may_write(&self.users, &context.token) {
            return refuse(
                "only users of the server's users file may acknowledge",
                StatusCode::BadUserAccessDenied,
            );
        }
        let mode = context.session.read().message_security_mode();
        if !crate::auth::users_allowed(mode, self.unsigned_writes) {
            return refuse(
                "acknowledgements travel over Sign or SignAndEncrypt channels only",
                StatusCode::BadSecurityModeInsufficient,
            );
        }
        if event_id != current {
            return refuse(
                "the EventId is not the condition's last event",
                StatusCode::BadEventIdUnknown,
            );
        }
        if !waiting {
            return refuse(
                "nothing waits for an acknowledgement",
                StatusCode::BadConditionBranchAlreadyAcked,
            );
        }
        let (reply, answer) = oneshot::channel();
        let job = AckJob {
            number,
            comment: comment.clone(),
            user: user.clone(),
            reply,
        };
        if let Err(status) = alarms.send_ack(job) {
            return refuse("the server cannot take more acknowledgements now", status);
        }
        match tokio::time::timeout(ACK_TIMEOUT, answer).await {
            Ok(Ok(Ok(()))) => {
                // Debug-quoted: a comment cannot forge log lines.
                log::info!("OPC UA acknowledgement by `{user}`: {target}: {comment:?}");
                StatusCode::Good
            }
            Ok(Ok(Err(e))) => refuse(&e.to_string(), ack_refusal(&e)),
            Ok(Err(_)) => StatusCode::BadServerHalted,
            Err(_) => refuse("the program did not answer", StatusCode::BadTimeout),
        }
    }

    /// ConditionRefresh (subscription) or ConditionRefresh2 (subscription, monitored item):
    /// the calling session's subscription alone gets a RefreshStartEvent, the retained
    /// conditions of the segments its event items watch, and a RefreshEndEvent.
    fn refresh(&self, context: &RequestContext, call: &mut MethodCall, two: bool) -> StatusCode {
        let wanted = if two { 2 } else { 1 };
        let args = call.arguments();
        if args.len() < wanted {
            return StatusCode::BadArgumentsMissing;
        }
        if args.len() > wanted {
            return StatusCode::BadTooManyArguments;
        }
        let ids: Vec<Option<u32>> = args
            .iter()
            .map(|a| match a {
                Variant::UInt32(v) => Some(*v),
                _ => None,
            })
            .collect();
        if ids.iter().any(Option::is_none) {
            let results = ids
                .iter()
                .map(|i| {
                    if i.is_some() {
                        StatusCode::Good
                    } else {
                        StatusCode::BadTypeMismatch
                    }
                })
                .collect();
            call.set_argument_error(results);
            return StatusCode::BadInvalidArgument;
        }
        let subscription = ids[0].unwrap_or_default();
        let item = ids.get(1).copied().flatten();
        // The events first, without the subscriptions' lock (the alarm threads notify while
        // holding none of the tables).
        let spaces: Vec<(NodeId, Vec<AlarmEvent>)> = self
            .registry
            .all()
            .iter()
            .map(|s| {
                let table = s.table();
                let quality = nodes::quality(table.connected);
                let retained = table.conditions.iter().filter(|c| c.retain());
                let events = retained
                    .map(|c| AlarmEvent::new(c.clone(), quality))
                    .collect();
                (s.program_node(), events)
            })
            .collect();
        let Some(subs) = context
            .subscriptions
            .get_session_subscriptions(context.session_id)
        else {
            return StatusCode::BadSubscriptionIdInvalid;
        };
        let mut subs = subs.lock();
        let Some(sub) = subs.get_mut(subscription) else {
            return StatusCode::BadSubscriptionIdInvalid;
        };
        let server = NodeId::from(ObjectId::Server);
        let items: Vec<(u32, NodeId)> = sub
            .items()
            .filter(|i| i.item_to_monitor().attribute_id == AttributeId::EventNotifier)
            .filter(|i| item.is_none_or(|wanted| i.id() == wanted))
            .map(|i| (i.id(), i.item_to_monitor().node_id.clone()))
            .take(REFRESH_ITEMS)
            .collect();
        if item.is_some() && items.is_empty() {
            return StatusCode::BadMonitoredItemIdInvalid;
        }
        let type_tree = context.get_type_tree_for_user();
        let type_tree = type_tree.get();
        let mark = |start| RefreshEvent::new(start, self.registry.next_event_id());
        for (id, node) in items {
            sub.notify_event(&id, &mark(true), type_tree);
            for (program, events) in &spaces {
                if node == server || node == *program {
                    for e in events {
                        sub.notify_event(&id, e, type_tree);
                    }
                }
            }
            sub.notify_event(&id, &mark(false), type_tree);
        }
        StatusCode::Good
    }
}
