//! Compaction changes the file, never what it says: after any number of records and any
//! capacity, the compacted journal reads as the whole history would with that capacity (the
//! same records kept, the same count dropped, the same alarms not normal).

use super::super::read::Contents;
use super::super::record::Record;
use super::super::{AlarmJournal, JournalOptions, read_journal, replay};
use super::{line, private_dir};
use plc_core::alarm::{AlarmEvent, EventKind, Level};
use proptest::prelude::*;
use std::collections::BTreeMap;
use std::time::Duration;

fn notable(c: &Contents) -> BTreeMap<String, plc_core::alarm::Snapshot> {
    c.states()
        .iter()
        .filter(|(_, s)| replay::notable(s))
        .map(|(p, s)| (p.clone(), s.clone()))
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 16, ..ProptestConfig::default() })]

    #[test]
    fn compacted_reads_as_the_whole_history_would(
        events in proptest::collection::vec((0usize..5, 0u8..3), 1..300),
        capacity in 3usize..60,
    ) {
        let dir = private_dir(&format!("compaction-{capacity}-{}", events.len()));
        let file = dir.join("j.alarms");
        let options = JournalOptions {
            capacity,
            queue: 1_000,
            per_second: usize::MAX,
            sync_interval: Duration::from_millis(10),
        };
        let paths: Vec<String> = (0..5).map(|i| format!("a{i}")).collect();
        let journal = AlarmJournal::open_with(&file, options).unwrap();
        let sender = journal.sender(paths.clone());
        let mut whole = Vec::new();
        for (t, (alarm, kind)) in events.iter().enumerate() {
            let kind = match kind {
                0 => EventKind::Raised { level: Level::Active },
                1 => EventKind::Cleared { from: Level::Active },
                _ => EventKind::Acknowledged,
            };
            let event = AlarmEvent { alarm: *alarm, time_ns: t as i64, kind };
            sender.record(&event, 1.0);
            // Flushed now and then, so compactions come between batches of every size.
            if t % 97 == 0 {
                journal.flush().unwrap();
            }
            whole.extend(line(super::super::frame::Item::Record(Record {
                seq: t as u64 + 1,
                time_ns: t as i64,
                path: paths[*alarm].clone(),
                entry: super::super::Entry::from_event(&event, 1.0, None),
            })));
        }
        prop_assert_eq!(sender.summarised(), 0);
        journal.finish().unwrap();
        let expected = Contents::from_bytes(&whole, capacity);
        let read = read_journal(&file, capacity).unwrap().unwrap();
        prop_assert_eq!(read.records(), expected.records());
        prop_assert_eq!(read.dropped(), expected.dropped());
        prop_assert_eq!(notable(&read), notable(&expected));
        prop_assert!(read.damage().is_empty());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
