//! The bound: at most the capacity's records are read, older ones dropped and counted, the
//! file compacted with the count and the states at the cut.

use super::super::{AlarmJournal, JournalOptions, read_journal};
use super::private_dir;
use plc_core::alarm::{AlarmEvent, EventKind, Level};
use std::time::Duration;

fn options(capacity: usize) -> JournalOptions {
    JournalOptions {
        capacity,
        // Room for every transition these tests send at once, and no budget: all recorded.
        queue: 20_000,
        per_second: usize::MAX,
        sync_interval: Duration::from_millis(50),
    }
}

fn raised(alarm: usize, t: i64) -> AlarmEvent {
    AlarmEvent {
        alarm,
        time_ns: t,
        kind: EventKind::Raised {
            level: Level::Active,
        },
    }
}

fn cleared(alarm: usize, t: i64) -> AlarmEvent {
    AlarmEvent {
        alarm,
        time_ns: t,
        kind: EventKind::Cleared {
            from: Level::Active,
        },
    }
}

#[test]
fn ten_thousand_fifty_keeps_ten_thousand_and_counts_fifty_dropped() {
    let dir = private_dir("bound-10050");
    let file = dir.join("j.alarms");
    let journal = AlarmJournal::open_with(&file, options(10_000)).unwrap();
    let sender = journal.sender(vec!["a".to_string(), "b".to_string()]);
    for t in 0..10_050 {
        // a raised and cleared in turn, b never touched.
        let e = if t % 2 == 0 {
            raised(0, t)
        } else {
            cleared(0, t)
        };
        sender.record(&e, 0.0);
    }
    journal.finish().unwrap();
    let c = read_journal(&file, 10_000).unwrap().unwrap();
    assert_eq!(c.records().len(), 10_000);
    assert_eq!(c.dropped(), 50);
    assert_eq!(c.records()[0].seq, 51);
    assert_eq!(c.records().last().unwrap().seq, 10_050);
    assert!(c.damage().is_empty() && c.torn().is_none());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn compaction_keeps_the_capacity_the_count_and_an_old_unacknowledged_alarm() {
    let dir = private_dir("bound-compact");
    let file = dir.join("j.alarms");
    let capacity = 1_000;
    let journal = AlarmJournal::open_with(&file, options(capacity)).unwrap();
    let sender = journal.sender(vec!["old".to_string(), "busy".to_string()]);
    // The first record: `old` raised, never acknowledged; then far more than the capacity.
    sender.record(&raised(0, 1), 1.0);
    let total = 3_000;
    for t in 2..=total {
        let e = if t % 2 == 0 {
            raised(1, t)
        } else {
            cleared(1, t)
        };
        sender.record(&e, 0.0);
    }
    journal.finish().unwrap();

    let text = std::fs::read_to_string(&file).unwrap();
    let lines = text.lines().count();
    // The header, the states at the cut (`old`, `busy`), the records.
    assert!(
        lines <= 1 + 2 + capacity + capacity / 4,
        "{lines} lines: never more than the capacity and its slack"
    );
    assert!(
        text.lines()
            .next()
            .unwrap()
            .contains(r#""journal":"plc-vars alarm journal""#)
    );
    assert!(
        text.lines().take(3).any(|l| l.contains(r#""state":"old""#)),
        "the state at the cut: {text:.400}"
    );
    let c = read_journal(&file, capacity).unwrap().unwrap();
    assert_eq!(c.records().len(), capacity);
    assert_eq!(c.dropped(), total as u64 - capacity as u64);
    let old = &c.states()["old"];
    assert!(old.level == Level::Active && !old.acknowledged, "{old:?}");

    // Reopened, it goes on numbering where it stopped.
    let journal = AlarmJournal::open_with(&file, options(capacity)).unwrap();
    assert_eq!(journal.contents().next_seq(), total as u64 + 1);
    assert_eq!(journal.contents().states()["old"], *old);
    drop(journal);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_file_over_the_capacity_is_compacted_when_opened() {
    let dir = private_dir("bound-open");
    let file = dir.join("j.alarms");
    std::fs::write(&file, super::file_of(300)).unwrap();
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(&file, std::fs::Permissions::from_mode(0o600)).unwrap();
    // A smaller capacity than the file holds (it was lowered).
    let journal = AlarmJournal::open_with(&file, options(100)).unwrap();
    assert_eq!(journal.contents().records().len(), 100);
    assert_eq!(journal.contents().dropped(), 200);
    drop(journal);
    let text = std::fs::read_to_string(&file).unwrap();
    assert!(text.lines().count() <= 100 + 10 + 1);
    assert!(text.contains(r#""dropped":200"#));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn when_compactions_fail_the_file_stops_at_its_limit_and_counts_the_rest() {
    use std::os::unix::fs::PermissionsExt;
    let dir = private_dir("bound-failing");
    let file = dir.join("j.alarms");
    let journal = AlarmJournal::open_with(&file, options(20)).unwrap();
    let sender = journal.sender(vec!["a".to_string()]);
    // A directory others may write: compactions refuse to rewrite the file in it.
    std::fs::set_permissions(&dir, std::fs::Permissions::from_mode(0o777)).unwrap();
    for t in 0..100 {
        sender.record(&raised(0, t), 1.0);
        if t % 10 == 0 {
            journal.flush().unwrap();
        }
    }
    journal.flush().unwrap();
    let records = std::fs::read_to_string(&file).unwrap().lines().count();
    assert!(
        records <= 20 + 2 * 5,
        "{records} records: never past the hard limit"
    );
    assert!(sender.summarised() > 0);
    // Fixed: the next batch compacts, and the summary says what was only counted.
    std::fs::set_permissions(&dir, std::fs::Permissions::from_mode(0o700)).unwrap();
    std::thread::sleep(Duration::from_millis(60));
    sender.record(&raised(0, 100), 1.0);
    journal.finish().unwrap();
    let c = read_journal(&file, 20).unwrap().unwrap();
    let counted: u64 = c
        .records()
        .iter()
        .map(|r| match r.entry {
            crate::alarm_journal::Entry::Summarised { transitions, .. } => transitions,
            _ => 0,
        })
        .sum();
    assert!(counted > 0, "the summary says how many: {:?}", c.records());
    assert!(
        c.records()
            .iter()
            .any(|r| r.time_ns == 100 && r.path == "a"),
        "written again"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
