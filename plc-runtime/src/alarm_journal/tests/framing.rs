//! One line, framed and checked: every entry comes back as written, and the frame's limits.

use super::super::frame::{Item, MAX_LINE, decode};
use super::super::record::{Entry, MAX_COMMENT, Operator, Record, bounded};
use super::line;
use plc_core::alarm::{AlarmEvent, EventKind, Level, Shelf, Snapshot};

fn every_entry() -> Vec<Entry> {
    let anna = Operator::new(Some(1000), "anna").with_comment("pump \"B\" checked");
    vec![
        Entry::Raised {
            level: Level::HighHigh,
            value: Some(96.5),
        },
        Entry::Raised {
            level: Level::Active,
            value: None,
        },
        Entry::LevelChanged {
            from: Level::High,
            to: Level::HighHigh,
            value: Some(95.0),
        },
        Entry::Cleared {
            from: Level::Low,
            value: Some(7.0),
        },
        Entry::ConditionCleared {
            level: Level::LowLow,
            value: Some(3.0),
        },
        Entry::Acknowledged { by: anna.clone() },
        Entry::Reset {
            by: Operator::new(None, "opcua-user"),
        },
        Entry::Shelved {
            by: anna.clone(),
            until_ns: 7_200_000_000_000,
        },
        Entry::Unshelved { by: Some(anna) },
        Entry::Unshelved { by: None },
        Entry::Suppressed,
        Entry::Unsuppressed,
        Entry::Summarised {
            transitions: 12,
            actions: 1,
        },
    ]
}

#[test]
fn every_entry_reads_back_as_written() {
    for (i, entry) in every_entry().into_iter().enumerate() {
        let r = Record {
            seq: i as u64 + 1,
            time_ns: -5 + i as i64,
            path: "stations[2].door".into(),
            entry,
        };
        let l = line(Item::Record(r.clone()));
        assert_eq!(l.last(), Some(&b'\n'));
        assert_eq!(l.iter().filter(|&&b| b == b'\n').count(), 1, "one line");
        assert_eq!(decode(&l[..l.len() - 1]), Ok(Item::Record(r)));
    }
}

#[test]
fn a_line_is_its_checksum_then_json_an_auditor_can_read() {
    let l = line(Item::Record(super::raised(3, "door")));
    let text = String::from_utf8(l).unwrap();
    let (crc, json) = text.trim_end().split_once(' ').unwrap();
    assert_eq!(crc, format!("{:08x}", crc32fast::hash(json.as_bytes())));
    assert_eq!(
        json,
        r#"{"seq":3,"t":3,"path":"door","ev":"raised","level":"active","value":1.0}"#
    );
}

#[test]
fn header_and_state_read_back() {
    let header = Item::Header { dropped: 42 };
    let state = Item::State {
        path: "oil".into(),
        state: Snapshot {
            level: Level::High,
            acknowledged: false,
            held: true,
            shelf: Some(Shelf {
                by: "anna".into(),
                since_ns: 1,
                until_ns: 2,
            }),
            since_ns: 9,
        },
    };
    for item in [header, state] {
        let l = line(item.clone());
        assert_eq!(decode(&l[..l.len() - 1]), Ok(item));
    }
}

#[test]
fn longest_strings_still_fit_a_line() {
    // Quotes and backslashes double when escaped; control characters become spaces.
    let worst = "\"\\".repeat(4096) + &"\u{1}".repeat(100);
    let by = Operator::new(Some(u32::MAX), worst.clone()).with_comment(worst.clone());
    let event = AlarmEvent {
        alarm: 0,
        time_ns: i64::MIN,
        kind: EventKind::Shelved { until_ns: i64::MAX },
    };
    let r = Record {
        seq: u64::MAX,
        time_ns: i64::MIN,
        path: bounded(&worst, 512),
        entry: Entry::from_event(&event, f64::NAN, Some(by.bounded())),
    };
    let l = line(Item::Record(r));
    assert!(l.len() <= MAX_LINE, "{} bytes", l.len());
    assert!(!l[..l.len() - 1].contains(&b'\n'));
}

#[test]
fn bounded_cuts_at_a_character_and_blanks_control_characters() {
    assert_eq!(bounded("éé", 3), "é");
    assert_eq!(bounded("a\nb\x1b[2J", 10), "a b [2J");
    assert_eq!(
        bounded(&"x".repeat(MAX_COMMENT + 9), MAX_COMMENT).len(),
        MAX_COMMENT
    );
}

#[test]
fn a_line_too_long_or_too_short_is_damage_not_a_panic() {
    assert!(
        decode(&vec![b'a'; MAX_LINE + 1])
            .unwrap_err()
            .contains("longer")
    );
    assert!(decode(b"").is_err());
    assert!(decode(b"12345678").is_err());
    assert!(decode(b"zzzzzzzz {}").unwrap_err().contains("checksum"));
    let crc = crc32fast::hash(b"[1]");
    assert!(
        decode(format!("{crc:08x} [1]").as_bytes())
            .unwrap_err()
            .contains("object")
    );
}

#[test]
fn a_header_of_another_version_is_refused() {
    let json = r#"{"journal":"plc-vars alarm journal","version":2,"dropped":0}"#;
    let l = format!("{:08x} {json}", crc32fast::hash(json.as_bytes()));
    assert!(decode(l.as_bytes()).unwrap_err().contains("version 2"));
}

#[test]
fn from_event_names_the_operator_and_no_one_for_an_expired_shelf() {
    let by = Operator::new(Some(1), "bob");
    let ev = |kind| AlarmEvent {
        alarm: 0,
        time_ns: 0,
        kind,
    };
    let expired = Entry::from_event(&ev(EventKind::Unshelved { expired: true }), 0.0, None);
    assert_eq!(expired, Entry::Unshelved { by: None });
    let by_bob = Entry::from_event(
        &ev(EventKind::Unshelved { expired: false }),
        0.0,
        Some(by.clone()),
    );
    assert_eq!(by_bob, Entry::Unshelved { by: Some(by) });
    let raised = Entry::from_event(&ev(EventKind::Raised { level: Level::Low }), f64::NAN, None);
    assert_eq!(
        raised,
        Entry::Raised {
            level: Level::Low,
            value: None
        }
    );
}

#[test]
fn the_format_example_in_the_module_docs_reads() {
    // The lines an auditor sees first: they must be what the reader takes.
    let docs = include_str!("../mod.rs");
    let example: Vec<&str> = docs
        .lines()
        .filter_map(|l| l.strip_prefix("//! "))
        .filter(|l| {
            l.len() > 10 && l.as_bytes()[8] == b' ' && l[..8].bytes().all(|b| b.is_ascii_hexdigit())
        })
        .collect();
    assert_eq!(example.len(), 4);
    for l in example {
        assert!(
            decode(l.as_bytes()).is_ok(),
            "{l}: {:?}",
            decode(l.as_bytes())
        );
    }
}

#[test]
fn a_record_reads_to_people_without_a_terminals_control_characters() {
    let r = Record {
        seq: 9,
        time_ns: 0,
        path: "door\u{1b}[2J".into(),
        entry: Entry::Shelved {
            by: Operator::new(None, "eve\u{7}").with_comment("a\nb"),
            until_ns: 3_600_000_000_000,
        },
    };
    assert_eq!(
        r.to_string(),
        r#"1970-01-01 00:00:00 UTC #9 door?[2J: shelved until 1970-01-01 01:00:00 UTC by eve?: "a\nb""#
    );
    let s = Record {
        seq: 10,
        time_ns: 0,
        path: String::new(),
        entry: Entry::Summarised {
            transitions: 5,
            actions: 1,
        },
    };
    assert!(
        s.to_string()
            .contains("#10 5 transitions and 1 operator actions not recorded")
    );
}
