//! One running program as a Sparkplug device: its metrics (every basic value, named by its
//! path), what was last sent of each, and its births, data and commands.

use crate::alarm_counts::{self, Counts};
use crate::alarm_states;
use crate::metric::{self, DataType};
use crate::proto::{Metric, Payload};
use plc_core::Value;
use plc_shm::{AlarmEntry, DynSegment, OwnerState, PathLocation, PathTarget};
use std::time::{Duration, Instant, SystemTime};

/// At most this many metrics per device: a birth of more would not fit a broker's message
/// limit anyway (about 60 bytes each), and the walk over a damaged descriptor stays bounded.
pub const MAX_METRICS: usize = 100_000;

/// How a device sends its data.
#[derive(Clone, Copy, Debug)]
pub struct DataPolicy {
    /// A number is sent when it moved by more than this since it was last sent (0: every
    /// change), unless it declares a deadband of its own (`#[plc(deadband = ...)]`).
    pub deadband: f64,
    /// At least this long between two values of one metric (zero: no limit); a change held
    /// back is sent when the time is up, as its latest value.
    pub min_interval: Duration,
}

/// One metric: where its value lies and what was last sent of it.
struct Entry {
    at: PathLocation,
    datatype: DataType,
    sent: Option<Value>,
    sent_at: Option<Instant>,
}

/// A segment attached and published as a device.
pub struct Device {
    /// The device id: the segment's name as given.
    pub id: String,
    seg: DynSegment,
    entries: Vec<Entry>,
    last_cycle: u64,
    /// The alarm counts last sent.
    alarms_sent: Counts,
    /// Each alarm's state last sent.
    states_sent: Vec<AlarmEntry>,
}

/// Milliseconds since the Unix epoch now.
pub fn now_ms() -> u64 {
    SystemTime::now()
        .duration_since(SystemTime::UNIX_EPOCH)
        .map_or(0, |d| d.as_millis() as u64)
}

impl Device {
    /// Attaches to segment `name`.
    pub fn attach(name: &str) -> Result<Device, String> {
        let seg = DynSegment::attach(name).map_err(|e| e.to_string())?;
        let entries = leaves(&seg)?
            .into_iter()
            .map(|at| Entry {
                datatype: DataType::of(at.var.iec_type),
                at,
                sent: None,
                sent_at: None,
            })
            .collect();
        Ok(Device {
            id: name.to_string(),
            seg,
            entries,
            last_cycle: u64::MAX,
            alarms_sent: [0; 2],
            states_sent: Vec::new(),
        })
    }

    /// Whether its program still runs: a program stopped, failed or gone is a dead device.
    pub fn alive(&self) -> bool {
        matches!(
            self.seg.owner_state(),
            OwnerState::Running | OwnerState::Stalled
        )
    }

    /// The descriptor's layout hash: a program that came back with another declaration has
    /// another.
    pub fn layout_hash(&self) -> u64 {
        self.seg.descriptor().layout_hash
    }

    /// The time of the values just read: the cycle's UTC time when the segment gives one
    /// (read with the snapshot, so at most one cycle late), else now; the cycle's number and
    /// the program's alarm counts.
    fn value_time(&self) -> (u64, u64, Counts) {
        let status = self.seg.status();
        let ms = if status.cycle_utc_ns > 0 {
            status.cycle_utc_ns / 1_000_000
        } else {
            now_ms()
        };
        (ms, status.cycle_count, alarm_counts::of(&status))
    }

    /// The DBIRTH payload (seq to be set by the node): every metric with its name, alias,
    /// datatype, properties and current value; what is sent becomes the base of the deadband.
    pub fn birth(&mut self) -> Result<Payload, String> {
        let image = self.seg.snapshot_bytes().map_err(|e| e.to_string())?;
        let (ts, cycle, alarms) = self.value_time();
        self.last_cycle = cycle;
        let now = Instant::now();
        let mut metrics = Vec::with_capacity(self.entries.len());
        for (alias, e) in self.entries.iter_mut().enumerate() {
            let value = e.at.var.value_in(&image, 0);
            let mut m = Metric {
                name: Some(e.at.path.clone()),
                alias: Some(alias as u64),
                timestamp: Some(ts),
                datatype: Some(e.datatype.code()),
                properties: Some(metric::properties(&e.at.var, e.at.writable)),
                ..Metric::default()
            };
            set_value(&mut m, e.datatype, value.as_ref());
            e.sent = value;
            e.sent_at = Some(now);
            metrics.push(m);
        }
        metrics.extend(alarm_counts::birth(alarms, self.entries.len(), ts));
        self.alarms_sent = alarms;
        let states = self.alarm_states()?;
        metrics.extend(alarm_states::birth(
            self.seg.alarms(),
            &states,
            self.first_state_alias(),
            ts,
        ));
        self.states_sent = states;
        Ok(Payload {
            timestamp: Some(now_ms()),
            metrics,
            ..Payload::default()
        })
    }

    /// A DDATA payload of the metrics that changed beyond the deadband (and whose rate limit
    /// lets them go), by alias only; `None` when nothing is to be sent. `historical` ones (for
    /// the store, sent after a later birth) carry names, which stay true if the program comes
    /// back with another declaration, and `is_historical`.
    pub fn changes(
        &mut self,
        policy: &DataPolicy,
        historical: bool,
    ) -> Result<Option<Payload>, String> {
        let (ts, cycle, alarms) = self.value_time();
        let held = policy.min_interval > Duration::ZERO;
        // Without a new cycle nothing changed, unless a change is being held by the rate limit.
        if cycle == self.last_cycle && !held {
            return Ok(None);
        }
        self.last_cycle = cycle;
        let image = self.seg.snapshot_bytes().map_err(|e| e.to_string())?;
        let now = Instant::now();
        let mut metrics = Vec::new();
        for (alias, e) in self.entries.iter_mut().enumerate() {
            let value = e.at.var.value_in(&image, 0);
            let changed = match (&e.sent, &value) {
                (Some(s), Some(v)) => {
                    metric::exceeds_deadband(s, v, metric::deadband(&e.at.var, policy.deadband))
                }
                (None, None) => false,
                _ => true,
            };
            if !changed
                || e.sent_at
                    .is_some_and(|t| now.duration_since(t) < policy.min_interval)
            {
                continue;
            }
            let mut m = Metric {
                timestamp: Some(ts),
                ..Metric::default()
            };
            if historical {
                m.name = Some(e.at.path.clone());
                m.is_historical = Some(true);
            } else {
                m.alias = Some(alias as u64);
            }
            set_value(&mut m, e.datatype, value.as_ref());
            e.sent = value;
            e.sent_at = Some(now);
            metrics.push(m);
        }
        let first = self.entries.len();
        metrics.extend(alarm_counts::changed(
            alarms,
            self.alarms_sent,
            first,
            ts,
            historical,
        ));
        self.alarms_sent = alarms;
        let states = self.alarm_states()?;
        metrics.extend(alarm_states::changed(
            self.seg.alarms(),
            &states,
            &self.states_sent,
            self.first_state_alias(),
            historical,
        ));
        self.states_sent = states;
        Ok((!metrics.is_empty()).then(|| Payload {
            timestamp: Some(now_ms()),
            metrics,
            ..Payload::default()
        }))
    }

    /// Applies a DCMD's metrics through the one write path: each found by alias or name and
    /// checked as the program checks a write; all are sent as one request, or none if one is
    /// refused. Returns how many values were written, or why none was.
    pub fn command(&self, payload: &Payload) -> Result<usize, String> {
        // One request holds at most this many writes.
        if payload.metrics.len() > plc_shm::limits::MAX_WRITES {
            return Err(format!(
                "{} metrics in one command; at most {} are written at once",
                payload.metrics.len(),
                plc_shm::limits::MAX_WRITES
            ));
        }
        let mut checked = Vec::with_capacity(payload.metrics.len());
        for m in &payload.metrics {
            if alarm_counts::is_named(m, self.entries.len()) {
                return Err(format!(
                    "the alarm counts ({}) are read-only: they count the program's alarms",
                    alarm_counts::NAMES.join(", ")
                ));
            }
            if self.is_alarm_state(m) {
                return Err(
                    "the alarms' metrics (`Alarms/<path>/...`) are read-only: an \
                            operator acknowledges with `plc ack` or over OPC UA"
                        .into(),
                );
            }
            let entry = self.find(m)?;
            let value = metric::from_payload(entry.at.var.iec_type, m.value.as_ref())
                .map_err(|e| format!("metric `{}`: {e}", entry.at.path))?;
            let write = plc_core::write::Write {
                index: entry.at.index,
                leaf: entry.at.leaf,
                value,
            };
            checked.push(
                self.seg
                    .check_write(write)
                    .map_err(|e| format!("metric `{}`: {e}", entry.at.path))?,
            );
        }
        if checked.is_empty() {
            return Ok(0);
        }
        self.seg
            .write_checked(&checked)
            .map_err(|e| e.to_string())?;
        Ok(checked.len())
    }

    /// Every alarm's state, as the segment's table holds it.
    fn alarm_states(&self) -> Result<Vec<AlarmEntry>, String> {
        self.seg.alarm_states().map_err(|e| e.to_string())
    }

    /// The alias of the first alarm's first metric: after the variables and the counts.
    fn first_state_alias(&self) -> usize {
        self.entries.len() + alarm_counts::NAMES.len()
    }

    /// Whether a command's metric names an alarm's metric (by alias past the counts, or by a
    /// name under `Alarms/`, where no variable's path lies).
    fn is_alarm_state(&self, m: &Metric) -> bool {
        let first = self.first_state_alias() as u64;
        let count = (self.seg.alarms().len() * alarm_states::PER_ALARM) as u64;
        match (m.alias, &m.name) {
            (Some(a), _) => a >= first && a < first + count,
            (None, Some(n)) => n.starts_with("Alarms/"),
            (None, None) => false,
        }
    }

    /// The metric a command names: by alias (what hosts send once a birth defined one), else
    /// by name.
    fn find(&self, m: &Metric) -> Result<&Entry, String> {
        if let Some(alias) = m.alias {
            return usize::try_from(alias)
                .ok()
                .and_then(|a| self.entries.get(a))
                .ok_or_else(|| format!("no metric has alias {alias}"));
        }
        let Some(name) = &m.name else {
            return Err("a metric with neither name nor alias".into());
        };
        self.entries
            .iter()
            .find(|e| e.at.path == *name)
            .ok_or_else(|| format!("no metric is named `{}`", name.escape_debug()))
    }
}

/// Puts `value` into `m` as datatype `dt` says, or marks it null (a damaged image).
fn set_value(m: &mut Metric, dt: DataType, value: Option<&Value>) {
    match value.and_then(|v| metric::to_payload(dt, v)) {
        Some(v) => m.value = Some(v),
        None => m.is_null = Some(true),
    }
}

/// Every basic value of the segment, member by member and element by element, named by its
/// path as `plc get` takes it (`axes[1].pos`).
fn leaves(seg: &DynSegment) -> Result<Vec<PathLocation>, String> {
    let mut out = Vec::new();
    let mut todo: Vec<String> = seg
        .descriptor()
        .variables
        .iter()
        .rev()
        .map(|v| v.name.clone())
        .collect();
    while let Some(p) = todo.pop() {
        match seg.resolve_path(&p).map_err(|e| e.to_string())? {
            PathTarget::Value(at) => out.push(*at),
            PathTarget::Group(children) => todo.extend(children.into_iter().rev()),
        }
        if out.len() + todo.len() > MAX_METRICS {
            return Err(format!(
                "segment `{}` holds more than {MAX_METRICS} values: more than one device's \
                 birth can carry",
                seg.name()
            ));
        }
    }
    Ok(out)
}
