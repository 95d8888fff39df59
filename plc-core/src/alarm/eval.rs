//! [`Alarms`]: the state of every declared alarm and the pure step from one cycle's values to
//! the next states. It reads nothing itself (the caller gives each alarm's value and whether
//! it is suppressed) and writes nothing but its states and the events it returns, so the
//! runtime, a replay or a test drive it alike.
//!
//! The cycle's path is one comparison per alarm when nothing changes: each alarm keeps the
//! condition it saw last and the next time something is due (end of an on-delay, a shelf's
//! expiry), and only a new condition, a change of suppression or a due time takes the slow
//! path. No allocation happens unless an event is pushed past the vector's capacity.

use super::decl::{AlarmDecl, AlarmKind, Condition, Level};
use super::state::{ActionError, AlarmEvent, AlarmState, EventKind, Shelf, Snapshot};
use crate::Time;
use std::vec::Vec;

/// The longest shelf unless [`Alarms::with_max_shelve`] says otherwise: 8 hours, one shift,
/// so a shelved alarm cannot be forgotten across shifts.
pub const DEFAULT_MAX_SHELVE: Time = Time::from_secs(8 * 3600);

/// "Nothing due": the deadline of an alarm that waits for nothing.
const NEVER: i64 = i64::MAX;

/// One alarm's value in a cycle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    /// The value: a number, or a bool as 0.0 / 1.0.
    pub value: f64,
    /// Whether its `suppress_when` bool is true.
    pub suppressed: bool,
}

impl Sample {
    /// The sample of a value as `GlobalMemory::get` gives it: a bool as 0 or 1, a number as
    /// itself; text or a duration (which no alarm watches) as not a number, which keeps the
    /// level an alarm has.
    pub fn from_value(value: &crate::Value, suppressed: bool) -> Sample {
        use crate::Value;
        let value = match *value {
            Value::Bool(b) => f64::from(u8::from(b)),
            Value::Int(i) => i as f64,
            Value::UInt(u) => u as f64,
            Value::Real(r) => r,
            Value::Text(_) | Value::Time(_) => f64::NAN,
        };
        Sample { value, suppressed }
    }

    /// A bool's sample.
    pub const fn bool(value: bool, suppressed: bool) -> Sample {
        Sample {
            value: if value { 1.0 } else { 0.0 },
            suppressed,
        }
    }
}

/// The condition, prepared for the cycle: thresholds with the missing ones at infinity.
#[derive(Clone, Copy, Debug)]
struct Cfg {
    /// `None` for a limit alarm; the active value for a bool.
    discrete: Option<bool>,
    /// low_low, low, high, high_high.
    limits: [f64; 4],
    deadband: f64,
    delay_ns: i64,
    latched: bool,
}

impl Cfg {
    fn new(c: &Condition) -> Cfg {
        let (discrete, limits, deadband) = match c.kind {
            AlarmKind::Discrete { active } => (Some(active), [0.0; 4], 0.0),
            AlarmKind::Limit(l) => (
                None,
                [
                    l.low_low.unwrap_or(f64::NEG_INFINITY),
                    l.low.unwrap_or(f64::NEG_INFINITY),
                    l.high.unwrap_or(f64::INFINITY),
                    l.high_high.unwrap_or(f64::INFINITY),
                ],
                l.deadband.max(0.0),
            ),
        };
        Cfg {
            discrete,
            limits,
            deadband,
            delay_ns: c.delay.as_nanos().max(0),
            latched: c.latched,
        }
    }

    /// The condition's level for `v`, `prev` the level seen last: a level is left only
    /// once the value is the deadband past its limit. A value that is not a number (a
    /// failed reading) says nothing, so the level stays.
    #[inline(always)]
    fn level(&self, v: f64, prev: Level) -> Level {
        if let Some(active) = self.discrete {
            return if (v != 0.0) == active {
                Level::Active
            } else {
                Level::Normal
            };
        }
        if v.is_nan() {
            return prev;
        }
        let [ll, l, h, hh] = self.limits;
        let db = self.deadband;
        let hh = if prev == Level::HighHigh { hh - db } else { hh };
        let h = if matches!(prev, Level::High | Level::HighHigh) {
            h - db
        } else {
            h
        };
        let ll = if prev == Level::LowLow { ll + db } else { ll };
        let l = if matches!(prev, Level::Low | Level::LowLow) {
            l + db
        } else {
            l
        };
        if v >= hh {
            Level::HighHigh
        } else if v >= h {
            Level::High
        } else if v <= ll {
            Level::LowLow
        } else if v <= l {
            Level::Low
        } else {
            Level::Normal
        }
    }
}

/// One alarm's state.
#[derive(Clone, Debug)]
struct Slot {
    /// The condition seen last cycle.
    seen: Level,
    suppressed: bool,
    /// The next time something is due: an on-delay's end, a shelf's expiry; `i64::MIN` to
    /// look again next cycle.
    deadline: i64,
    /// The level annunciated.
    level: Level,
    acked: bool,
    /// A latched alarm whose condition cleared.
    held: bool,
    /// The level waiting for its on-delay, and since when.
    pending: Level,
    pending_since: i64,
    shelf: Option<Shelf>,
    /// The time of the last transition.
    since: i64,
}

/// Every declared alarm's state, stepped once a cycle by [`evaluate`](Self::evaluate).
#[derive(Clone, Debug)]
pub struct Alarms {
    cfg: Vec<Cfg>,
    slots: Vec<Slot>,
    max_shelve: Time,
}

impl Alarms {
    /// Alarms with these conditions, numbered in order, all normal.
    pub fn new(conditions: impl IntoIterator<Item = Condition>) -> Alarms {
        let cfg: Vec<Cfg> = conditions.into_iter().map(|c| Cfg::new(&c)).collect();
        let slot = Slot {
            seen: Level::Normal,
            suppressed: false,
            deadline: NEVER,
            level: Level::Normal,
            acked: true,
            held: false,
            pending: Level::Normal,
            pending_since: 0,
            shelf: None,
            since: 0,
        };
        Alarms {
            slots: std::vec![slot; cfg.len()],
            cfg,
            max_shelve: DEFAULT_MAX_SHELVE,
        }
    }

    /// The alarms of a declaration (`GlobalMemory::ALARMS`), numbered as it lists them.
    pub fn from_decls(decls: &[AlarmDecl]) -> Alarms {
        Alarms::new(decls.iter().map(|d| d.condition))
    }

    /// With another longest shelf than [`DEFAULT_MAX_SHELVE`].
    pub fn with_max_shelve(mut self, max: Time) -> Alarms {
        self.max_shelve = max;
        self
    }

    /// Number of alarms.
    pub fn len(&self) -> usize {
        self.slots.len()
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.slots.is_empty()
    }

    /// One cycle: `sample(i)` gives alarm `i`'s value and suppression at `now_ns` (UTC
    /// nanoseconds); each transition is pushed onto `events`.
    pub fn evaluate(
        &mut self,
        now_ns: i64,
        mut sample: impl FnMut(usize) -> Sample,
        events: &mut Vec<AlarmEvent>,
    ) {
        for (i, (slot, cfg)) in self.slots.iter_mut().zip(&self.cfg).enumerate() {
            let s = sample(i);
            let raw = cfg.level(s.value, slot.seen);
            if raw == slot.seen && s.suppressed == slot.suppressed && now_ns < slot.deadline {
                continue;
            }
            step(i, slot, cfg, raw, s.suppressed, now_ns, events);
        }
    }

    /// Alarm `alarm`'s state.
    ///
    /// # Panics
    /// If there is no such alarm.
    pub fn state(&self, alarm: usize) -> AlarmState {
        let s = &self.slots[alarm];
        if s.suppressed {
            AlarmState::SuppressedByDesign
        } else if s.shelf.is_some() {
            AlarmState::Shelved
        } else if s.held {
            AlarmState::Latched {
                acknowledged: s.acked,
            }
        } else if s.level != Level::Normal {
            if s.acked {
                AlarmState::ActiveAcknowledged
            } else {
                AlarmState::ActiveUnacknowledged
            }
        } else if !s.acked {
            AlarmState::ReturnedUnacknowledged
        } else {
            AlarmState::Normal
        }
    }

    /// The level alarm `alarm` is annunciated at (`normal` while it is not active).
    pub fn level(&self, alarm: usize) -> Level {
        self.slots[alarm].level
    }

    /// Whether nothing of alarm `alarm` waits for an acknowledgement (also while it is
    /// shelved or suppressed, which [`state`](Self::state) does not show).
    pub fn acknowledged(&self, alarm: usize) -> bool {
        self.slots[alarm].acked
    }

    /// When alarm `alarm` last changed state, UTC nanoseconds (0 if never).
    pub fn since_ns(&self, alarm: usize) -> i64 {
        self.slots[alarm].since
    }

    /// Who shelved alarm `alarm` and until when, while it is shelved.
    pub fn shelf(&self, alarm: usize) -> Option<&Shelf> {
        self.slots[alarm].shelf.as_ref()
    }

    /// Alarms waiting for an acknowledgement.
    pub fn unacknowledged(&self) -> usize {
        (0..self.len())
            .filter(|&i| self.state(i).unacknowledged())
            .count()
    }

    /// Alarm `alarm`'s state as [`restore`](Self::restore) takes it back.
    pub fn snapshot(&self, alarm: usize) -> Snapshot {
        let s = &self.slots[alarm];
        Snapshot {
            level: s.level,
            acknowledged: s.acked,
            held: s.held,
            shelf: s.shelf.clone(),
            since_ns: s.since,
        }
    }

    /// Gives alarm `alarm` a state kept from before (a restart, an online change): an alarm
    /// nobody acknowledged stays unacknowledged. Its condition is looked at again next cycle:
    /// one that went meanwhile clears then, as it would have. A latched hold on an alarm
    /// that is not latched (its declaration changed) is dropped.
    pub fn restore(&mut self, alarm: usize, state: Snapshot) -> Result<(), ActionError> {
        let (s, cfg) = self.slot(alarm)?;
        s.level = state.level;
        // The level is where the deadband counts from.
        s.seen = state.level;
        s.acked = state.acknowledged;
        s.held = state.held && cfg.latched && state.level != Level::Normal;
        s.pending = Level::Normal;
        s.shelf = state.shelf;
        s.since = state.since_ns;
        s.deadline = i64::MIN;
        Ok(())
    }

    fn slot(&mut self, alarm: usize) -> Result<(&mut Slot, &Cfg), ActionError> {
        match (self.slots.get_mut(alarm), self.cfg.get(alarm)) {
            (Some(s), Some(c)) => Ok((s, c)),
            _ => Err(ActionError::Unknown { alarm }),
        }
    }

    /// An operator acknowledges alarm `alarm`.
    pub fn acknowledge(&mut self, alarm: usize, now_ns: i64) -> Result<AlarmEvent, ActionError> {
        let (s, _) = self.slot(alarm)?;
        if s.acked {
            return Err(ActionError::NotUnacknowledged);
        }
        s.acked = true;
        s.since = now_ns;
        Ok(event(alarm, now_ns, EventKind::Acknowledged))
    }

    /// An operator resets latched alarm `alarm` once its condition has cleared; a reset also
    /// acknowledges it.
    pub fn reset(&mut self, alarm: usize, now_ns: i64) -> Result<AlarmEvent, ActionError> {
        let (s, cfg) = self.slot(alarm)?;
        if !cfg.latched {
            return Err(ActionError::NotLatched);
        }
        if !s.held {
            return Err(if s.level != Level::Normal {
                ActionError::StillActive
            } else {
                ActionError::NotHeld
            });
        }
        s.held = false;
        s.level = Level::Normal;
        s.acked = true;
        s.since = now_ns;
        Ok(event(alarm, now_ns, EventKind::Reset))
    }

    /// `by` shelves alarm `alarm` for `duration` (more than 0, at most the longest shelf):
    /// it is not shown, and comes back by itself when the shelf expires, as a new alarm if its
    /// condition still holds (a latched one's hold is dropped with the rest of its state).
    pub fn shelve(
        &mut self,
        alarm: usize,
        now_ns: i64,
        duration: Time,
        by: &str,
    ) -> Result<AlarmEvent, ActionError> {
        let max = self.max_shelve;
        let (s, _) = self.slot(alarm)?;
        if duration.as_nanos() <= 0 || duration.as_nanos() > max.as_nanos() {
            return Err(ActionError::ShelveDuration { max });
        }
        let until_ns = now_ns.saturating_add(duration.as_nanos());
        s.shelf = Some(Shelf {
            by: by.into(),
            since_ns: now_ns,
            until_ns,
        });
        quiet(s);
        s.since = now_ns;
        s.deadline = until_ns;
        Ok(event(alarm, now_ns, EventKind::Shelved { until_ns }))
    }

    /// An operator takes alarm `alarm` off the shelf; its condition is looked at again next
    /// cycle.
    pub fn unshelve(&mut self, alarm: usize, now_ns: i64) -> Result<AlarmEvent, ActionError> {
        let (s, _) = self.slot(alarm)?;
        if s.shelf.take().is_none() {
            return Err(ActionError::NotShelved);
        }
        s.since = now_ns;
        s.deadline = i64::MIN;
        Ok(event(
            alarm,
            now_ns,
            EventKind::Unshelved { expired: false },
        ))
    }
}

const fn event(alarm: usize, time_ns: i64, kind: EventKind) -> AlarmEvent {
    AlarmEvent {
        alarm,
        time_ns,
        kind,
    }
}

/// Takes an alarm out of annunciation (shelved, suppressed): nothing active, nothing to
/// acknowledge or reset, no delay running.
fn quiet(s: &mut Slot) {
    s.level = Level::Normal;
    s.acked = true;
    s.held = false;
    s.pending = Level::Normal;
}

/// The slow path: the condition, suppression or a due time changed.
#[cold]
fn step(
    i: usize,
    s: &mut Slot,
    cfg: &Cfg,
    raw: Level,
    suppressed: bool,
    now: i64,
    events: &mut Vec<AlarmEvent>,
) {
    s.seen = raw;
    if suppressed != s.suppressed {
        s.suppressed = suppressed;
        s.since = now;
        if suppressed {
            quiet(s);
            events.push(event(i, now, EventKind::Suppressed));
        } else {
            events.push(event(i, now, EventKind::Unsuppressed));
        }
    }
    if let Some(shelf) = &s.shelf
        && now >= shelf.until_ns
    {
        s.shelf = None;
        s.since = now;
        events.push(event(i, now, EventKind::Unshelved { expired: true }));
    }
    if s.suppressed || s.shelf.is_some() {
        s.deadline = s.shelf.as_ref().map_or(NEVER, |f| f.until_ns);
        return;
    }
    s.deadline = NEVER;
    if raw != Level::Normal && s.level != Level::Normal && side(raw) != side(s.level) && !s.held {
        // Swung past normal to the other side: the old level's condition is gone now, while
        // the new one waits for its delay like any raise.
        apply(i, s, cfg, Level::Normal, now, events);
    }
    // A latched alarm holding at a level counts as there for escalation.
    let at = s.level;
    let escalates = raw != Level::Normal && (raw.rank() > at.rank() || side(raw) != side(at));
    if !escalates {
        s.pending = Level::Normal;
        // A holding latched alarm whose condition is back stops holding, at any level.
        if (raw != at && !(s.held && raw == Level::Normal)) || (s.held && raw != Level::Normal) {
            apply(i, s, cfg, raw, now, events);
        }
        return;
    }
    if s.pending != raw {
        s.pending = raw;
        s.pending_since = now;
    }
    let due = s.pending_since.saturating_add(cfg.delay_ns);
    if now >= due {
        s.pending = Level::Normal;
        apply(i, s, cfg, raw, now, events);
    } else {
        s.deadline = due;
    }
}

/// Which side of normal a level is on: -1 below, 1 above, 0 for normal and bools.
fn side(l: Level) -> i8 {
    match l {
        Level::Low | Level::LowLow => -1,
        Level::High | Level::HighHigh => 1,
        Level::Normal | Level::Active => 0,
    }
}

/// The annunciated level becomes `to` (the delay, if any, has run).
fn apply(i: usize, s: &mut Slot, cfg: &Cfg, to: Level, now: i64, events: &mut Vec<AlarmEvent>) {
    let from = s.level;
    if to == Level::Normal {
        if cfg.latched {
            if !s.held {
                s.held = true;
                s.since = now;
                events.push(event(i, now, EventKind::ConditionCleared { level: from }));
            }
            return;
        }
        s.level = Level::Normal;
        s.since = now;
        events.push(event(i, now, EventKind::Cleared { from }));
        return;
    }
    s.held = false;
    if from == to {
        // A latched alarm whose condition came back at the level it holds.
        return;
    }
    s.level = to;
    s.since = now;
    if from == Level::Normal {
        s.acked = false;
        events.push(event(i, now, EventKind::Raised { level: to }));
    } else {
        // More urgent, or swung past normal to the other side: a new condition to see.
        if to.rank() > from.rank() || side(from) != side(to) {
            s.acked = false;
        }
        events.push(event(i, now, EventKind::LevelChanged { from, to }));
    }
}
