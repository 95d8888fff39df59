//! A restart restores what the evaluator had: the states folded from the records, given
//! back by path, behave as the evaluator that never stopped.

use super::super::record::{Entry, Operator, Record};
use super::super::{replay, restore};
use plc_core::Time;
use plc_core::alarm::{AlarmState, Alarms, Condition, Level, Limits, Sample};
use proptest::prelude::*;
use std::collections::BTreeMap;

const S: i64 = 1_000_000_000;

fn conditions() -> Vec<Condition> {
    let mut latched = Condition::discrete(true);
    latched.latched = true;
    let limits = Condition::limit(Limits {
        low_low: Some(0.0),
        low: Some(5.0),
        high: Some(80.0),
        high_high: Some(95.0),
        deadband: 0.0,
    });
    let mut latched_limits = limits;
    latched_limits.latched = true;
    vec![Condition::discrete(true), latched, limits, latched_limits]
}

fn paths() -> Vec<String> {
    ["door", "estop", "oil", "pressure"]
        .map(String::from)
        .to_vec()
}

/// The evaluator, its events recorded as the journal's writer would.
struct Run {
    alarms: Alarms,
    values: Vec<(f64, bool)>,
    now: i64,
    records: Vec<Record>,
}

impl Run {
    fn new() -> Run {
        Run {
            alarms: Alarms::new(conditions()).with_max_shelve(Time::from_secs(10)),
            values: vec![(0.0, false), (0.0, false), (50.0, false), (50.0, false)],
            now: 0,
            records: Vec::new(),
        }
    }

    fn cycle(&mut self) {
        let mut events = Vec::new();
        let values = self.values.clone();
        self.alarms.evaluate(
            self.now,
            |i| Sample {
                value: values[i].0,
                suppressed: values[i].1,
            },
            &mut events,
        );
        for e in events {
            self.push(&e, None);
        }
    }

    fn push(&mut self, e: &plc_core::alarm::AlarmEvent, by: Option<Operator>) {
        self.records.push(Record {
            seq: self.records.len() as u64 + 1,
            time_ns: e.time_ns,
            path: paths()[e.alarm].clone(),
            entry: Entry::from_event(e, self.values[e.alarm].0, by),
        });
    }

    fn act(&mut self, alarm: usize, op: u8) {
        let anna = Operator::new(Some(1000), "anna");
        let now = self.now;
        let done = match op {
            1 => self.alarms.acknowledge(alarm, now),
            2 => self.alarms.shelve(alarm, now, Time::from_secs(2), "anna"),
            3 => self.alarms.unshelve(alarm, now),
            4 => self.alarms.reset(alarm, now),
            _ => return,
        };
        if let Ok(e) = done {
            self.push(&e, Some(anna));
        }
    }
}

proptest! {
    /// Whatever happened before the stop: the evaluator given the folded states by path and
    /// the one that never stopped agree from the next cycle on.
    #[test]
    fn restored_states_behave_as_the_evaluator_that_never_stopped(
        steps in proptest::collection::vec(
            (0usize..4, -10.0f64..110.0, proptest::bool::weighted(0.1), 0i64..3, 0u8..8),
            1..150),
        last in proptest::collection::vec((-10.0f64..110.0, any::<bool>()), 4),
    ) {
        let mut run = Run::new();
        for (alarm, value, suppressed, dt, op) in steps {
            run.now += dt * S;
            run.values[alarm] = (if alarm < 2 { f64::from(u8::from(value > 50.0)) } else { value }, suppressed);
            run.cycle();
            run.act(alarm, op);
        }
        let mut states = BTreeMap::new();
        for r in &run.records {
            replay::apply(&mut states, r);
        }
        let mut restored = Alarms::new(conditions()).with_max_shelve(Time::from_secs(10));
        restore(&mut restored, &paths(), &states);
        // One more cycle for both, with the same values.
        run.now += S;
        for (i, (v, s)) in last.into_iter().enumerate() {
            run.values[i] = (if i < 2 { f64::from(u8::from(v > 50.0)) } else { v }, s);
        }
        let values = run.values.clone();
        let sample = |i: usize| Sample { value: values[i].0, suppressed: values[i].1 };
        run.alarms.evaluate(run.now, sample, &mut Vec::new());
        restored.evaluate(run.now, sample, &mut Vec::new());
        for i in 0..4 {
            let (a, b) = (run.alarms.snapshot(i), restored.snapshot(i));
            prop_assert_eq!(
                (a.level, a.acknowledged, a.held, &a.shelf),
                (b.level, b.acknowledged, b.held, &b.shelf),
                "alarm {} after {:?}", paths()[i], run.records
            );
            prop_assert_eq!(run.alarms.state(i), restored.state(i));
        }
    }
}

#[test]
fn restored_by_path_whatever_the_order_and_unknown_paths_reported() {
    let mut run = Run::new();
    run.values[0] = (1.0, false); // door raised
    run.values[2] = (99.0, false); // oil high-high
    run.now = 5 * S;
    run.cycle();
    run.act(2, 1); // oil acknowledged
    let mut states = BTreeMap::new();
    for r in &run.records {
        replay::apply(&mut states, r);
    }
    states.insert("gone".into(), replay::normal());

    // After an online change: oil first, door second, a new alarm, estop and pressure gone.
    let mut after = Alarms::new([conditions()[2], conditions()[0], Condition::discrete(true)]);
    let names = ["oil", "door", "fresh"].map(String::from);
    let report = restore(&mut after, &names, &states);
    assert_eq!(report.restored, ["oil", "door"]);
    assert_eq!(report.unknown, ["gone"]);
    assert_eq!(after.state(0), AlarmState::ActiveAcknowledged);
    assert_eq!(after.level(0), Level::HighHigh);
    assert_eq!(after.state(1), AlarmState::ActiveUnacknowledged);
    assert_eq!(after.since_ns(1), 5 * S);
    assert_eq!(after.state(2), AlarmState::Normal);
}
