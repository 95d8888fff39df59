//! What `plc watch` marks on a line besides its value: a forced value (`F`), and a value an
//! alarm watches (`!` after its name; red while the alarm is active or waits for an
//! acknowledgement); and the header's counts of both.

use super::Error;
use plc_shm::{DynSegment, Status};
use std::collections::{HashMap, HashSet};

/// The marks of the values shown, refreshed with them.
pub struct Marks {
    /// The values forced now, as (variable, leaf), and the variables holding one.
    forced: HashSet<(usize, usize)>,
    forced_vars: HashSet<usize>,
    /// The values alarms watch, (variable, leaf) -> the alarms' numbers.
    alarm_leaves: HashMap<(usize, usize), Vec<usize>>,
    /// The same by variable: a line of a whole variable looks up its own alarms, not all.
    alarm_vars: HashMap<usize, Vec<usize>>,
    /// The alarms that want an operator's eye now (active or unacknowledged).
    alarmed: HashSet<usize>,
}

/// How one line is marked.
#[derive(Clone, Copy, Debug, Default)]
pub struct Mark {
    /// A value of it is forced.
    pub forced: bool,
    /// An alarm watches a value of it.
    pub alarm: bool,
    /// And that alarm is active or waits for an acknowledgement.
    pub alarmed: bool,
}

impl Marks {
    /// The alarm marks of `seg`'s declaration, nothing forced or alarmed yet.
    pub fn new(seg: &DynSegment) -> Marks {
        let mut alarm_leaves: HashMap<(usize, usize), Vec<usize>> = HashMap::new();
        let mut alarm_vars: HashMap<usize, Vec<usize>> = HashMap::new();
        for (n, a) in seg.alarms().iter().enumerate() {
            alarm_leaves
                .entry((a.variable, a.leaf))
                .or_default()
                .push(n);
            alarm_vars.entry(a.variable).or_default().push(n);
        }
        Marks {
            alarm_vars,
            alarm_leaves,
            forced: HashSet::new(),
            forced_vars: HashSet::new(),
            alarmed: HashSet::new(),
        }
    }

    /// Reads the forces and the alarm states again, each table only while the status block
    /// counts some (or, for alarms, counted some at the last look).
    pub fn refresh(&mut self, seg: &DynSegment, status: &Status) -> Result<(), Error> {
        self.forced.clear();
        self.forced_vars.clear();
        if status.forces > 0 {
            for f in seg.forces()? {
                self.forced.insert((f.index, f.leaf));
                self.forced_vars.insert(f.index);
            }
        }
        let counted = status.alarms_active + status.alarms_unacknowledged > 0;
        if counted || !self.alarmed.is_empty() {
            self.alarmed.clear();
            for (n, s) in seg.alarm_states()?.iter().enumerate() {
                if s.active() || s.state.unacknowledged() {
                    self.alarmed.insert(n);
                }
            }
        }
        Ok(())
    }

    /// The marks of top-level variable `var` shown whole, or of the basic value `leaf`.
    pub fn of(&self, var: Option<usize>, leaf: Option<(usize, usize)>) -> Mark {
        let alarmed = |numbers: &Vec<usize>| numbers.iter().any(|n| self.alarmed.contains(n));
        match (var, leaf) {
            (Some(v), _) => Mark {
                forced: self.forced_vars.contains(&v),
                alarm: self.alarm_vars.contains_key(&v),
                alarmed: self.alarm_vars.get(&v).is_some_and(alarmed),
            },
            (None, Some(at)) => Mark {
                forced: self.forced.contains(&at),
                alarm: self.alarm_leaves.contains_key(&at),
                alarmed: self.alarm_leaves.get(&at).is_some_and(alarmed),
            },
            (None, None) => Mark::default(),
        }
    }
}

/// The header's counts: `| 2 forced (F) | alarms: 1 unacknowledged, 1 active (!)`, or
/// nothing.
pub fn header_counts(status: &Status) -> String {
    let mut out = String::new();
    if status.forces > 0 {
        out.push_str(&format!(" | {} forced (F)", status.forces));
    }
    if status.alarms_active + status.alarms_unacknowledged > 0 {
        out.push_str(&format!(
            " | alarms: {} unacknowledged, {} active (!; plc alarms)",
            status.alarms_unacknowledged, status.alarms_active
        ));
    }
    out
}
