//! Properties of the evaluator over random values, suppression, delays and operators.

use super::*;
use proptest::prelude::*;

proptest! {
    /// Whatever the values, suppression and delays: every state is one of the diagram's,
    /// a raise always comes before its clear, and an alarm is active only at a level its
    /// value reached.
    #[test]
    fn any_values_keep_the_state_machine_consistent(
        steps in proptest::collection::vec((-10.0f64..110.0, any::<bool>(), 0i64..3), 1..200),
        delay in 0i64..3,
        latched in any::<bool>(),
    ) {
        let mut c = limits();
        c.delay = Time::from_secs(delay);
        c.latched = latched;
        let mut a = One::new(c);
        let mut active = false;
        for (value, suppressed, dt) in steps {
            for k in a.step_at(dt * S, value, suppressed) {
                match k {
                    EventKind::Raised { level } => {
                        prop_assert!(!active);
                        prop_assert!(level != Level::Normal);
                        active = true;
                    }
                    EventKind::Cleared { .. } => {
                        prop_assert!(active);
                        active = false;
                    }
                    EventKind::Suppressed => active = false,
                    EventKind::LevelChanged { from, to } => {
                        prop_assert!(active && from != to);
                    }
                    EventKind::ConditionCleared { .. } => prop_assert!(latched && active),
                    _ => {}
                }
            }
            if matches!(a.state(), AlarmState::Latched { .. }) {
                prop_assert!(latched);
                // A reset clears it; the next raise is a raise.
                a.alarms.reset(0, a.now).unwrap();
                active = false;
            }
            prop_assert_eq!(suppressed, a.state() == AlarmState::SuppressedByDesign);
            if a.alarms.level(0) == Level::HighHigh {
                prop_assert!(value >= 94.0);
            }
        }
    }

    /// With operators acknowledging, shelving and unshelving at random: an action is
    /// refused exactly when the state says it has nothing to act on, a shelved or
    /// suppressed alarm asks nobody for anything, and a shelf never outlives its end.
    #[test]
    fn operator_actions_agree_with_the_state(
        steps in proptest::collection::vec(
            (-10.0f64..110.0, any::<bool>(), 0i64..3, 0u8..4), 1..200),
        delay in 0i64..2,
    ) {
        let mut c = limits();
        c.delay = Time::from_secs(delay);
        let mut a = One::new(c);
        for (value, suppressed, dt, action) in steps {
            a.step_at(dt * S, value, suppressed);
            let state = a.state();
            if matches!(state, AlarmState::Shelved | AlarmState::SuppressedByDesign) {
                prop_assert!(!state.unacknowledged());
            }
            if let Some(shelf) = a.alarms.shelf(0) {
                prop_assert!(a.now < shelf.until_ns);
            }
            let now = a.now;
            match action {
                1 => prop_assert_eq!(
                    a.alarms.acknowledge(0, now).is_ok(),
                    state.unacknowledged()
                ),
                2 => {
                    a.alarms.shelve(0, now, Time::from_secs(2), "op").unwrap();
                    prop_assert_eq!(a.alarms.unacknowledged(), 0);
                }
                3 => {
                    let shelved = a.alarms.shelf(0).is_some();
                    prop_assert_eq!(a.alarms.unshelve(0, now).is_ok(), shelved);
                }
                _ => {}
            }
        }
    }
}
