//! The program's alarms as the runtime keeps them: evaluated after the tick every cycle from
//! the variables, each transition handed to the alarm journal, and the operators' actions
//! (acknowledge, reset, shelve, unshelve) taken by path from the program's side.
//!
//! The evaluator ([`Alarms`]) is plc-core's; this is what ties it to a running program: which
//! value each alarm watches, which bool suppresses it, the cycle's UTC time, and the journal's
//! sender. A program without alarms has none of it to run: the cycle looks at one length and
//! goes on.

use crate::alarm_journal::{self, JournalSender, Operator};
use plc_core::Time;
use plc_core::alarm::{
    ActionError, AlarmEvent, AlarmState, Alarms, Level, Sample, Snapshot, alarm_paths,
    resolve_suppress,
};
use plc_core::memory::{Memory, Schema};
use plc_shm::AlarmEntry;
use std::collections::BTreeMap;
use std::fmt;
use std::sync::Arc;

/// What one alarm reads each cycle: its value, and the bool that suppresses it, as
/// `GlobalMemory::get` takes them (variable index, leaf).
#[derive(Clone, Copy, Debug)]
struct Watch {
    value: (usize, usize),
    suppress: Option<(usize, usize)>,
}

/// The program's alarms while it runs: their states, and the operators' actions by path.
/// The tick reaches it as [`Context::alarms`](crate::Context::alarms); the runtime evaluates
/// it after each tick, so the program writes nothing for its alarms.
///
/// ```no_run
/// use plc_core::GlobalMemory;
/// use plc_core::alarm::AlarmState;
/// use plc_runtime::Runtime;
/// use plc_runtime::alarm_journal::Operator;
///
/// #[derive(GlobalMemory, Debug, Clone)]
/// struct Gm {
///     #[plc(alarm = "Guard door open", direction = "input")]
///     door_open: bool,
///     #[plc(direction = "input")]
///     ack_button: bool,
/// }
///
/// Runtime::<Gm>::builder()
///     .segment("press")
///     .retain("state/press.retain") // the journal: state/press.alarms
///     .build()?
///     .run(|ctx| {
///         // The acknowledge button on the panel acknowledges the door alarm.
///         if ctx.gm.ack_button
///             && ctx.alarms().state("door_open") == Some(AlarmState::ActiveUnacknowledged)
///         {
///             let _ = ctx.alarms_mut().acknowledge("door_open", Operator::new(None, "panel"));
///         }
///     })?;
/// # Ok::<(), plc_runtime::RuntimeError>(())
/// ```
pub struct RuntimeAlarms {
    alarms: Alarms,
    paths: Arc<[String]>,
    watch: Vec<Watch>,
    /// This cycle's transitions; its capacity is kept, so a cycle allocates nothing.
    events: Vec<AlarmEvent>,
    sender: Option<JournalSender>,
    /// The cycle's UTC time, nanoseconds: every transition's and action's time.
    now_ns: i64,
    /// Counts for the status block, recounted only after a transition or an action.
    active: usize,
    unacknowledged: usize,
    recount: bool,
    /// The counts last published to the status block.
    published: (usize, usize),
    /// The alarms whose state changed since the segment's table was last given them, once
    /// each (`dirty` says which are in `changed`); both keep their capacity.
    changed: Vec<usize>,
    dirty: Vec<bool>,
}

impl fmt::Debug for RuntimeAlarms {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("RuntimeAlarms")
            .field("alarms", &self.alarms.len())
            .field("active", &self.active)
            .field("unacknowledged", &self.unacknowledged)
            .field("journal", &self.sender.is_some())
            .finish()
    }
}

impl RuntimeAlarms {
    /// No alarms: a program without any, or a unit test's context.
    pub(crate) fn none() -> RuntimeAlarms {
        RuntimeAlarms {
            alarms: Alarms::new([]),
            paths: Arc::from(Vec::new()),
            watch: Vec::new(),
            events: Vec::new(),
            sender: None,
            now_ns: 0,
            active: 0,
            unacknowledged: 0,
            recount: false,
            published: (0, 0),
            changed: Vec::new(),
            dirty: Vec::new(),
        }
    }

    /// The alarms `T` declares, all normal; an error naming the alarm if a `suppress_when`
    /// path names no bool of the program (the derive cannot follow a path into a structure
    /// or an array, so this is where it is checked).
    pub(crate) fn of(schema: &Schema) -> Result<RuntimeAlarms, String> {
        let (variables, decls) = (schema.variables, schema.alarms);
        if decls.is_empty() {
            return Ok(RuntimeAlarms::none());
        }
        let paths = alarm_paths(variables, decls);
        let watch = decls
            .iter()
            .zip(&paths)
            .map(|(d, path)| {
                let suppress = resolve_suppress(variables, d.suppress_when).map_err(|e| {
                    format!(
                        "alarm `{path}` (\"{}\"): {e}; point `suppress_when` at a bool of the \
                         program, by its path as `plc get` takes it",
                        d.text
                    )
                })?;
                Ok(Watch {
                    value: (d.index, d.leaf),
                    suppress,
                })
            })
            .collect::<Result<Vec<_>, String>>()?;
        Ok(RuntimeAlarms {
            alarms: Alarms::from_decls(decls),
            // Room for a few transitions of every alarm in one cycle: a flood pushes no
            // further once the vector has grown to it.
            events: Vec::with_capacity(4 * paths.len()),
            paths: paths.into(),
            watch,
            sender: None,
            now_ns: 0,
            active: 0,
            unacknowledged: 0,
            recount: true,
            published: (0, 0),
            changed: Vec::with_capacity(decls.len()),
            dirty: vec![false; decls.len()],
        })
    }

    /// Each alarm's state from before (the journal's, by path); the paths the journal names
    /// that are no alarm now are logged and ignored.
    pub(crate) fn restore(&mut self, states: &BTreeMap<String, Snapshot>, file: &std::path::Path) {
        let report = alarm_journal::restore(&mut self.alarms, &self.paths, states);
        for i in 0..self.alarms.len() {
            self.mark(i);
        }
        if !report.restored.is_empty() {
            log::info!(target: "plc_io::runtime",
                "alarm journal {}: the state of {} alarms restored",
                file.display(), report.restored.len());
        }
        if !report.unknown.is_empty() {
            log::warn!(target: "plc_io::runtime",
                "alarm journal {}: {} alarms in it are not alarms of this program any more \
                 (removed or renamed), ignored: {}",
                file.display(), report.unknown.len(), report.unknown.join(", "));
        }
        self.recount = true;
    }

    /// Operators may shelve an alarm for at most `max`.
    pub(crate) fn set_max_shelve(&mut self, max: Time) {
        let alarms = std::mem::replace(&mut self.alarms, Alarms::new([]));
        self.alarms = alarms.with_max_shelve(max);
    }

    /// Transitions go to the journal through `sender` from now on.
    pub(crate) fn attach(&mut self, sender: JournalSender) {
        self.sender = Some(sender);
    }

    /// The path table, for the journal's sender.
    pub(crate) fn path_table(&self) -> Arc<[String]> {
        self.paths.clone()
    }

    /// Sets the cycle's UTC time, before its tick: the time of what happens in it.
    pub(crate) fn set_now(&mut self, now_ns: i64) {
        self.now_ns = now_ns;
    }

    /// One cycle's step from `gm`'s values, each transition handed to the journal.
    pub(crate) fn evaluate<T: Memory>(&mut self, gm: &T) {
        let watch = &self.watch;
        let sample = |i: usize| sample(gm, watch[i]);
        self.alarms.evaluate(self.now_ns, sample, &mut self.events);
        if !self.events.is_empty() {
            if let Some(sender) = &self.sender {
                for e in &self.events {
                    sender.record(e, sample(e.alarm).value);
                }
            }
            for k in 0..self.events.len() {
                self.mark(self.events[k].alarm);
            }
            self.events.clear();
            self.recount = true;
        }
        self.recount();
    }

    /// Notes that alarm `i` changed, for the segment's table.
    fn mark(&mut self, i: usize) {
        if let Some(d) = self.dirty.get_mut(i)
            && !*d
        {
            *d = true;
            self.changed.push(i);
        }
    }

    /// Whether an alarm changed since [`drain_changed`](Self::drain_changed) last ran.
    pub(crate) fn has_changed(&self) -> bool {
        !self.changed.is_empty()
    }

    /// The alarms that changed, with their states as the segment's table holds them; none
    /// again until the next change.
    pub(crate) fn drain_changed(&mut self) -> impl Iterator<Item = (usize, AlarmEntry)> + '_ {
        let (alarms, dirty) = (&self.alarms, &mut self.dirty);
        self.changed.drain(..).map(move |i| {
            dirty[i] = false;
            let entry = AlarmEntry {
                state: alarms.state(i),
                level: alarms.level(i),
                acknowledged: alarms.acknowledged(i),
                since_ns: alarms.since_ns(i),
                shelved_until_ns: alarms.shelf(i).map(|s| s.until_ns),
            };
            (i, entry)
        })
    }

    /// Counts again if a transition or an action happened since the last count: one walk
    /// over the alarms then, none in a cycle where nothing happened.
    pub(crate) fn recount(&mut self) {
        if !std::mem::take(&mut self.recount) {
            return;
        }
        let (mut active, mut unacknowledged) = (0, 0);
        for i in 0..self.alarms.len() {
            active += usize::from(self.alarms.level(i) != Level::Normal);
            unacknowledged += usize::from(self.alarms.state(i).unacknowledged());
        }
        (self.active, self.unacknowledged) = (active, unacknowledged);
    }

    /// The counts of active and unacknowledged alarms if they changed since the last call
    /// (for the status block, written only then).
    pub(crate) fn counts_to_publish(&mut self) -> Option<(usize, usize)> {
        let now = (self.active, self.unacknowledged);
        (now != self.published).then(|| {
            self.published = now;
            now
        })
    }

    /// Number of alarms the program declares.
    pub fn len(&self) -> usize {
        self.alarms.len()
    }

    /// Whether the program declares none.
    pub fn is_empty(&self) -> bool {
        self.alarms.is_empty()
    }

    /// Each alarm's path (`door`, `stations[2].door`), in the declaration's order.
    pub fn paths(&self) -> &[String] {
        &self.paths
    }

    /// The number of the alarm at `path`.
    pub fn find(&self, path: &str) -> Option<usize> {
        self.paths.iter().position(|p| p == path)
    }

    /// The state of the alarm at `path`, `None` if there is no alarm there.
    pub fn state(&self, path: &str) -> Option<AlarmState> {
        self.find(path).map(|i| self.alarms.state(i))
    }

    /// The level the alarm at `path` is annunciated at (`normal` while not active).
    pub fn level(&self, path: &str) -> Option<Level> {
        self.find(path).map(|i| self.alarms.level(i))
    }

    /// The evaluator itself, to read every alarm's state by number (the order of
    /// [`paths`](Self::paths)): since when, the shelf, a snapshot.
    pub fn evaluator(&self) -> &Alarms {
        &self.alarms
    }

    /// Alarms active now: raised, or latched and waiting for their reset.
    pub fn active(&self) -> usize {
        self.active
    }

    /// Alarms waiting for an acknowledgement.
    pub fn unacknowledged(&self) -> usize {
        self.unacknowledged
    }

    /// Transitions the journal only counted so far (a flood, or no journal room), in its
    /// `summarised` records; 0 without a journal.
    pub fn summarised(&self) -> u64 {
        self.sender.as_ref().map_or(0, JournalSender::summarised)
    }

    /// `by` acknowledges the alarm at `path`, at this cycle's time; journaled with who did
    /// it.
    pub fn acknowledge(&mut self, path: &str, by: Operator) -> Result<(), AlarmActionError> {
        let now = self.now_ns;
        self.act(path, by, |a, i, _| a.acknowledge(i, now))
    }

    /// `by` resets the latched alarm at `path` (its condition must have cleared); a reset
    /// also acknowledges it.
    pub fn reset(&mut self, path: &str, by: Operator) -> Result<(), AlarmActionError> {
        let now = self.now_ns;
        self.act(path, by, |a, i, _| a.reset(i, now))
    }

    /// `by` shelves the alarm at `path` for `duration` (at most 8 hours): it is not shown,
    /// and comes back by itself when the shelf expires.
    pub fn shelve(
        &mut self,
        path: &str,
        duration: Time,
        by: Operator,
    ) -> Result<(), AlarmActionError> {
        let now = self.now_ns;
        self.act(path, by, |a, i, user| a.shelve(i, now, duration, user))
    }

    /// `by` takes the alarm at `path` off its shelf.
    pub fn unshelve(&mut self, path: &str, by: Operator) -> Result<(), AlarmActionError> {
        let now = self.now_ns;
        self.act(path, by, |a, i, _| a.unshelve(i, now))
    }

    fn act(
        &mut self,
        path: &str,
        by: Operator,
        action: impl FnOnce(&mut Alarms, usize, &str) -> Result<AlarmEvent, ActionError>,
    ) -> Result<(), AlarmActionError> {
        let i = self
            .find(path)
            .ok_or_else(|| AlarmActionError::Unknown { path: path.into() })?;
        self.act_on(i, &by, action)
            .map_err(|error| AlarmActionError::Refused {
                path: path.into(),
                error,
            })?;
        self.recount();
        Ok(())
    }

    /// Does `action` to alarm `i` (a number below [`len`](Self::len)) for `by`, journaled.
    /// The counts are due again: the caller counts once after all its actions
    /// ([`recount`](Self::recount)), not once an alarm.
    pub(crate) fn act_on(
        &mut self,
        i: usize,
        by: &Operator,
        action: impl FnOnce(&mut Alarms, usize, &str) -> Result<AlarmEvent, ActionError>,
    ) -> Result<(), ActionError> {
        let event = action(&mut self.alarms, i, &by.user)?;
        if let Some(sender) = &self.sender {
            sender.record_action(&event, by.clone());
        }
        self.mark(i);
        self.recount = true;
        Ok(())
    }

    /// The cycle's UTC time, nanoseconds.
    pub(crate) fn now_ns(&self) -> i64 {
        self.now_ns
    }
}

/// Alarm `w`'s value and suppression in `gm`.
fn sample<T: Memory>(gm: &T, w: Watch) -> Sample {
    let suppressed = w
        .suppress
        .is_some_and(|(index, leaf)| gm.try_get(index, leaf) == Some(plc_core::Value::Bool(true)));
    // The paths were resolved against this program's variables: a value is always there.
    let value = gm
        .try_get(w.value.0, w.value.1)
        .unwrap_or(plc_core::Value::Bool(false));
    Sample::from_value(&value, suppressed)
}

/// Why an operator's action on an alarm was refused. Nothing changed, nothing was journaled.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum AlarmActionError {
    /// No alarm has this path.
    Unknown {
        /// The path given.
        path: String,
    },
    /// The alarm's state does not allow it.
    Refused {
        /// The alarm.
        path: String,
        /// Why.
        error: ActionError,
    },
}

impl fmt::Display for AlarmActionError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            AlarmActionError::Unknown { path } => write!(
                f,
                "no alarm at `{path}`: an alarm is named by the path of the value it watches \
                 (`door`, `stations[2].door`); `RuntimeAlarms::paths` lists them"
            ),
            AlarmActionError::Refused { path, error } => write!(f, "alarm `{path}`: {error}"),
        }
    }
}

impl std::error::Error for AlarmActionError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            AlarmActionError::Refused { error, .. } => Some(error),
            AlarmActionError::Unknown { .. } => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{AlarmActionError, RuntimeAlarms};
    use crate::alarm_journal::Operator;
    use plc_core::alarm::{ActionError, AlarmState};
    use plc_core::{GlobalMemory, PlcStruct, Time};

    #[derive(PlcStruct, Debug, Clone)]
    #[plc(crate = "plc_core")]
    struct Station {
        #[plc(alarm(text = "Station door open", suppress_when = "out_of_service"))]
        door: bool,
        out_of_service: bool,
    }

    #[derive(GlobalMemory, Debug, Clone)]
    #[plc(crate = "plc_core")]
    struct Gm {
        stations: [Station; 2],
    }

    fn op() -> Operator {
        Operator::new(Some(1000), "anna")
    }

    #[test]
    fn a_suppress_when_member_of_each_instance_suppresses_its_own_alarm() {
        let mut alarms = RuntimeAlarms::of(&plc_core::memory::Schema::of::<Gm>()).unwrap();
        assert_eq!(alarms.paths(), ["stations[0].door", "stations[1].door"]);
        let mut gm = Gm::default();
        gm.stations[0].out_of_service = true;
        gm.stations[0].door = true;
        gm.stations[1].door = true;
        alarms.set_now(5);
        alarms.evaluate(&gm);
        assert_eq!(
            alarms.state("stations[0].door"),
            Some(AlarmState::SuppressedByDesign)
        );
        assert_eq!(
            alarms.state("stations[1].door"),
            Some(AlarmState::ActiveUnacknowledged)
        );
        assert_eq!((alarms.active(), alarms.unacknowledged()), (1, 1));
        assert_eq!(alarms.counts_to_publish(), Some((1, 1)));
        assert_eq!(alarms.counts_to_publish(), None, "published once");
    }

    #[test]
    fn a_shelved_alarm_is_out_of_the_counts_until_its_shelf_expires() {
        let mut alarms = RuntimeAlarms::of(&plc_core::memory::Schema::of::<Gm>()).unwrap();
        let mut gm = Gm::default();
        gm.stations[1].door = true;
        alarms.set_now(1_000);
        alarms.evaluate(&gm);
        alarms
            .shelve("stations[1].door", Time::from_secs(60), op())
            .unwrap();
        assert_eq!(alarms.state("stations[1].door"), Some(AlarmState::Shelved));
        assert_eq!((alarms.active(), alarms.unacknowledged()), (0, 0));
        let too_long = alarms.shelve("stations[0].door", Time::from_secs(9 * 3600), op());
        assert!(matches!(
            too_long,
            Err(AlarmActionError::Refused {
                error: ActionError::ShelveDuration { .. },
                ..
            })
        ));
        alarms.set_now(1_000 + 61_000_000_000);
        alarms.evaluate(&gm);
        assert_eq!(
            alarms.state("stations[1].door"),
            Some(AlarmState::ActiveUnacknowledged),
            "back as a new alarm, its condition still holding"
        );
        let unknown = alarms.unshelve("stations[9].door", op()).unwrap_err();
        assert!(
            unknown
                .to_string()
                .contains("no alarm at `stations[9].door`")
        );
    }
}
