//! The force log under a flood: every force and release is accounted for in the owner's log,
//! shown, or counted in a line that says how many were not shown (at most a few lines every
//! ten seconds per uid) or were not logged because the log fell behind; none is lost
//! silently, and the log stays a few lines long.

mod common;

use common::{unique, with_cycles};
use log::{Level, LevelFilter, Log, Metadata, Record};
use plc_core::write::Write;
use plc_core::{GlobalMemory, Value};
use plc_io::shm::{DynSegment, SharedGlobalMemory};
use std::sync::Mutex;
use std::time::Instant;

/// Level and text of every record of the owner's segment server.
struct Keep(Mutex<Vec<(Level, String)>>);

impl Log for Keep {
    fn enabled(&self, _: &Metadata) -> bool {
        true
    }
    fn log(&self, record: &Record) {
        if record.target() == "plc_io::shm" {
            let kept = (record.level(), record.args().to_string());
            self.0.lock().unwrap().push(kept);
        }
    }
    fn flush(&self) {}
}

static KEPT: Keep = Keep(Mutex::new(Vec::new()));

#[derive(GlobalMemory, Debug, Clone)]
pub struct Gm {
    #[plc(direction = "command")]
    speeds: [i16; 300],
}

/// The number a line starts with after the segment's name, if it starts with one.
fn leading_count(line: &str) -> Option<u64> {
    line.split_whitespace().next()?.parse().ok()
}

#[test]
fn a_flood_of_forces_is_logged_in_a_few_lines_that_count_every_one() {
    log::set_logger(&KEPT).expect("the only logger of this test binary");
    log::set_max_level(LevelFilter::Trace);
    let name = unique("force_log");
    let started = Instant::now();
    let mut owner = SharedGlobalMemory::<Gm>::create(&name).unwrap();
    let mut gm = Gm::default();
    let seg = DynSegment::attach(&name).unwrap();
    let index = seg.index_of("speeds").unwrap();
    const REQUESTS: usize = 6;
    // Nothing in here panics (the cycle thread would wait for it forever): the outcomes
    // are checked after.
    let outcomes = with_cycles(&mut owner, &mut gm, || {
        let mut outcomes = Vec::new();
        for r in 0..REQUESTS {
            // 1,024 forces of the 256 values a program may hold forced.
            let forces: Result<Vec<_>, _> = (0..1024)
                .map(|k| {
                    let value = Value::Int((r * 1024 + k) as i64 % 30_000);
                    seg.check_force(Write {
                        index,
                        leaf: k % 256,
                        value,
                    })
                })
                .collect();
            outcomes.push(forces.and_then(|forces| seg.force(&forces)));
        }
        outcomes.push(seg.release_all(false));
        outcomes
    });
    for outcome in outcomes {
        outcome.unwrap();
    }
    drop(seg);
    // The owner's server writes what is left as it stops.
    drop(owner);
    let windows = started.elapsed().as_secs() / 10 + 1;
    let prefix = format!("segment `{name}`: ");
    let kept = KEPT.0.lock().unwrap();
    let ours: Vec<&(Level, String)> = kept
        .iter()
        .filter(|(_, line)| line.starts_with(&prefix))
        .collect();
    let (mut shown, mut not_shown, mut dropped) = (0u64, 0u64, 0u64);
    for (level, line) in &ours {
        let line = &line[prefix.len()..];
        if line.contains(" forces `speeds[") || line.contains(" releases `speeds[") {
            assert_eq!(*level, Level::Info, "{line}");
            shown += 1;
        } else if line.contains("more forces and releases by uid") {
            assert_eq!(*level, Level::Warn, "{line}");
            not_shown += leading_count(line).unwrap();
        } else if line.ends_with("force/release events were not logged: the log fell behind") {
            assert_eq!(*level, Level::Warn, "{line}");
            dropped += leading_count(line).unwrap();
        }
    }
    let events = (REQUESTS * 1024 + 256) as u64;
    assert_eq!(
        shown + not_shown + dropped,
        events,
        "every force and release is accounted for: {ours:#?}"
    );
    assert!(
        (1..=10 * windows).contains(&shown),
        "{shown} lines shown in {windows} windows of ten seconds"
    );
    assert!(ours.len() as u64 <= 3 * 10 * windows + 4, "{ours:#?}");
}
