//! Each alarm's state from its records, as the evaluator ([`Alarms`]) would have it after the
//! same transitions, and that state given back to the evaluator by path after a restart.

use super::record::{Entry, Record};
use plc_core::alarm::{Alarms, Level, Shelf, Snapshot};
use std::collections::BTreeMap;

/// A normal alarm, as the evaluator starts them.
pub(super) fn normal() -> Snapshot {
    Snapshot {
        level: Level::Normal,
        acknowledged: true,
        held: false,
        shelf: None,
        since_ns: 0,
    }
}

/// Whether a state is worth keeping across a cut of the file: anything but normal.
pub(super) fn notable(s: &Snapshot) -> bool {
    s.level != Level::Normal || !s.acknowledged || s.held || s.shelf.is_some()
}

fn side(l: Level) -> i8 {
    match l {
        Level::Low | Level::LowLow => -1,
        Level::High | Level::HighHigh => 1,
        Level::Normal | Level::Active => 0,
    }
}

/// Takes out of annunciation, as the evaluator does when shelving or suppressing.
fn quiet(s: &mut Snapshot) {
    s.level = Level::Normal;
    s.acknowledged = true;
    s.held = false;
}

/// Applies one record to the states, the evaluator's rules followed (plc-core's `eval.rs`).
pub(super) fn apply(states: &mut BTreeMap<String, Snapshot>, r: &Record) {
    if matches!(r.entry, Entry::Summarised { .. }) || r.path.is_empty() {
        return;
    }
    let s = states.entry(r.path.clone()).or_insert_with(normal);
    match &r.entry {
        Entry::Raised { level, .. } => {
            s.level = *level;
            s.acknowledged = false;
            s.held = false;
        }
        Entry::LevelChanged { from, to, .. } => {
            // More urgent, or past normal to the other side: a new condition to see.
            if to.rank() > from.rank() || side(*from) != side(*to) {
                s.acknowledged = false;
            }
            s.level = *to;
            s.held = false;
        }
        Entry::Cleared { .. } => {
            s.level = Level::Normal;
            s.held = false;
        }
        Entry::ConditionCleared { .. } => s.held = true,
        Entry::Acknowledged { .. } => s.acknowledged = true,
        Entry::Reset { .. } => {
            quiet(s);
        }
        Entry::Shelved { by, until_ns } => {
            quiet(s);
            s.shelf = Some(Shelf {
                by: by.user.clone(),
                since_ns: r.time_ns,
                until_ns: *until_ns,
            });
        }
        Entry::Unshelved { .. } => s.shelf = None,
        Entry::Suppressed => quiet(s),
        Entry::Unsuppressed | Entry::Summarised { .. } => {}
    }
    s.since_ns = r.time_ns;
}

/// What [`restore`] did.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct RestoreReport {
    /// Alarms given their state from the journal, by path.
    pub restored: Vec<String>,
    /// Paths in the journal that name no alarm now (removed or renamed): ignored.
    pub unknown: Vec<String>,
}

/// Gives each alarm of `alarms` (named by `paths`, in the evaluator's order) its state from
/// `states` ([`Contents::states`](super::Contents::states)), so that an alarm unacknowledged
/// before a restart is unacknowledged after it. Alarms the journal does not name stay
/// normal; paths it names that are no alarm now are reported.
///
/// ```
/// use plc_core::alarm::{Alarms, AlarmState, Condition, Level, Snapshot};
/// use std::collections::BTreeMap;
/// let mut alarms = Alarms::new([Condition::discrete(true)]);
/// let mut states = BTreeMap::new();
/// states.insert("door".to_string(), Snapshot {
///     level: Level::Active, acknowledged: false, held: false, shelf: None, since_ns: 5,
/// });
/// let report = plc_runtime::alarm_journal::restore(&mut alarms, &["door".into()], &states);
/// assert_eq!(report.restored, ["door"]);
/// assert_eq!(alarms.state(0), AlarmState::ActiveUnacknowledged);
/// ```
pub fn restore(
    alarms: &mut Alarms,
    paths: &[String],
    states: &BTreeMap<String, Snapshot>,
) -> RestoreReport {
    let mut report = RestoreReport::default();
    for (i, path) in paths.iter().enumerate().take(alarms.len()) {
        if let Some(state) = states.get(path)
            && alarms.restore(i, state.clone()).is_ok()
        {
            report.restored.push(path.clone());
        }
    }
    let known: std::collections::HashSet<&str> = paths.iter().map(String::as_str).collect();
    report.unknown = states
        .keys()
        .filter(|p| !known.contains(p.as_str()))
        .cloned()
        .collect();
    report
}
