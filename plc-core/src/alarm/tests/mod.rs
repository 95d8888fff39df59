//! The evaluator's transitions, one test each (the properties are in `properties`).

use super::*;
use crate::Time;
use std::vec::Vec;

const S: i64 = 1_000_000_000;

fn limits() -> Condition {
    Condition::limit(Limits {
        low_low: Some(0.0),
        low: Some(5.0),
        high: Some(80.0),
        high_high: Some(95.0),
        deadband: 1.0,
    })
}

/// One alarm stepped through `values` (one a second from t = 1 s), with its events.
struct One {
    alarms: Alarms,
    events: Vec<AlarmEvent>,
    now: i64,
}

impl One {
    fn new(c: Condition) -> One {
        One {
            alarms: Alarms::new([c]),
            events: Vec::new(),
            now: 0,
        }
    }

    /// Steps with `value` at `now + dt`, returning the kinds of this step's events.
    fn step_at(&mut self, dt: i64, value: f64, suppressed: bool) -> Vec<EventKind> {
        self.now += dt;
        self.events.clear();
        self.alarms
            .evaluate(self.now, |_| Sample { value, suppressed }, &mut self.events);
        assert!(self.events.iter().all(|e| e.time_ns == self.now));
        self.events.iter().map(|e| e.kind).collect()
    }

    fn step(&mut self, value: f64) -> Vec<EventKind> {
        self.step_at(S, value, false)
    }

    fn state(&self) -> AlarmState {
        self.alarms.state(0)
    }
}

#[test]
fn a_bool_alarm_goes_through_the_four_states_of_iec_62682() {
    let mut a = One::new(Condition::discrete(true));
    assert_eq!(a.step(0.0), []);
    assert_eq!(a.state(), AlarmState::Normal);
    assert_eq!(
        a.step(1.0),
        [EventKind::Raised {
            level: Level::Active
        }]
    );
    assert_eq!(a.state(), AlarmState::ActiveUnacknowledged);
    assert_eq!(a.alarms.since_ns(0), a.now);
    let ack = a.alarms.acknowledge(0, a.now + 5).unwrap();
    assert_eq!(
        (ack.kind, ack.time_ns),
        (EventKind::Acknowledged, a.now + 5)
    );
    assert_eq!(a.state(), AlarmState::ActiveAcknowledged);
    assert_eq!(
        a.step(0.0),
        [EventKind::Cleared {
            from: Level::Active
        }]
    );
    assert_eq!(a.state(), AlarmState::Normal);
    // Raised and cleared before anyone acknowledged it.
    a.step(1.0);
    a.step(0.0);
    assert_eq!(a.state(), AlarmState::ReturnedUnacknowledged);
    assert_eq!(a.alarms.unacknowledged(), 1);
    a.alarms.acknowledge(0, a.now).unwrap();
    assert_eq!(a.state(), AlarmState::Normal);
    assert_eq!(
        a.alarms.acknowledge(0, a.now),
        Err(ActionError::NotUnacknowledged)
    );
}

#[test]
fn an_active_low_bool_alarm_is_active_when_false() {
    let mut a = One::new(Condition::discrete(false));
    assert_eq!(
        a.step(0.0),
        [EventKind::Raised {
            level: Level::Active
        }]
    );
    assert_eq!(
        a.step(1.0),
        [EventKind::Cleared {
            from: Level::Active
        }]
    );
}

#[test]
fn a_limit_alarm_reports_each_level_and_returns_only_past_the_deadband() {
    let mut a = One::new(limits());
    assert_eq!(a.step(50.0), []);
    assert_eq!(a.step(80.0), [EventKind::Raised { level: Level::High }]);
    // Inside the deadband (80 - 1): still high, no event.
    assert_eq!(a.step(79.5), []);
    assert_eq!(a.alarms.level(0), Level::High);
    assert_eq!(
        a.step(96.0),
        [EventKind::LevelChanged {
            from: Level::High,
            to: Level::HighHigh
        }]
    );
    assert_eq!(Level::HighHigh.to_string(), "high-high");
    assert_eq!(a.step(94.5), [], "high-high holds down to 94");
    assert_eq!(
        a.step(93.9),
        [EventKind::LevelChanged {
            from: Level::HighHigh,
            to: Level::High
        }]
    );
    assert_eq!(a.step(78.9), [EventKind::Cleared { from: Level::High }]);
    assert_eq!(a.step(5.0), [EventKind::Raised { level: Level::Low }]);
    assert_eq!(a.step(5.9), [], "low holds up to 6");
    assert_eq!(
        a.step(-1.0),
        [EventKind::LevelChanged {
            from: Level::Low,
            to: Level::LowLow
        }]
    );
    assert_eq!(a.step(f64::NAN), [], "a failed reading says nothing");
    assert_eq!(
        a.step(7.0),
        [EventKind::Cleared {
            from: Level::LowLow
        }]
    );
}

#[test]
fn escalation_asks_for_a_new_acknowledgement_and_de_escalation_does_not() {
    let mut a = One::new(limits());
    a.step(85.0);
    a.alarms.acknowledge(0, a.now).unwrap();
    a.step(99.0);
    assert_eq!(a.state(), AlarmState::ActiveUnacknowledged);
    a.alarms.acknowledge(0, a.now).unwrap();
    a.step(85.0);
    assert_eq!(a.state(), AlarmState::ActiveAcknowledged);
}

#[test]
fn the_on_delay_raises_only_a_condition_that_held_for_the_whole_delay() {
    let mut c = Condition::discrete(true);
    c.delay = Time::from_secs(2);
    let mut a = One::new(c);
    assert_eq!(a.step_at(S, 1.0, false), []);
    assert_eq!(a.step_at(S, 1.0, false), [], "1 s of 2");
    assert_eq!(
        a.step_at(S / 2, 0.0, false),
        [],
        "gone before the delay ran out"
    );
    assert_eq!(a.step_at(S, 1.0, false), []);
    assert_eq!(a.step_at(S, 1.0, false), []);
    assert_eq!(
        a.step_at(S, 1.0, false),
        [EventKind::Raised {
            level: Level::Active
        }],
        "2 s since it came back"
    );
    // Clearing is not delayed.
    assert_eq!(
        a.step_at(1, 0.0, false),
        [EventKind::Cleared {
            from: Level::Active
        }]
    );
}

#[test]
fn a_latched_alarm_stays_until_reset_and_a_reset_while_active_is_refused() {
    let mut c = Condition::discrete(true);
    c.latched = true;
    let mut a = One::new(c);
    a.step(1.0);
    assert_eq!(
        a.alarms.reset(0, a.now),
        Err(ActionError::StillActive),
        "refused while its condition holds"
    );
    assert_eq!(
        a.step(0.0),
        [EventKind::ConditionCleared {
            level: Level::Active
        }]
    );
    assert_eq!(
        a.state(),
        AlarmState::Latched {
            acknowledged: false
        }
    );
    assert_eq!(a.step(0.0), []);
    assert_eq!(a.step(1.0), [], "back at the level it holds");
    assert_eq!(a.state(), AlarmState::ActiveUnacknowledged);
    a.step(0.0);
    let reset = a.alarms.reset(0, a.now).unwrap();
    assert_eq!(reset.kind, EventKind::Reset);
    assert_eq!(a.state(), AlarmState::Normal, "a reset acknowledges");
    assert_eq!(a.alarms.reset(0, a.now), Err(ActionError::NotHeld));
    let mut plain = One::new(Condition::discrete(true));
    plain.step(1.0);
    assert_eq!(plain.alarms.reset(0, 0), Err(ActionError::NotLatched));
}

#[test]
fn a_shelved_alarm_is_quiet_and_comes_back_by_itself_when_the_shelf_expires() {
    let mut a = One::new(Condition::discrete(true));
    a.step(1.0);
    let shelved = a
        .alarms
        .shelve(0, a.now, Time::from_secs(10), "operator 7")
        .unwrap();
    let until_ns = a.now + 10 * S;
    assert_eq!(shelved.kind, EventKind::Shelved { until_ns });
    assert_eq!(a.state(), AlarmState::Shelved);
    let shelf = a.alarms.shelf(0).unwrap();
    assert_eq!(
        (shelf.by.as_str(), shelf.until_ns),
        ("operator 7", until_ns)
    );
    assert_eq!(a.alarms.unacknowledged(), 0);
    assert_eq!(a.step(0.0), []);
    assert_eq!(a.step(1.0), [], "changes while shelved raise nothing");
    assert_eq!(a.step_at(7 * S, 1.0, false), [], "9 s of 10");
    assert_eq!(
        a.step(1.0),
        [
            EventKind::Unshelved { expired: true },
            EventKind::Raised {
                level: Level::Active
            }
        ],
        "still active when the shelf expires: raised again"
    );
    assert_eq!(a.alarms.unshelve(0, a.now), Err(ActionError::NotShelved));
}

#[test]
fn a_shelf_is_at_most_8_hours_unless_the_program_says_otherwise() {
    let mut alarms = Alarms::new([Condition::discrete(true)]);
    let max = ActionError::ShelveDuration {
        max: DEFAULT_MAX_SHELVE,
    };
    assert_eq!(
        alarms.shelve(0, 0, Time::from_secs(8 * 3600 + 1), "op"),
        Err(max)
    );
    assert_eq!(alarms.shelve(0, 0, Time::from_secs(0), "op"), Err(max));
    assert!(alarms.shelve(0, 0, Time::from_secs(8 * 3600), "op").is_ok());
    let mut day = Alarms::new([Condition::discrete(true)]).with_max_shelve(Time::from_secs(86400));
    assert!(day.shelve(0, 0, Time::from_secs(86400), "op").is_ok());
    assert_eq!(
        day.acknowledge(3, 0),
        Err(ActionError::Unknown { alarm: 3 })
    );
}

#[test]
fn an_operator_unshelves_and_the_alarm_is_evaluated_the_next_cycle() {
    let mut a = One::new(Condition::discrete(true));
    a.alarms
        .shelve(0, a.now, Time::from_secs(60), "op")
        .unwrap();
    a.step(1.0);
    let e = a.alarms.unshelve(0, a.now).unwrap();
    assert_eq!(e.kind, EventKind::Unshelved { expired: false });
    assert_eq!(
        a.step(1.0),
        [EventKind::Raised {
            level: Level::Active
        }]
    );
}

#[test]
fn suppression_by_design_silences_the_alarm_while_its_bool_is_true() {
    let mut a = One::new(Condition::discrete(true));
    a.step(1.0);
    assert_eq!(a.step_at(S, 1.0, true), [EventKind::Suppressed]);
    assert_eq!(a.state(), AlarmState::SuppressedByDesign);
    assert_eq!(a.alarms.unacknowledged(), 0, "nothing to acknowledge");
    assert_eq!(a.step_at(S, 0.0, true), []);
    assert_eq!(a.step_at(S, 1.0, true), []);
    assert_eq!(
        a.step_at(S, 1.0, false),
        [
            EventKind::Unsuppressed,
            EventKind::Raised {
                level: Level::Active
            }
        ]
    );
    assert_eq!(a.step_at(S, 0.0, true), [EventKind::Suppressed]);
    assert_eq!(a.step_at(S, 0.0, false), [EventKind::Unsuppressed]);
    assert_eq!(a.state(), AlarmState::Normal);
}

#[test]
fn nothing_changing_pushes_no_event_and_leaves_the_vector_alone() {
    let mut alarms = Alarms::new((0..100).map(|i| {
        if i % 2 == 0 {
            Condition::discrete(true)
        } else {
            limits()
        }
    }));
    let mut events = Vec::new();
    alarms.evaluate(0, |_| Sample::bool(false, false), &mut events);
    let mut events = Vec::new();
    for t in 1..100 {
        alarms.evaluate(t, |_| Sample::bool(false, false), &mut events);
    }
    assert!(events.is_empty());
    assert_eq!(events.capacity(), 0, "no allocation");
}

#[test]
fn a_declaration_numbers_its_alarms_by_path() {
    use crate::{GlobalMemory, PlcStruct};
    #[derive(PlcStruct, Debug, Clone)]
    #[plc(crate = "crate")]
    struct Station {
        #[plc(alarm(text = "Door open", suppress_when = "off", latched))]
        door: bool,
        off: bool,
    }
    #[derive(GlobalMemory, Debug, Clone)]
    #[plc(crate = "crate")]
    struct Gm {
        speed: f32,
        stations: [Station; 3],
        #[plc(alarm(text = "Oil", high = 80, severity = 700, delay = "1.5s"))]
        oil: f64,
        #[plc(alarm(text = "Jam", suppress_when = "stations[1].off"))]
        jam: bool,
    }
    let a = Gm::ALARMS;
    assert_eq!(a.len(), 5);
    let paths = alarm_paths(Gm::VARIABLES, a);
    assert_eq!(
        paths,
        [
            "stations[0].door",
            "stations[1].door",
            "stations[2].door",
            "oil",
            "jam"
        ]
    );
    // Each station's door by its own station's `off` (leaves: door 0, off 1 per station).
    assert_eq!(
        (a[2].index, a[2].leaf, a[2].suppress_when),
        (1, 4, SuppressWhen::At { index: 1, leaf: 5 })
    );
    assert!(a[2].condition.latched);
    assert_eq!(
        (a[3].severity, a[3].condition.delay),
        (700, Time::from_millis(1500))
    );
    assert_eq!(a[0].severity, 500);
    assert_eq!(
        resolve_suppress(Gm::VARIABLES, a[4].suppress_when),
        Ok(Some((1, 3)))
    );
    assert!(resolve_suppress(Gm::VARIABLES, SuppressWhen::Path("speed")).is_err());
    assert!(resolve_suppress(Gm::VARIABLES, SuppressWhen::Path("nothing")).is_err());
}

#[test]
fn a_restored_state_survives_a_restart_and_meets_the_condition_of_now() {
    let mut before = One::new(limits());
    before.step(85.0);
    before.step(50.0);
    let kept = before.alarms.snapshot(0);
    assert_eq!(before.state(), AlarmState::ReturnedUnacknowledged);
    let mut after = One::new(limits());
    after.alarms.restore(0, kept.clone()).unwrap();
    assert_eq!(
        after.state(),
        AlarmState::ReturnedUnacknowledged,
        "still waiting"
    );
    assert_eq!(after.step(50.0), []);
    assert_eq!(after.alarms.snapshot(0), kept);
    // Active before the restart, normal after it: it clears on the first cycle.
    before.step(99.0);
    let mut after = One::new(limits());
    after.alarms.restore(0, before.alarms.snapshot(0)).unwrap();
    assert_eq!(after.state(), AlarmState::ActiveUnacknowledged);
    assert_eq!(
        after.step(50.0),
        [EventKind::Cleared {
            from: Level::HighHigh
        }]
    );
    // Still active: nothing new, and the deadband counts from the kept level.
    let mut again = One::new(limits());
    again.alarms.restore(0, before.alarms.snapshot(0)).unwrap();
    assert_eq!(again.step(94.5), []);
    assert_eq!(again.alarms.level(0), Level::HighHigh);
    assert_eq!(
        again.alarms.restore(1, before.alarms.snapshot(0)),
        Err(ActionError::Unknown { alarm: 1 })
    );
}

#[test]
fn a_sample_of_any_value_a_program_holds() {
    use crate::Value;
    assert_eq!(
        Sample::from_value(&Value::Bool(true), false),
        Sample::bool(true, false)
    );
    assert_eq!(Sample::from_value(&Value::Int(-3), true).value, -3.0);
    assert_eq!(Sample::from_value(&Value::UInt(7), false).value, 7.0);
    assert_eq!(Sample::from_value(&Value::Real(2.5), false).value, 2.5);
    assert!(
        Sample::from_value(&Value::Time(Time::from_secs(1)), false)
            .value
            .is_nan()
    );
}

mod properties;
