//! What a declaration says of one alarm: which basic value it watches, its text, condition
//! (a bool's active level, or a number's limits with a deadband), on-delay, latching,
//! severity and what suppresses it. Plain `Copy` data, built at compile time by the derive.

use crate::Time;
use core::fmt;

/// The level a limit alarm is at, or whether a bool alarm is active. Ordered by urgency on
/// each side: [`rank`](Self::rank) 0 for normal, 1 for `low`/`high`/`active`, 2 for
/// `low-low`/`high-high`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum Level {
    /// The condition does not hold.
    Normal,
    /// A bool alarm's condition holds.
    Active,
    /// At or below `low`.
    Low,
    /// At or below `low_low`.
    LowLow,
    /// At or above `high`.
    High,
    /// At or above `high_high`.
    HighHigh,
}

impl Level {
    /// Every level, in this order (a table's code of a level is its place here).
    pub const ALL: [Level; 6] = [
        Level::Normal,
        Level::Active,
        Level::Low,
        Level::LowLow,
        Level::High,
        Level::HighHigh,
    ];

    /// 0 for normal, 1 for a first level (`active`, `low`, `high`), 2 for a second.
    pub const fn rank(self) -> u8 {
        match self {
            Level::Normal => 0,
            Level::Active | Level::Low | Level::High => 1,
            Level::LowLow | Level::HighHigh => 2,
        }
    }

    /// The name tools show: `normal`, `active`, `low`, `low-low`, `high`, `high-high`.
    pub const fn name(self) -> &'static str {
        match self {
            Level::Normal => "normal",
            Level::Active => "active",
            Level::Low => "low",
            Level::LowLow => "low-low",
            Level::High => "high",
            Level::HighHigh => "high-high",
        }
    }
}

impl fmt::Display for Level {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The limits of an alarm on a number. A missing limit is never reached.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Limits {
    /// The second level below.
    pub low_low: Option<f64>,
    /// The first level below.
    pub low: Option<f64>,
    /// The first level above.
    pub high: Option<f64>,
    /// The second level above.
    pub high_high: Option<f64>,
    /// How far a value must come back past a limit before its level clears (0: at the limit).
    /// It keeps a value that hovers at a limit from raising and clearing every cycle.
    pub deadband: f64,
}

/// What makes an alarm active.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum AlarmKind {
    /// A bool, active when it equals `active` (`alarm_when = false`: active-low).
    Discrete {
        /// The value that makes it active.
        active: bool,
    },
    /// A number against its limits.
    Limit(Limits),
}

/// The part of an alarm the evaluator needs: its condition, on-delay and latching.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Condition {
    /// What makes it active.
    pub kind: AlarmKind,
    /// How long the condition must hold before the alarm is raised.
    pub delay: Time,
    /// `latched`: it stays until reset, even after its condition clears.
    pub latched: bool,
}

impl Condition {
    /// A bool alarm active when the value is `active`, without delay or latching.
    pub const fn discrete(active: bool) -> Condition {
        Condition {
            kind: AlarmKind::Discrete { active },
            delay: Time::from_nanos(0),
            latched: false,
        }
    }

    /// A limit alarm, without delay or latching.
    pub const fn limit(limits: Limits) -> Condition {
        Condition {
            kind: AlarmKind::Limit(limits),
            delay: Time::from_nanos(0),
            latched: false,
        }
    }
}

/// The bool that suppresses an alarm by design (IEC 62682): `suppress_when = "path"`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SuppressWhen {
    /// Nothing suppresses it.
    Never,
    /// The bool at this basic value: `index` of the top-level variable and its `leaf` (see
    /// [`Location`](crate::Location)). In a structure's own table (`PlcType::ALARMS`), the
    /// leaf counts from the structure's start.
    At {
        /// Index of the top-level variable.
        index: usize,
        /// Leaf within it.
        leaf: usize,
    },
    /// A path the derive could not follow (into a structure or an array): resolve it with
    /// [`resolve_suppress`](crate::alarm::resolve_suppress) when the program starts.
    Path(&'static str),
}

/// One declared alarm: a basic value it watches and what raises it. A declaration on an array
/// of bools has one per element, one on a structure's member one per instance, each with its
/// own `leaf`.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct AlarmDecl {
    /// Index of the top-level variable in `GlobalMemory::VARIABLES`.
    pub index: usize,
    /// The basic value within it (see [`Location::leaf`](crate::Location::leaf)): the element
    /// of an array, the member of a structure.
    pub leaf: usize,
    /// The message operators see.
    pub text: &'static str,
    /// What makes it active, its delay and latching.
    pub condition: Condition,
    /// 1 (least urgent) to 1000, OPC UA's range; 500 if not declared.
    pub severity: u16,
    /// What suppresses it by design.
    pub suppress_when: SuppressWhen,
}

impl AlarmDecl {
    /// An alarm on leaf `leaf` of variable `index`, severity 500, never suppressed.
    pub const fn new(
        index: usize,
        leaf: usize,
        text: &'static str,
        condition: Condition,
    ) -> AlarmDecl {
        AlarmDecl {
            index,
            leaf,
            text,
            condition,
            severity: 500,
            suppress_when: SuppressWhen::Never,
        }
    }

    /// With severity `severity` (1..=1000).
    pub const fn with_severity(mut self, severity: u16) -> AlarmDecl {
        self.severity = severity;
        self
    }

    /// Suppressed by design while `suppress_when` is true.
    pub const fn with_suppress(mut self, suppress_when: SuppressWhen) -> AlarmDecl {
        self.suppress_when = suppress_when;
        self
    }

    /// With an on-delay.
    pub const fn with_delay(mut self, delay: Time) -> AlarmDecl {
        self.condition.delay = delay;
        self
    }

    /// Latched: it stays until reset.
    pub const fn latched(mut self) -> AlarmDecl {
        self.condition.latched = true;
        self
    }
}
