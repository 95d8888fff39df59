//! Recovery while the bus is faulty: when to try ([`RecoveryTimer`]), one attempt on every
//! SubDevice ([`recover`], through the register access of `registers`), and what remains wrong
//! in words an operator can act on ([`describe`]).

mod registers;
mod sync0;

pub(super) use registers::Configured;
use registers::Outcome;
pub(super) use sync0::Sync0Setup;

use async_io::block_on;
use ethercrab::MainDevice;
use std::time::{Duration, Instant};

/// When recovery is due: at the first faulty exchange, then at most every `interval`, so a
/// bus that stays faulty costs a few datagrams per SubDevice per interval, not per cycle.
#[derive(Clone, Copy, Debug)]
pub(super) struct RecoveryTimer {
    interval: Duration,
    last: Option<Instant>,
}

impl RecoveryTimer {
    pub(super) fn new(interval: Duration) -> Self {
        RecoveryTimer {
            interval,
            last: None,
        }
    }

    /// Whether an attempt is due at `now`; if so, it counts as made.
    pub(super) fn due(&mut self, now: Instant) -> bool {
        let due = self
            .last
            .is_none_or(|t| now.saturating_duration_since(t) >= self.interval);
        if due {
            self.last = Some(now);
        }
        due
    }
}

/// One recovery attempt on every SubDevice in `configured` (ring order); the problems that
/// remain, as [`describe`] words them. `names` are the description's device names by position.
///
/// `pre_op` writes a device's start-up SDOs (by ring position) when a restarted one reaches
/// PRE-OP again, before it goes on to SAFE-OP.
pub(super) fn recover(
    md: &MainDevice<'static>,
    configured: &[Configured],
    names: &[String],
    eeprom_timeout: Duration,
    pre_op: &impl AsyncFn(u16) -> Result<(), String>,
) -> Vec<String> {
    let outcomes: Vec<_> = configured
        .iter()
        .map(|dev| {
            let outcome = block_on(registers::attempt(md, dev, eeprom_timeout, pre_op));
            (dev.position, dev.model.as_str(), outcome)
        })
        .collect();
    describe(&outcomes, names)
}

/// One line per SubDevice not in OP, from each one's ring position, model and outcome.
fn describe(outcomes: &[(u16, &str, Outcome)], names: &[String]) -> Vec<String> {
    let mut problems = Vec::new();
    let mut cut_off = false;
    for (position, model, outcome) in outcomes {
        let pos = usize::from(*position);
        let what = format!(
            "position {pos} (`{}`, {model})",
            names.get(pos).map_or("?", String::as_str),
        );
        match outcome {
            Outcome::Op => {}
            Outcome::NotOp(text) => problems.push(format!(
                "{what} is {text}; inputs stay invalid until it is back in OP"
            )),
            // Frames turn back before a device whose link is down, so every device behind it
            // is silent too: name the first one, where the cable or power is to check.
            Outcome::NoAnswer if !cut_off => {
                cut_off = true;
                let behind = if pos + 1 < outcomes.len() {
                    " (the SubDevices behind it are cut off too)"
                } else {
                    ""
                };
                problems.push(format!(
                    "{what} does not answer: check its power and the cable into it{behind}; \
                     it is brought back to OP when it answers again"
                ));
            }
            Outcome::NoAnswer => {}
        }
    }
    problems
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn recovery_is_due_at_once_then_once_per_interval() {
        let mut timer = RecoveryTimer::new(Duration::from_millis(100));
        let t0 = Instant::now();
        assert!(timer.due(t0), "the first faulty exchange tries at once");
        assert!(!timer.due(t0 + Duration::from_millis(99)));
        assert!(timer.due(t0 + Duration::from_millis(100)));
        assert!(
            !timer.due(t0 + Duration::from_millis(150)),
            "timed from the last attempt"
        );
        assert!(timer.due(t0 + Duration::from_millis(200)));
    }

    #[test]
    fn a_clock_reading_before_the_last_attempt_is_not_due() {
        let mut timer = RecoveryTimer::new(Duration::from_millis(100));
        let t0 = Instant::now() + Duration::from_secs(1);
        assert!(timer.due(t0));
        assert!(!timer.due(t0 - Duration::from_millis(500)));
    }

    fn names() -> Vec<String> {
        ["coupler", "inputs", "outputs"].map(String::from).to_vec()
    }

    #[test]
    fn a_healthy_bus_has_nothing_to_describe() {
        let all_op = [(0, "EK1100", Outcome::Op), (1, "EL1004", Outcome::Op)];
        assert!(describe(&all_op, &names()).is_empty());
    }

    #[test]
    fn a_device_out_of_op_is_named_with_its_state() {
        let outcomes = [
            (0, "EK1100", Outcome::Op),
            (
                1,
                "EL1004",
                Outcome::NotOp("in SAFE-OP with error 0x001B".into()),
            ),
        ];
        assert_eq!(
            describe(&outcomes, &names()),
            [
                "position 1 (`inputs`, EL1004) is in SAFE-OP with error 0x001B; inputs stay \
              invalid until it is back in OP"
            ]
        );
    }

    #[test]
    fn only_the_first_silent_device_is_named_and_those_behind_it_are_said_cut_off() {
        let outcomes = [
            (0, "EK1100", Outcome::Op),
            (1, "EL1004", Outcome::NoAnswer),
            (2, "EL2004", Outcome::NoAnswer),
        ];
        let problems = describe(&outcomes, &names());
        assert_eq!(problems.len(), 1, "{problems:?}");
        assert!(problems[0].starts_with("position 1 (`inputs`, EL1004) does not answer"));
        assert!(problems[0].contains("behind it are cut off too"));
    }

    #[test]
    fn the_last_silent_device_has_nothing_behind_it() {
        let outcomes = [(0, "EK1100", Outcome::Op), (1, "EL1004", Outcome::NoAnswer)];
        let problems = describe(&outcomes, &names());
        assert!(!problems[0].contains("cut off"), "{problems:?}");
    }

    #[test]
    fn a_position_beyond_the_description_is_named_by_a_question_mark() {
        let outcomes = [(5, "EL2004", Outcome::NotOp("in INIT".into()))];
        assert!(describe(&outcomes, &names())[0].starts_with("position 5 (`?`, EL2004)"));
    }
}
