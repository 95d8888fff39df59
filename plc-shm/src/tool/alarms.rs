//! A program's alarms from a tool: their declarations (the descriptor's list), their states
//! (the segment's alarm table), and operators' actions on them over the segment's socket,
//! which the owner checks against the write policy like writes.

use super::dynamic::DynSegment;
use crate::error::ShmError;
use crate::format::alarm_descriptor::AlarmDescriptor;
use crate::format::alarm_table::{self, AlarmEntry, TableError};
use crate::limits::MAX_WRITES;
use crate::protocol::{self, AlarmAction, AlarmRequest, Code};

impl DynSegment {
    /// The alarms the program declares, in the order of [`alarm_states`](Self::alarm_states).
    pub fn alarms(&self) -> &[AlarmDescriptor] {
        &self.descriptor().alarms
    }

    /// The number of the alarm at `path` (`door`, `stations[2].door`; letters in any case),
    /// or an error saying whether the path is a variable without an alarm.
    pub fn alarm_number(&self, path: &str) -> Result<usize, ShmError> {
        let wanted = path.trim();
        self.alarms()
            .iter()
            .position(|a| a.path.eq_ignore_ascii_case(wanted))
            .ok_or_else(|| ShmError::UnknownAlarm {
                name: self.name().to_string(),
                path: path.to_string(),
                is_variable: self.locate(wanted).is_ok(),
            })
    }

    /// Every alarm's state now, in the order of [`alarms`](Self::alarms).
    ///
    /// ```no_run
    /// let seg = plc_shm::DynSegment::attach("tensile_tester")?;
    /// for (alarm, state) in seg.alarms().iter().zip(seg.alarm_states()?) {
    ///     if state.state.unacknowledged() {
    ///         println!("{}: {} ({})", alarm.path, alarm.text, state.state);
    ///     }
    /// }
    /// # Ok::<(), plc_shm::ShmError>(())
    /// ```
    pub fn alarm_states(&self) -> Result<Vec<AlarmEntry>, ShmError> {
        self.view.check_owner()?;
        alarm_table::read(&self.view.base, &self.view.alarms).map_err(|e| match e {
            TableError::Busy => ShmError::Stuck(self.name().into()),
            TableError::Damaged { alarm } => ShmError::Corrupt {
                name: self.name().into(),
                why: format!("its alarm table holds no state for alarm {alarm}"),
            },
        })
    }

    /// Does `action` to the alarms numbered `alarms` (at most [`MAX_WRITES`]), all or none,
    /// as this tool's user (who may is the write policy's), with the operator's `comment`
    /// and, for a tool that acts for a user signed in elsewhere, that user's name. Returns
    /// once the program took it (the alarm table shows it then), or with its refusal.
    ///
    /// ```no_run
    /// use plc_shm::protocol::AlarmAction;
    /// let seg = plc_shm::DynSegment::attach("tensile_tester")?;
    /// let door = seg.alarm_number("guard_door_open")?;
    /// seg.act_on_alarms(AlarmAction::Acknowledge, &[door], "door closed again", "")?;
    /// # Ok::<(), plc_shm::ShmError>(())
    /// ```
    pub fn act_on_alarms(
        &self,
        action: AlarmAction,
        alarms: &[usize],
        comment: &str,
        on_behalf: &str,
    ) -> Result<(), ShmError> {
        self.view.count_ok(alarms.len(), MAX_WRITES, "alarms")?;
        self.send_alarm_request(action, false, alarms, comment, on_behalf)
    }

    /// Does `action` to every alarm it applies to (acknowledge every unacknowledged one,
    /// reset every latched one that may be reset, ...); refused if it applies to none.
    pub fn act_on_all_alarms(
        &self,
        action: AlarmAction,
        comment: &str,
        on_behalf: &str,
    ) -> Result<(), ShmError> {
        self.send_alarm_request(action, true, &[], comment, on_behalf)
    }

    fn send_alarm_request(
        &self,
        action: AlarmAction,
        all: bool,
        alarms: &[usize],
        comment: &str,
        on_behalf: &str,
    ) -> Result<(), ShmError> {
        let ticket = self.view.post_with(|id| {
            protocol::encode_alarm(&AlarmRequest {
                id,
                action,
                all,
                comment: comment.to_string(),
                on_behalf: on_behalf.to_string(),
                alarms: alarms.to_vec(),
            })
        })?;
        let reply = self.view.wait_reply(ticket)?;
        if reply.code != Code::Rejected {
            let names: Vec<String> = Vec::new();
            return super::client::answer_result(self.name(), &names, reply);
        }
        let alarm = match alarms.get(usize::from(reply.which)) {
            Some(&n) => self
                .alarms()
                .get(n)
                .map_or_else(|| format!("number {n}"), |a| a.path.clone()),
            None => "*".to_string(),
        };
        Err(ShmError::AlarmRefused {
            name: self.name().to_string(),
            alarm,
            action: action.verb(),
            reason: reply.reason,
        })
    }
}
