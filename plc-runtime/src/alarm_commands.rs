//! Operators' actions on alarms from tools (`plc ack`, `plc shelve`, the OPC UA server's
//! Acknowledge), as the cycle thread takes them from the segment's socket: the alarms named,
//! all or none, or every alarm the action applies to.

use crate::alarm_journal::Operator;
use crate::alarms::RuntimeAlarms;
use plc_core::Time;
use plc_core::alarm::{ActionError, AlarmEvent, Alarms};
use plc_shm::protocol::AlarmAction;
use plc_shm::{AlarmCommand, AlarmRefusal};

impl RuntimeAlarms {
    /// Takes `command`: the alarms it names are tried first on a copy of their states, so
    /// that a refusal of one leaves every one as it was; `all` does the action to each alarm
    /// it applies to, and is refused if there is none.
    pub(crate) fn command(&mut self, command: &AlarmCommand) -> Result<(), AlarmRefusal> {
        let now = self.now_ns();
        let action = command.action;
        let by = operator(command);
        let step = |a: &mut Alarms, i: usize, user: &str| -> Result<AlarmEvent, ActionError> {
            match action {
                AlarmAction::Acknowledge => a.acknowledge(i, now),
                AlarmAction::Reset => a.reset(i, now),
                AlarmAction::Shelve { for_ns } => a.shelve(i, now, Time::from_nanos(for_ns), user),
                AlarmAction::Unshelve => a.unshelve(i, now),
            }
        };
        if command.all {
            let mut done = 0;
            for i in 0..self.len() {
                done += usize::from(self.act_on(i, &by, step).is_ok());
            }
            self.recount();
            return match done {
                0 => Err(AlarmRefusal {
                    which: 0,
                    why: format!("no alarm to {}", action.verb()),
                }),
                _ => Ok(()),
            };
        }
        // Operators' actions are rare: a copy of the states per request is cheap enough, and
        // it makes the request all or none.
        let mut trial = self.evaluator().clone();
        for (k, &i) in command.alarms.iter().enumerate() {
            step(&mut trial, i, &by.user).map_err(|e| AlarmRefusal {
                which: k,
                why: e.to_string(),
            })?;
        }
        for &i in &command.alarms {
            // The trial took each: the same steps on the same states take them again.
            let _ = self.act_on(i, &by, step);
        }
        self.recount();
        Ok(())
    }
}

/// Who acts: the tool's user, or the user it acts for (signed in elsewhere), with the
/// operator's comment.
fn operator(command: &AlarmCommand) -> Operator {
    let by = match &command.on_behalf {
        Some(user) => Operator::new(None, user.clone()),
        None => Operator::new(Some(command.uid), command.user.clone()),
    };
    match &command.comment {
        Some(c) => by.with_comment(c.clone()),
        None => by,
    }
}
