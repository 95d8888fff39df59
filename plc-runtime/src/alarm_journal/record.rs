//! What one journal record says: [`Record`] (sequence number, the cycle's UTC time, the
//! alarm's path) and [`Entry`], the transition, made from plc-core's [`EventKind`] plus who did
//! an operator's action ([`Operator`]).

use plc_core::alarm::{AlarmEvent, EventKind, Level};
use serde::{Deserialize, Serialize};

/// The longest path, user name and comment kept, in bytes: longer ones are cut at a character
/// boundary, so that every line stays under [`MAX_LINE`](super::MAX_LINE) and a reader can
/// refuse anything longer as damage.
pub(super) const MAX_PATH: usize = 512;
pub(super) const MAX_USER: usize = 64;
pub(super) const MAX_COMMENT: usize = 512;

/// One line of the journal: a transition of one alarm.
///
/// ```
/// use plc_runtime::alarm_journal::{Entry, Record};
/// use plc_core::alarm::Level;
/// let r = Record {
///     seq: 7,
///     time_ns: 1_764_950_400_000_000_000,
///     path: "oil".into(),
///     entry: Entry::Raised { level: Level::HighHigh, value: Some(96.5) },
/// };
/// assert_eq!(r.entry.name(), "raised");
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Record {
    /// Numbered from 1, one more for each record written, across restarts: a gap is a record
    /// lost (damaged, or dropped by the bound).
    pub seq: u64,
    /// UTC nanoseconds since 1970: the cycle's time (or the operator's action's).
    #[serde(rename = "t")]
    pub time_ns: i64,
    /// The alarm, named by the path of the value it watches (`stations[2].door`); empty for a
    /// [`Entry::Summarised`] record, which is about no one alarm.
    pub path: String,
    /// What happened.
    #[serde(flatten)]
    pub entry: Entry,
}

/// Who did an operator's action.
///
/// ```
/// use plc_runtime::alarm_journal::Operator;
/// let anna = Operator::new(Some(1000), "anna").with_comment("pump checked");
/// assert_eq!(anna.comment.as_deref(), Some("pump checked"));
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Operator {
    /// The user id of a local user (over the owner's socket); `None` for one signed in
    /// elsewhere (OPC UA).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub uid: Option<u32>,
    /// The user's name.
    pub user: String,
    /// What the operator wrote with the action.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub comment: Option<String>,
}

impl Operator {
    /// User `user` (uid `uid` if local), without comment.
    pub fn new(uid: Option<u32>, user: impl Into<String>) -> Operator {
        Operator {
            uid,
            user: user.into(),
            comment: None,
        }
    }

    /// With a comment.
    pub fn with_comment(mut self, comment: impl Into<String>) -> Operator {
        self.comment = Some(comment.into());
        self
    }

    /// Cut to the lengths the journal keeps, control characters made spaces.
    pub(super) fn bounded(&self) -> Operator {
        Operator {
            uid: self.uid,
            user: bounded(&self.user, MAX_USER),
            comment: self.comment.as_deref().map(|c| bounded(c, MAX_COMMENT)),
        }
    }
}

/// A transition, as the journal records it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "ev", rename_all = "snake_case")]
pub enum Entry {
    /// Active at `level`, unacknowledged; `value` the value that raised it (none for a value
    /// that is not a number).
    Raised {
        /// `active` for a bool, a limit's level for a number.
        #[serde(with = "level")]
        level: Level,
        /// The value.
        value: Option<f64>,
    },
    /// A limit alarm moved between levels while active.
    LevelChanged {
        /// The level before.
        #[serde(with = "level")]
        from: Level,
        /// The level now.
        #[serde(with = "level")]
        to: Level,
        /// The value.
        value: Option<f64>,
    },
    /// Returned to normal.
    Cleared {
        /// The level it was at.
        #[serde(with = "level")]
        from: Level,
        /// The value.
        value: Option<f64>,
    },
    /// A latched alarm's condition cleared: it holds at `level` until reset.
    ConditionCleared {
        /// The level it holds.
        #[serde(with = "level")]
        level: Level,
        /// The value.
        value: Option<f64>,
    },
    /// Acknowledged by an operator.
    Acknowledged {
        /// Who.
        by: Operator,
    },
    /// A latched alarm reset by an operator.
    Reset {
        /// Who.
        by: Operator,
    },
    /// Shelved by an operator until `until_ns` (UTC nanoseconds).
    Shelved {
        /// Who.
        by: Operator,
        /// When it comes back by itself.
        until_ns: i64,
    },
    /// Off the shelf: by an operator, or (`by` none) because the shelf expired.
    Unshelved {
        /// Who, if an operator did it.
        #[serde(default)]
        by: Option<Operator>,
    },
    /// Its `suppress_when` bool became true.
    Suppressed,
    /// Its `suppress_when` bool became false.
    Unsuppressed,
    /// Transitions that were not recorded one by one (a flood filled the queue, or the
    /// writer's budget per second was spent, or a write failed): only counted, here.
    Summarised {
        /// Transitions of the evaluator not recorded.
        transitions: u64,
        /// Operator actions not recorded.
        actions: u64,
    },
}

impl Entry {
    /// The name the file and tools give it: `raised`, `acknowledged`, ...
    pub fn name(&self) -> &'static str {
        match self {
            Entry::Raised { .. } => "raised",
            Entry::LevelChanged { .. } => "level_changed",
            Entry::Cleared { .. } => "cleared",
            Entry::ConditionCleared { .. } => "condition_cleared",
            Entry::Acknowledged { .. } => "acknowledged",
            Entry::Reset { .. } => "reset",
            Entry::Shelved { .. } => "shelved",
            Entry::Unshelved { .. } => "unshelved",
            Entry::Suppressed => "suppressed",
            Entry::Unsuppressed => "unsuppressed",
            Entry::Summarised { .. } => "summarised",
        }
    }

    /// The entry of an evaluator's event: `value` the alarm's value in that cycle (NaN for
    /// none), `by` the operator for an action (acknowledge, reset, shelve, unshelve).
    ///
    /// ```
    /// use plc_core::alarm::{AlarmEvent, EventKind};
    /// use plc_runtime::alarm_journal::{Entry, Operator};
    /// let ack = AlarmEvent { alarm: 0, time_ns: 5, kind: EventKind::Acknowledged };
    /// let e = Entry::from_event(&ack, f64::NAN, Some(Operator::new(Some(0), "root")));
    /// assert_eq!(e.name(), "acknowledged");
    /// ```
    pub fn from_event(event: &AlarmEvent, value: f64, by: Option<Operator>) -> Entry {
        let value = value.is_finite().then_some(value);
        // An action without its operator (a caller that did not say) is still recorded, by
        // nobody named.
        let by_or_unknown = |by: Option<Operator>| by.unwrap_or_else(|| Operator::new(None, ""));
        match event.kind {
            EventKind::Raised { level } => Entry::Raised { level, value },
            EventKind::LevelChanged { from, to } => Entry::LevelChanged { from, to, value },
            EventKind::Cleared { from } => Entry::Cleared { from, value },
            EventKind::ConditionCleared { level } => Entry::ConditionCleared { level, value },
            EventKind::Acknowledged => Entry::Acknowledged {
                by: by_or_unknown(by),
            },
            EventKind::Reset => Entry::Reset {
                by: by_or_unknown(by),
            },
            EventKind::Shelved { until_ns } => Entry::Shelved {
                by: by_or_unknown(by),
                until_ns,
            },
            EventKind::Unshelved { expired } => Entry::Unshelved {
                by: if expired {
                    None
                } else {
                    Some(by_or_unknown(by))
                },
            },
            EventKind::Suppressed => Entry::Suppressed,
            EventKind::Unsuppressed => Entry::Unsuppressed,
        }
    }
}

/// `text` cut to at most `max` bytes at a character boundary, control characters (which
/// would be escaped six times longer, and could fake lines on a terminal) made spaces.
pub(super) fn bounded(text: &str, max: usize) -> String {
    let mut end = text.len().min(max);
    while !text.is_char_boundary(end) {
        end -= 1;
    }
    text[..end]
        .chars()
        .map(|c| if c.is_control() { ' ' } else { c })
        .collect()
}

/// A level by the name tools show (`high-high`), as plc-core names them.
pub(super) fn level_by_name(name: &str) -> Option<Level> {
    Level::ALL.into_iter().find(|l| l.name() == name)
}

/// Levels written by name (`"high-high"`), as tools show them.
pub(super) mod level {
    use plc_core::alarm::Level;
    use serde::{Deserialize, Deserializer, Serializer, de::Error};

    pub fn serialize<S: Serializer>(l: &Level, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(l.name())
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Level, D::Error> {
        // Owned: a flattened record is buffered before its fields are read.
        let name = String::deserialize(d)?;
        super::level_by_name(&name).ok_or_else(|| D::Error::custom(format!("no level `{name}`")))
    }
}
