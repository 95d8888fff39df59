//! The alarm journal across `kill -9`: a child process appends records as fast as it can
//! (compacting as it goes) and is killed mid-write, three times over the same file (the last
//! time stopped halfway through a write by the `fault-injection` hook, so its last record is
//! surely torn). Each time every record read is whole and as the child wrote it, none is
//! missing before the last whole one, a torn end is reported and never read, and the next run
//! cuts it off and goes on numbering.

use plc_core::alarm::{AlarmEvent, EventKind, Level};
use plc_runtime::alarm_journal::{
    AlarmJournal, Contents, Entry, JournalOptions, Operator, read_journal,
};
use plc_test_support::SpawnGuarded;
use std::os::unix::fs::PermissionsExt;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

const CHILD: &str = "PLC_JOURNAL_KILL_CHILD";
const ROUND: &str = "PLC_JOURNAL_KILL_ROUND";
/// Small, so the child compacts every few hundred records and a kill can land in one.
const CAPACITY: usize = 2_000;
/// Each round's times start at round × BASE.
const BASE: i64 = 1_000_000_000_000;
const ALARMS: i64 = 50;

fn options() -> JournalOptions {
    JournalOptions {
        capacity: CAPACITY,
        queue: 4096,
        per_second: usize::MAX,
        sync_interval: Duration::from_secs(1),
    }
}

/// The child: records transitions until killed. Alarm `t % 50` at time `round × BASE + t`,
/// raised and cleared in turn, its value `t % 1000`; every 10th an acknowledgement.
fn child(file: &Path, round: i64) -> ! {
    let journal = AlarmJournal::open_with(file, options()).expect("open the journal");
    let paths: Vec<String> = (0..ALARMS).map(|i| format!("a{i}")).collect();
    let sender = journal.sender(paths);
    for t in 0i64.. {
        let alarm = (t % ALARMS) as usize;
        let time_ns = round * BASE + t;
        if t % 10 == 9 {
            let ack = AlarmEvent {
                alarm,
                time_ns,
                kind: EventKind::Acknowledged,
            };
            sender.record_action(&ack, Operator::new(Some(0), "root").with_comment("seen"));
        } else {
            let kind = if (t / ALARMS) % 2 == 0 {
                EventKind::Raised {
                    level: Level::Active,
                }
            } else {
                EventKind::Cleared {
                    from: Level::Active,
                }
            };
            sender.record(
                &AlarmEvent {
                    alarm,
                    time_ns,
                    kind,
                },
                (t % 1000) as f64,
            );
        }
        if t % 256 == 0 {
            // Let the writer take batches of every size, not one huge one.
            std::thread::yield_now();
        }
    }
    unreachable!()
}

/// Every record read is as the child wrote it, numbered without a gap.
fn check(c: &Contents) {
    assert!(c.damage().is_empty(), "damaged: {:?}", c.damage());
    assert!(!c.records().is_empty());
    for w in c.records().windows(2) {
        assert_eq!(w[1].seq, w[0].seq + 1, "a record lost between {w:?}");
    }
    for r in c.records() {
        if let Entry::Summarised { .. } = r.entry {
            continue;
        }
        let t = r.time_ns % BASE;
        assert_eq!(r.path, format!("a{}", t % ALARMS), "{r:?}");
        match &r.entry {
            Entry::Raised { value, .. } | Entry::Cleared { value, .. } => {
                assert_eq!(*value, Some((t % 1000) as f64), "{r:?}")
            }
            Entry::Acknowledged { by } => {
                assert_eq!(
                    (by.user.as_str(), by.comment.as_deref()),
                    ("root", Some("seen"))
                )
            }
            other => panic!("the child never wrote {other:?}"),
        }
    }
}

fn private_dir() -> PathBuf {
    let dir = std::env::temp_dir().join(format!("plc-journal-kill-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::set_permissions(&dir, std::fs::Permissions::from_mode(0o700)).unwrap();
    dir
}

#[test]
fn killed_mid_write_the_journal_reads_whole_records_and_goes_on() {
    if let Ok(file) = std::env::var(CHILD) {
        let round = std::env::var(ROUND).unwrap().parse().unwrap();
        child(Path::new(&file), round);
    }
    let dir = private_dir();
    let file = dir.join("press.alarms");
    let mut last_seq = 0;
    let mut torn_seen = 0;
    for round in 1..=3i64 {
        let mut child = Command::new(std::env::current_exe().unwrap())
            .args([
                "killed_mid_write_the_journal_reads_whole_records_and_goes_on",
                "--exact",
                "--nocapture",
                "--test-threads=1",
            ])
            .env(CHILD, &file)
            .env(ROUND, round.to_string())
            .env("PLC_JOURNAL_FAULT", if round == 3 { "stall" } else { "" })
            .stdout(Stdio::null())
            .spawn_guarded()
            .unwrap();
        // Until it has written a good deal this round (and compacted on the way).
        let start = Instant::now();
        let written = || {
            read_journal(&file, CAPACITY)
                .ok()
                .flatten()
                .and_then(|c| c.records().last().map(|r| r.seq))
                .unwrap_or(0)
        };
        // The stall: a file that ends within a line and stays so (a read racing an ordinary
        // append could see part of it for a moment).
        let torn_len = || {
            std::fs::read(&file)
                .ok()
                .filter(|b| b.last().is_some_and(|&l| l != b'\n'))
                .map(|b| b.len())
        };
        let stalled = || {
            let before = torn_len();
            std::thread::sleep(Duration::from_millis(50));
            before.is_some() && torn_len() == before
        };
        while if round == 3 {
            !stalled()
        } else {
            written() < last_seq + 3 * CAPACITY as u64
        } {
            assert!(
                start.elapsed() < Duration::from_secs(60),
                "round {round}: the child wrote too little: {} of {}",
                written(),
                last_seq + 3 * CAPACITY as u64
            );
            assert!(child.try_wait().unwrap().is_none(), "the child ended");
            std::thread::sleep(Duration::from_millis(5));
        }
        std::thread::sleep(Duration::from_millis(round as u64 * 7));
        child.signal(libc::SIGKILL);
        child.wait().unwrap();

        let c = read_journal(&file, CAPACITY).unwrap().expect("the journal");
        check(&c);
        torn_seen += usize::from(c.torn().is_some());
        if round == 3 {
            assert!(c.torn().is_some(), "stopped halfway through a write");
        }
        assert!(c.dropped() > 0, "compacted");
        // Numbered on from the last run's last record (checked without a gap by `check`
        // where both runs' records are kept).
        assert!(c.records().last().unwrap().seq > last_seq);
        assert_eq!(c.records().last().unwrap().time_ns / BASE, round);
        last_seq = c.records().last().unwrap().seq;

        // The next run cuts the torn end off and numbers on.
        let journal = AlarmJournal::open_with(&file, options()).unwrap();
        assert_eq!(journal.contents().next_seq(), last_seq + 1);
        journal.finish().unwrap();
        let again = read_journal(&file, CAPACITY).unwrap().unwrap();
        assert!(again.torn().is_none() && again.damage().is_empty());
        assert_eq!(again.records(), c.records());
    }
    eprintln!("torn ends in 3 kills: {torn_seen} (the third always)");
    std::fs::remove_dir_all(&dir).unwrap();
}
