//! What the evaluator reports: an alarm's state as IEC 62682 names it ([`AlarmState`]), each
//! transition as a plain [`AlarmEvent`], and why an operator's action was refused
//! ([`ActionError`]).

use super::decl::Level;
use crate::Time;
use core::fmt;
use std::string::String;

/// An alarm's state, as IEC 62682's state diagram names them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AlarmState {
    /// The condition does not hold and nothing waits for an operator.
    Normal,
    /// Active, not yet acknowledged.
    ActiveUnacknowledged,
    /// Active and acknowledged.
    ActiveAcknowledged,
    /// The condition has cleared, but nobody acknowledged the alarm.
    ReturnedUnacknowledged,
    /// A latched alarm whose condition has cleared: it stays until reset.
    Latched {
        /// Whether it was acknowledged.
        acknowledged: bool,
    },
    /// Shelved by an operator: not shown until unshelved or the shelf expires.
    Shelved,
    /// Suppressed by design: its `suppress_when` bool is true (the equipment is out of
    /// service).
    SuppressedByDesign,
}

impl AlarmState {
    /// The name tools show: `normal`, `active unacknowledged`, ...
    pub const fn name(self) -> &'static str {
        match self {
            AlarmState::Normal => "normal",
            AlarmState::ActiveUnacknowledged => "active unacknowledged",
            AlarmState::ActiveAcknowledged => "active acknowledged",
            AlarmState::ReturnedUnacknowledged => "returned to normal unacknowledged",
            AlarmState::Latched {
                acknowledged: false,
            } => "latched unacknowledged",
            AlarmState::Latched { acknowledged: true } => "latched acknowledged",
            AlarmState::Shelved => "shelved",
            AlarmState::SuppressedByDesign => "suppressed by design",
        }
    }

    /// Whether an operator still has to acknowledge it.
    pub const fn unacknowledged(self) -> bool {
        matches!(
            self,
            AlarmState::ActiveUnacknowledged
                | AlarmState::ReturnedUnacknowledged
                | AlarmState::Latched {
                    acknowledged: false
                }
        )
    }
}

impl fmt::Display for AlarmState {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// What happened to an alarm.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum EventKind {
    /// Its condition held (for its delay): it is active at `level`, unacknowledged.
    Raised {
        /// `active` for a bool, a limit's level for a number.
        level: Level,
    },
    /// A limit alarm moved between levels while active (to a more urgent one it is
    /// unacknowledged again).
    LevelChanged {
        /// The level before.
        from: Level,
        /// The level now.
        to: Level,
    },
    /// Its condition cleared: it returned to normal (unacknowledged if nobody acknowledged
    /// it).
    Cleared {
        /// The level it was at.
        from: Level,
    },
    /// A latched alarm's condition cleared: it stays until reset.
    ConditionCleared {
        /// The level it stays at.
        level: Level,
    },
    /// An operator acknowledged it.
    Acknowledged,
    /// An operator reset a latched alarm (which acknowledges it).
    Reset,
    /// An operator shelved it until `until_ns`.
    Shelved {
        /// When it comes back by itself, UTC nanoseconds.
        until_ns: i64,
    },
    /// It came off the shelf: by an operator, or because the shelf expired.
    Unshelved {
        /// Whether the shelf expired (else an operator unshelved it).
        expired: bool,
    },
    /// Its `suppress_when` bool became true.
    Suppressed,
    /// Its `suppress_when` bool became false.
    Unsuppressed,
}

/// One transition, with the UTC time of the cycle (or the action) it happened in.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AlarmEvent {
    /// The alarm's number: its place in the declaration's table.
    pub alarm: usize,
    /// UTC nanoseconds since 1970.
    pub time_ns: i64,
    /// What happened.
    pub kind: EventKind,
}

/// Who shelved an alarm, and for how long.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Shelf {
    /// The operator.
    pub by: String,
    /// When, UTC nanoseconds.
    pub since_ns: i64,
    /// When it comes back by itself, UTC nanoseconds.
    pub until_ns: i64,
}

/// What an alarm's state is made of, to keep it across a restart or an online change (the
/// journal's part): [`Alarms::snapshot`](super::Alarms::snapshot) and
/// [`Alarms::restore`](super::Alarms::restore). Suppression is not in it: it follows its bool
/// from the first cycle.
#[derive(Clone, Debug, PartialEq)]
pub struct Snapshot {
    /// The level annunciated (`normal` while not active).
    pub level: Level,
    /// Whether nothing waits for an acknowledgement.
    pub acknowledged: bool,
    /// A latched alarm whose condition cleared, waiting for its reset.
    pub held: bool,
    /// Its shelf, while shelved.
    pub shelf: Option<Shelf>,
    /// When it last changed state, UTC nanoseconds.
    pub since_ns: i64,
}

/// Why an operator's action was refused. Nothing changed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ActionError {
    /// No alarm has this number.
    Unknown {
        /// The number given.
        alarm: usize,
    },
    /// Nothing waits for an acknowledgement.
    NotUnacknowledged,
    /// Only a latched alarm is reset.
    NotLatched,
    /// A latched alarm whose condition still holds cannot be reset.
    StillActive,
    /// A latched alarm that is not holding: nothing to reset.
    NotHeld,
    /// A shelf of no time, or longer than allowed.
    ShelveDuration {
        /// The longest shelf allowed.
        max: Time,
    },
    /// It is not shelved.
    NotShelved,
}

impl fmt::Display for ActionError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ActionError::Unknown { alarm } => write!(f, "no alarm has number {alarm}"),
            ActionError::NotUnacknowledged => f.write_str("the alarm waits for no acknowledgement"),
            ActionError::NotLatched => {
                f.write_str("the alarm is not latched: it clears by itself, nothing to reset")
            }
            ActionError::StillActive => f.write_str(
                "the alarm is still active: a latched alarm is reset once its condition has \
                 cleared",
            ),
            ActionError::NotHeld => {
                f.write_str("the latched alarm is not holding: nothing to reset")
            }
            ActionError::ShelveDuration { max } => {
                write!(f, "an alarm is shelved for more than 0 and at most {max}")
            }
            ActionError::NotShelved => f.write_str("the alarm is not shelved"),
        }
    }
}

impl std::error::Error for ActionError {}
