//! The runtime keeps the program's alarms: evaluated after every tick with the cycle's UTC
//! time, each transition in the journal file, operators' actions by path, the counts in the
//! status block, the state kept across a restart, and a flood held to bounded memory.

mod common;

use common::{Cleanup, Scratch, unique, wait_for};
use plc_core::GlobalMemory;
use plc_core::alarm::{AlarmState, Level};
use plc_io::alarm_journal::{self, Entry, Operator, Record};
use plc_io::shm::DynSegment;
use plc_io::{Context, Runtime, StopHandle};
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};
use std::thread::JoinHandle;
use std::time::{Duration, SystemTime, UNIX_EPOCH};

#[derive(GlobalMemory, Debug, Clone)]
struct Plant {
    #[plc(alarm = "Guard door open")]
    door: bool,
    #[plc(alarm(
        text = "Oil temperature",
        high = 80.0,
        high_high = 95.0,
        deadband = 1.0,
        delay = "20ms",
        severity = 600
    ))]
    oil: f32,
    #[plc(alarm(text = "Overtravel", severity = 900, latched))]
    overtravel: bool,
}

/// An operator's action, done by the tick through `Context::alarms_mut`.
enum Act {
    Ack(&'static str, Operator),
    Reset(&'static str, Operator),
}

/// What the test sets and what the tick saw: the values the tick writes, the actions it does,
/// and the alarms' states after each cycle.
#[derive(Default)]
struct Panel {
    door: bool,
    oil: f32,
    overtravel: bool,
    acts: Vec<Act>,
    refused: Vec<String>,
    states: Vec<(String, AlarmState, Level, i64)>,
    counts: (usize, usize),
}

type Shared = Arc<Mutex<Panel>>;

fn utc_now() -> i64 {
    SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .unwrap()
        .as_nanos() as i64
}

/// A runtime of `Plant` at 1 kHz on its own thread, its journal where `journal` says.
fn start(
    segment: Option<&str>,
    retain: Option<&Path>,
    journal: Option<&Path>,
) -> (Shared, StopHandle, JoinHandle<Plant>) {
    let mut builder = Runtime::<Plant>::builder()
        .period(Duration::from_millis(1))
        .handle_signals(false);
    if let Some(s) = segment {
        builder = builder.segment(s);
    }
    if let Some(r) = retain {
        builder = builder.retain(r);
    }
    if let Some(j) = journal {
        builder = builder.alarm_journal(j);
    }
    let rt = builder.build().unwrap();
    let panel = Shared::default();
    let stop = rt.stop_handle();
    let p = panel.clone();
    let thread = std::thread::spawn(move || rt.run(move |ctx| tick(ctx, &p)).unwrap());
    (panel, stop, thread)
}

fn tick(ctx: &mut Context<Plant>, panel: &Shared) {
    let mut p = panel.lock().unwrap();
    (ctx.gm.door, ctx.gm.oil, ctx.gm.overtravel) = (p.door, p.oil, p.overtravel);
    for act in std::mem::take(&mut p.acts) {
        let done = match act {
            Act::Ack(path, by) => ctx.alarms_mut().acknowledge(path, by),
            Act::Reset(path, by) => ctx.alarms_mut().reset(path, by),
        };
        if let Err(e) = done {
            p.refused.push(e.to_string());
        }
    }
    // The states the last cycle's evaluation left, as the tick sees them.
    let alarms = ctx.alarms();
    p.states = alarms
        .paths()
        .iter()
        .enumerate()
        .map(|(i, path)| {
            let e = alarms.evaluator();
            (path.clone(), e.state(i), e.level(i), e.since_ns(i))
        })
        .collect();
    p.counts = (alarms.active(), alarms.unacknowledged());
}

/// Waits until alarm `path` is in `state` (at `level`); its time.
fn wait_state(panel: &Shared, path: &str, state: AlarmState, level: Level) -> i64 {
    wait_for(Duration::from_secs(10), || {
        let p = panel.lock().unwrap();
        p.states
            .iter()
            .find(|(q, s, l, _)| q == path && *s == state && *l == level)
            .map(|s| s.3)
    })
}

/// Waits until the journal at `file` holds a record that `matches`.
fn wait_record(file: &Path, matches: impl Fn(&Record) -> bool) -> Record {
    wait_for(Duration::from_secs(5), || {
        let contents = alarm_journal::read_journal(file, alarm_journal::DEFAULT_CAPACITY)
            .ok()
            .flatten()?;
        contents.records().iter().find(|r| matches(r)).cloned()
    })
}

fn act(panel: &Shared, a: Act) {
    panel.lock().unwrap().acts.push(a);
}

fn anna() -> Operator {
    Operator::new(Some(1000), "anna").with_comment("checked on site")
}

#[test]
fn a_raised_alarm_has_the_cycles_time_reaches_the_journal_and_is_acknowledged_by_path() {
    let dir = Scratch::new("alarms-raise");
    let name = unique("alarms_raise");
    let _cleanup = Cleanup(name.clone());
    let retain = dir.path("plant.retain");
    let (panel, stop, thread) = start(Some(&name), Some(&retain), None);
    // Beside the retain file, by default.
    let file = dir.path("plant.alarms");
    wait_state(&panel, "door", AlarmState::Normal, Level::Normal);

    let before = utc_now();
    panel.lock().unwrap().door = true;
    let since = wait_state(
        &panel,
        "door",
        AlarmState::ActiveUnacknowledged,
        Level::Active,
    );
    let after = utc_now();
    assert!(
        (before..=after).contains(&since),
        "the transition's time {since} is the cycle's UTC time, between {before} and {after}"
    );
    let raised = wait_record(&file, |r| {
        r.path == "door" && matches!(r.entry, Entry::Raised { .. })
    });
    assert_eq!(raised.time_ns, since, "the journal has the cycle's time");
    assert_eq!(
        raised.entry,
        Entry::Raised {
            level: Level::Active,
            value: Some(1.0)
        }
    );

    // The limit alarm: its delay, its levels, its deadband.
    panel.lock().unwrap().oil = 85.0;
    wait_state(&panel, "oil", AlarmState::ActiveUnacknowledged, Level::High);
    panel.lock().unwrap().oil = 96.0;
    wait_state(
        &panel,
        "oil",
        AlarmState::ActiveUnacknowledged,
        Level::HighHigh,
    );
    panel.lock().unwrap().oil = 94.5;
    std::thread::sleep(Duration::from_millis(50));
    let oil = |p: &Panel| p.states.iter().find(|s| s.0 == "oil").map(|s| s.2);
    assert_eq!(
        oil(&panel.lock().unwrap()),
        Some(Level::HighHigh),
        "within the deadband the level stays"
    );
    panel.lock().unwrap().oil = 93.0;
    wait_state(&panel, "oil", AlarmState::ActiveUnacknowledged, Level::High);
    wait_record(&file, |r| {
        r.path == "oil"
            && r.entry
                == Entry::LevelChanged {
                    from: Level::HighHigh,
                    to: Level::High,
                    value: Some(93.0),
                }
    });

    // Acknowledged through the API, journaled with who did it.
    act(&panel, Act::Ack("door", anna()));
    wait_state(
        &panel,
        "door",
        AlarmState::ActiveAcknowledged,
        Level::Active,
    );
    let acked = wait_record(&file, |r| {
        r.path == "door" && matches!(r.entry, Entry::Acknowledged { .. })
    });
    assert_eq!(acked.entry, Entry::Acknowledged { by: anna() });
    act(&panel, Act::Ack("door", anna()));
    act(&panel, Act::Ack("no_such_alarm", anna()));
    let refused = wait_for(Duration::from_secs(5), || {
        let p = panel.lock().unwrap();
        (p.refused.len() == 2).then(|| p.refused.clone())
    });
    assert!(refused[0].contains("`door`"), "{refused:?}");
    assert!(
        refused[1].contains("no alarm at `no_such_alarm`"),
        "{refused:?}"
    );

    // The status block counts them: door and oil active, oil unacknowledged.
    let status = wait_for(Duration::from_secs(5), || {
        let status = DynSegment::attach(&name).ok()?.status();
        (status.alarms_unacknowledged == 1).then_some(status)
    });
    assert_eq!(status.alarms_active, 2);
    assert_eq!(panel.lock().unwrap().counts, (2, 1));

    stop.stop();
    thread.join().unwrap();
}

/// Runs the plant on `journal` until `ready` holds, then stops it.
fn run_until(journal: &Path, set: impl FnOnce(&mut Panel), ready: impl Fn(&Panel) -> bool) {
    let (panel, stop, thread) = start(None, None, Some(journal));
    set(&mut panel.lock().unwrap());
    wait_for(Duration::from_secs(10), || {
        ready(&panel.lock().unwrap()).then_some(())
    });
    stop.stop();
    thread.join().unwrap();
}

fn state_of(p: &Panel, path: &str) -> Option<AlarmState> {
    p.states.iter().find(|s| s.0 == path).map(|s| s.1)
}

#[test]
fn an_unacknowledged_alarm_stays_unacknowledged_and_a_latched_one_latched_after_a_restart() {
    let dir = Scratch::new("alarms-restart");
    let file: PathBuf = dir.path("journal/plant.alarms");
    // First run: the door opens and the axis overtravels; nobody acknowledges.
    run_until(
        &file,
        |p| (p.door, p.overtravel) = (true, true),
        |p| {
            state_of(p, "door") == Some(AlarmState::ActiveUnacknowledged)
                && state_of(p, "overtravel") == Some(AlarmState::ActiveUnacknowledged)
        },
    );
    // Second run: the door is closed and the axis back, both still wait for an operator.
    let (panel, stop, thread) = start(None, None, Some(&file));
    wait_state(
        &panel,
        "door",
        AlarmState::ReturnedUnacknowledged,
        Level::Normal,
    );
    wait_state(
        &panel,
        "overtravel",
        AlarmState::Latched {
            acknowledged: false,
        },
        Level::Active,
    );
    assert_eq!(panel.lock().unwrap().counts.1, 2);
    act(&panel, Act::Ack("door", anna()));
    act(&panel, Act::Reset("overtravel", anna()));
    wait_state(&panel, "door", AlarmState::Normal, Level::Normal);
    wait_state(&panel, "overtravel", AlarmState::Normal, Level::Normal);
    stop.stop();
    thread.join().unwrap();
    // Third run: nothing left to acknowledge.
    run_until(
        &file,
        |_| {},
        |p| p.states.len() == 3 && p.states.iter().all(|s| s.1 == AlarmState::Normal),
    );
}

#[derive(GlobalMemory, Debug, Clone)]
struct Flood {
    #[plc(alarm = "Flooded")]
    flags: [bool; 500],
}

/// The process's resident memory, in bytes.
fn resident() -> u64 {
    let status = std::fs::read_to_string("/proc/self/status").unwrap();
    let line = status.lines().find(|l| l.starts_with("VmRSS:")).unwrap();
    let kb: u64 = line.split_whitespace().nth(1).unwrap().parse().unwrap();
    kb * 1024
}

#[test]
fn a_flood_of_500_alarms_toggling_every_cycle_holds_memory_and_is_summarised() {
    let dir = Scratch::new("alarms-flood");
    let file = dir.path("flood.alarms");
    let rss = Arc::new(Mutex::new((0u64, 0u64, 0u64)));
    let seen = rss.clone();
    let rt = Runtime::<Flood>::builder()
        .period(Duration::from_micros(500))
        .handle_signals(false)
        .alarm_journal(&file)
        .max_cycles(600)
        .build()
        .unwrap();
    rt.run(move |ctx| {
        let on = ctx.cycle % 2 == 1;
        ctx.gm.flags = [on; 500];
        let mut s = seen.lock().unwrap();
        match ctx.cycle {
            100 => s.0 = resident(),
            600 => (s.1, s.2) = (resident(), ctx.alarms().summarised()),
            _ => {}
        }
    })
    .unwrap();
    let (early, late, summarised) = *rss.lock().unwrap();
    assert!(
        summarised > 0,
        "500 transitions a cycle are more than the journal records one by one"
    );
    // 250,000 transitions went by: kept one by one they would take tens of megabytes.
    assert!(
        late < early + 16 * 1024 * 1024,
        "memory grew from {early} to {late} bytes"
    );
    let contents = alarm_journal::read_journal(&file, alarm_journal::DEFAULT_CAPACITY)
        .unwrap()
        .unwrap();
    let counted: u64 = contents
        .records()
        .iter()
        .filter_map(|r| match r.entry {
            Entry::Summarised { transitions, .. } => Some(transitions),
            _ => None,
        })
        .sum();
    assert!(counted > 0, "the journal says how many it summarised");
    assert!(contents.records().len() <= alarm_journal::DEFAULT_CAPACITY);
}

#[test]
fn the_longest_shelf_and_the_journals_size_are_the_programs_and_checked_when_built() {
    let refused = |b: plc_io::RuntimeBuilder<Plant>, wanted: &str| {
        let e = b.build().err().expect("refused").to_string();
        assert!(e.contains(wanted), "{e}");
    };
    refused(
        Runtime::<Plant>::builder().alarm_journal_capacity(0),
        "alarm_journal_capacity",
    );
    refused(
        Runtime::<Plant>::builder().max_shelve(plc_core::Time::from_secs(0)),
        "max_shelve",
    );
    refused(
        Runtime::<Plant>::builder().max_shelve(plc_core::Time::from_secs(31 * 86_400)),
        "at most 30 days",
    );
    // A program that allows one hour refuses two, and takes one.
    let outcome = Arc::new(Mutex::new(Vec::new()));
    let seen = outcome.clone();
    Runtime::<Plant>::builder()
        .period(Duration::from_millis(1))
        .max_shelve(plc_core::Time::from_secs(3600))
        .max_cycles(3)
        .handle_signals(false)
        .build()
        .unwrap()
        .run(move |ctx| {
            if ctx.cycle == 2 {
                let by = || Operator::new(None, "anna");
                let mut out = seen.lock().unwrap();
                for secs in [7200, 3600] {
                    let r = ctx
                        .alarms_mut()
                        .shelve("door", plc_core::Time::from_secs(secs), by());
                    out.push(r.map_err(|e| e.to_string()));
                }
            }
        })
        .unwrap();
    let outcome = outcome.lock().unwrap();
    assert!(
        outcome[0].as_ref().is_err_and(|e| e.contains("at most")),
        "{outcome:?}"
    );
    assert_eq!(outcome[1], Ok(()));
}
