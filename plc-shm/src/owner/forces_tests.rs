//! The force table's tests: forces, re-forces, releases and what the log is sent.

use super::super::force_log::{Ended, ForceLogReader};
use super::super::spent::{Spent, SpentTx};
use super::*;
use crate::limits::{FORCE_LOG_LINES, MAX_WRITES};
use plc_core::GlobalMemory;
use plc_core::write::{Write, check_force};
use std::sync::mpsc::Receiver;

#[derive(plc_core::GlobalMemory, Debug, Clone)]
struct Gm {
    speed: i32,
    values: [i32; 256],
}

const SPEED: usize = 0;
const VALUES: usize = 1;

fn table() -> (ForceTable<Gm>, ForceLogReader) {
    let (table, reader, _) = table_and_spent();
    (table, reader)
}

/// A table and what its log could not take, to be freed off the cycle thread.
fn table_and_spent() -> (ForceTable<Gm>, ForceLogReader, Receiver<Spent>) {
    let (spent, freed) = SpentTx::channel(1);
    let (log, reader) = ForceLog::channel(FORCE_LOG_LINES, spent);
    (ForceTable::new(Gm::VARIABLES, log), reader, freed)
}

fn forced(index: usize, leaf: usize, v: i64) -> Checked {
    let write = Write {
        index,
        leaf,
        value: Value::Int(v),
    };
    check_force(Gm::VARIABLES, write).unwrap()
}

/// A release of every force, each value set back to what it was before its first force.
fn every_restored() -> Release {
    Release {
        id: 2,
        restore: true,
        all: true,
        values: Vec::new(),
    }
}

fn release(values: &[(usize, usize)], restore: bool) -> Release {
    Release {
        id: 1,
        restore,
        all: false,
        values: values.to_vec(),
    }
}

#[test]
fn the_cycle_holds_the_last_value_forced_whether_or_not_it_changed() {
    let (mut forces, _log) = table();
    let mut gm = Gm::default();
    let at = |v: i64| (0..256).map(|k| forced(VALUES, k, v)).collect::<Vec<_>>();
    forces.force(&mut gm, at(5), 1000, 0).unwrap();
    // The same values again (nothing the cycle writes changes), then new ones.
    forces.force(&mut gm, at(5), 1001, 1).unwrap();
    let mut other = Gm::default();
    forces.apply(&mut other);
    assert!(other.values.iter().all(|&v| v == 5));
    forces.force(&mut gm, at(6), 1002, 2).unwrap();
    forces.apply(&mut other);
    assert!(other.values.iter().all(|&v| v == 6));
    // Who forced last and when is kept even when the value did not change.
    forces.force(&mut gm, at(6), 1003, 3).unwrap();
    assert!(forces.refusal(VALUES, 9).unwrap().contains("by uid 1003"));
    // A release with restore goes back to the value from before the first force.
    forces.release(&mut gm, &every_restored(), 1000, 4).unwrap();
    assert!(gm.values.iter().all(|&v| v == 0));
}

#[test]
fn a_re_force_keeps_the_first_before_and_refusals_name_who_forced() {
    let (mut forces, _log) = table();
    let mut gm = Gm {
        speed: 3,
        ..Gm::default()
    };
    forces
        .force(&mut gm, vec![forced(SPEED, 0, 7)], 1000, 0)
        .unwrap();
    forces
        .force(&mut gm, vec![forced(SPEED, 0, 9)], 1001, 0)
        .unwrap();
    assert_eq!((forces.len(), gm.speed), (1, 9), "one force, the new value");
    let why = forces.refusal(SPEED, 0).unwrap();
    assert!(
        why.starts_with("`speed` is forced (by uid 1001 since "),
        "{why}"
    );
    assert_eq!(
        forces.refusal(VALUES, 0),
        None,
        "only the forced value is refused"
    );
    gm.speed = 100;
    forces.apply(&mut gm);
    assert_eq!(gm.speed, 9, "held at both boundaries");
    forces
        .release(&mut gm, &release(&[(SPEED, 0)], true), 1000, 0)
        .unwrap();
    assert_eq!(
        (forces.len(), gm.speed),
        (0, 3),
        "restored to before the first"
    );
    assert_eq!(forces.refusal(SPEED, 0), None);
}

#[test]
fn a_release_of_a_value_not_forced_is_refused_naming_it_and_ends_nothing() {
    let (mut forces, _log) = table();
    let mut gm = Gm::default();
    let writes = [
        forced(VALUES, 4, 1),
        forced(VALUES, 5, 2),
        forced(SPEED, 0, 3),
    ];
    forces.force(&mut gm, writes.to_vec(), 1000, 0).unwrap();
    let named = release(&[(VALUES, 5), (VALUES, 6)], false);
    let refused = forces.release(&mut gm, &named, 1000, 0).unwrap_err();
    assert_eq!(refused.which, 1);
    assert!(
        refused.why.starts_with("`values[6]` is not forced"),
        "{}",
        refused.why
    );
    assert_eq!(forces.len(), 3, "all or none");
    // Values the program does not have, as a hostile tool may name them.
    for (index, leaf) in [(u32::MAX as usize, 0), (VALUES, 9999), (SPEED, 1)] {
        let named = release(&[(SPEED, 0), (index, leaf)], false);
        let refused = forces.release(&mut gm, &named, 1000, 0).unwrap_err();
        assert_eq!(refused.which, 1);
        assert_eq!(
            refused.why,
            format!("no value {index}/{leaf}: the program has none")
        );
    }
    assert_eq!(forces.len(), 3, "all or none");
    // A value named twice is released once; the others keep their places in the index.
    let twice = release(&[(VALUES, 5), (VALUES, 5)], false);
    // One more than the limit is refused, whole, saying how many it adds.
    let over: Vec<Checked> = (0..256)
        .filter(|k| ![4, 5].contains(k))
        .map(|k| forced(VALUES, k, 1))
        .collect();
    let refused = forces.force(&mut gm, over, 1000, 0).unwrap_err();
    assert!(
        refused
            .why
            .starts_with("3 forces are held and this request adds 254"),
        "{}",
        refused.why
    );
    assert_eq!((forces.len(), gm.values[7]), (3, 0));
    assert_eq!(
        MAX_FORCES, 256,
        "the count above is 3 + 254 = MAX_FORCES + 1"
    );
    forces.release(&mut gm, &twice, 1000, 0).unwrap();
    assert_eq!(forces.len(), 2);
    assert!(forces.refusal(VALUES, 5).is_none());
    assert!(forces.refusal(VALUES, 4).is_some() && forces.refusal(SPEED, 0).is_some());
    (gm.values[4], gm.speed) = (0, 0);
    forces.apply(&mut gm);
    assert_eq!((gm.values[4], gm.speed), (1, 3));
}

#[test]
fn a_flood_of_re_forces_sends_plain_events_and_counts_what_did_not_fit() {
    let (mut forces, mut log, freed) = table_and_spent();
    let mut gm = Gm::default();
    // 257 copies of one value are one force: not above the limit.
    let copies = vec![forced(VALUES, 0, 1); 257];
    forces.force(&mut gm, copies, 1000, 5).unwrap();
    assert_eq!(forces.len(), 1);
    // One event per request, naming every value of it.
    let values = |events: &[ForceEvent]| events.iter().map(ForceEvent::values).sum::<usize>();
    let (events, dropped) = log.take_events();
    assert_eq!((events.len(), values(&events), dropped), (1, 257, 0));
    let all: Vec<Checked> = (0..256).map(|k| forced(VALUES, k, 1)).collect();
    forces.force(&mut gm, all.clone(), 1000, 5).unwrap();
    let (events, dropped) = log.take_events();
    assert_eq!((values(&events), dropped), (256, 0));
    // A request of 256 re-forces and one of 1,024 of the 256 held values: the log holds
    // FORCE_LOG_LINES values waiting, and a request that does not fit is counted whole.
    forces.force(&mut gm, all.clone(), 1000, 5).unwrap();
    let again: Vec<Checked> = (0..MAX_WRITES)
        .map(|k| forced(VALUES, k % 256, 2))
        .collect();
    forces.force(&mut gm, again.clone(), 1001, 6).unwrap();
    forces.force(&mut gm, all.clone(), 1002, 7).unwrap();
    assert_eq!(forces.len(), 256, "re-forces add nothing");
    let (events, dropped) = log.take_events();
    assert_eq!(values(&events), 512);
    assert_eq!(dropped as usize, MAX_WRITES);
    // The request the log could not take is freed off the cycle thread.
    let left: Vec<usize> = (freed.try_iter())
        .map(|s| match s {
            Spent::Values(v) => v.len(),
            Spent::Ring(_) => 0,
        })
        .collect();
    assert_eq!(left, [MAX_WRITES]);
    const { assert!(256 + MAX_WRITES > FORCE_LOG_LINES && 512 <= FORCE_LOG_LINES) };
    assert_eq!(
        events.last(),
        Some(&ForceEvent::Forced {
            uid: 1002,
            writes: all,
            at_utc_ns: 7,
        })
    );
    // Taken, the log has room again.
    forces.force(&mut gm, again.clone(), 1001, 8).unwrap();
    let (events, dropped) = log.take_events();
    assert_eq!((values(&events), dropped), (MAX_WRITES, 0));
    // Released with restore, each value goes back to 0, from before the first force.
    forces.release(&mut gm, &every_restored(), 1000, 7).unwrap();
    assert!(gm.values.iter().all(|&v| v == 0));
    let (events, dropped) = log.take_events();
    assert_eq!((events.len(), values(&events), dropped), (1, 256, 0));
    let ForceEvent::Released {
        uid,
        ended,
        at_utc_ns,
    } = &events[0]
    else {
        panic!("{events:?}");
    };
    assert_eq!((*uid, *at_utc_ns), (1000, 7));
    assert_eq!(
        ended[3],
        Ended {
            index: VALUES,
            leaf: 3,
            forced_by: 1001,
            restored: Some(Value::Int(0)),
        }
    );
}
