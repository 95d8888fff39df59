//! What travels from the cycle and the journal's owner to its writer thread: a transition, an
//! operator's action, a flush or the stop. Its own file because both queues carry it (the
//! cycle's [`Handoff`](super::handoff::Handoff) and the writer's control channel).

use super::record::Operator;
use plc_core::alarm::AlarmEvent;
use std::sync::Arc;
use std::sync::mpsc::SyncSender;

/// What goes through the queue. An evaluator's transition is plain data and the path table is
/// shared, so handing one over allocates nothing.
pub(super) enum Msg {
    Event {
        paths: Arc<[String]>,
        event: AlarmEvent,
        value: f64,
    },
    Action {
        paths: Arc<[String]>,
        event: AlarmEvent,
        by: Box<Operator>,
    },
    /// Answer once everything before is on disk (on the control channel).
    Flush(SyncSender<()>),
    Stop,
}
