//! What a newcomer writing a conveyor program from the README saw, each pinned: `plc list`
//! says what a tool may do with each variable, `plc get` shows a running timer in seconds
//! (`plc log` keeps the literal), `plc get` without names shows every value, and the trace
//! plot never puts a counter under an axis that says "s".

use plc_core::{GlobalMemory, Time};
mod common;

use common::{ChildGuard, SpawnGuarded, plc, stderr, stdout, terminate, wait_until};
use plc_io::Runtime;
use std::process::{Command, Stdio};
use std::time::Duration;

/// The cycle of the conveyor program.
const PERIOD: Duration = Duration::from_millis(5);

#[derive(GlobalMemory, Debug, Clone)]
pub struct Conveyor {
    /// Parts at the light barrier
    #[plc(direction = "input")]
    barrier: bool,
    /// Belt speed asked for
    #[plc(direction = "command", initial = 100)]
    speed_setpoint: u16,
    /// Belt speed
    #[plc(direction = "status")]
    speed_actual: u16,
    /// Cycles run
    counter: u64,
    /// Parts passed: one a second
    parts: u32,
    /// The running timer's elapsed time
    elapsed: Time,
    /// How long a part may take, set by a tool
    #[plc(direction = "command", initial = "T#4s340ms4us953ns")]
    dwell: Time,
}

/// Runs as the conveyor program when `PLC_TEST_ROLE=conveyor`.
#[test]
fn conveyor_role() {
    if std::env::var("PLC_TEST_ROLE").as_deref() != Ok("conveyor") {
        return;
    }
    let segment = std::env::var("SEGMENT").unwrap();
    Runtime::<Conveyor>::builder()
        .period(PERIOD)
        .segment(segment)
        .build()
        .expect("the runtime's settings are valid")
        .run(|ctx| {
            let gm = &mut ctx.gm;
            gm.counter += 1;
            gm.speed_actual = gm.speed_setpoint;
            // A timer and a counter of the same range: seconds, and parts one a second.
            let ms = gm.counter.saturating_mul(PERIOD.as_millis() as u64);
            gm.elapsed = Time::from_millis(ms as i64);
            gm.parts = (ms / 1000) as u32;
        })
        .unwrap();
}

/// The conveyor program in another process, stopped when dropped.
struct Program {
    child: ChildGuard,
    segment: String,
}

impl Program {
    fn start(test: &str) -> Program {
        let segment = format!("newcomer_{test}_{}", std::process::id());
        let child = Command::new(std::env::current_exe().unwrap())
            .args(["conveyor_role", "--exact", "--nocapture"])
            .env("PLC_TEST_ROLE", "conveyor")
            .env("SEGMENT", &segment)
            .stdout(Stdio::null())
            .spawn_guarded()
            .unwrap();
        let program = Program { child, segment };
        wait_until("the program to start", || {
            plc(&["get", &program.segment, "counter"]).status.success()
        });
        program
    }
}

impl Drop for Program {
    fn drop(&mut self) {
        terminate(&mut self.child);
    }
}

/// A scratch directory of this test process.
fn scratch(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("plc-newcomer-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn list_says_what_a_tool_may_do_as_set_decides_it() {
    let program = Program::start("list");
    let list = stdout(&plc(&["list", &program.segment]));
    let access = |name: &str| {
        let line = list
            .lines()
            .find(|l| l.split_whitespace().next() == Some(name))
            .unwrap_or_else(|| panic!("no line for {name} in\n{list}"));
        // NAME, TYPE, DIRECTION, then ACCESS (one or two words).
        let words: Vec<&str> = line.split_whitespace().collect();
        match words.get(4) {
            Some(w) if w.starts_with('(') => format!("{} {w}", words[3]),
            _ => words[3].to_string(),
        }
    };
    assert_eq!(access("barrier"), "read-only (input)", "{list}");
    assert_eq!(access("speed_actual"), "read-only (status)", "{list}");
    assert_eq!(access("speed_setpoint"), "read-write", "{list}");
    // And `plc set` agrees with each.
    for (name, allowed) in [
        ("barrier=true", false),
        ("speed_actual=1", false),
        ("speed_setpoint=120", true),
    ] {
        let out = plc(&["set", &program.segment, name]);
        assert_eq!(out.status.success(), allowed, "{name}: {}", stderr(&out));
    }
}

#[test]
fn get_shows_a_running_timer_in_seconds_and_log_keeps_the_literal() {
    let program = Program::start("time");
    let s = program.segment.as_str();
    let got = stdout(&plc(&["get", s, "dwell"]));
    assert_eq!(got.trim(), "dwell = 4.340004953 s", "full precision");
    let got = stdout(&plc(&["get", s, "dwell", "--digits", "4"]));
    assert_eq!(got.trim(), "dwell = 4.34 s", "rounded to the digits asked");
    let got = stdout(&plc(&["get", s, "elapsed", "--digits", "3"]));
    assert!(
        got.starts_with("elapsed = ") && got.trim_end().ends_with(" s"),
        "{got}"
    );

    // `plc log` writes the literal a program reads back.
    let file = scratch("log").join("log.csv");
    let out = plc(&[
        "log",
        s,
        "dwell",
        "--csv",
        file.to_str().unwrap(),
        "--rate",
        "50",
        "--seconds",
        "0.2",
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let csv = std::fs::read_to_string(&file).unwrap();
    let row = csv.lines().nth(1).unwrap_or_default();
    assert!(row.ends_with(",LTIME#4s340ms4us953ns"), "{csv}");
    // And a literal still writes.
    let out = plc(&["set", s, "dwell=T#1.5s"]);
    assert!(out.status.success(), "{}", stderr(&out));
    wait_until("the write", || {
        stdout(&plc(&["get", s, "dwell"])).trim() == "dwell = 1.5 s"
    });
}

#[test]
fn get_without_names_shows_every_value() {
    let program = Program::start("all");
    let out = plc(&["get", &program.segment]);
    assert!(out.status.success(), "{}", stderr(&out));
    let got = stdout(&out);
    let names: Vec<&str> = got.lines().filter_map(|l| l.split(" = ").next()).collect();
    assert_eq!(
        names,
        [
            "barrier",
            "speed_setpoint",
            "speed_actual",
            "counter",
            "parts",
            "elapsed",
            "dwell"
        ],
        "{got}"
    );
    assert!(got.contains("speed_setpoint = 100"), "{got}");
}

#[test]
fn the_trace_plot_never_puts_a_counter_under_an_axis_that_says_seconds() {
    let program = Program::start("plot");
    let dir = scratch("plot");
    let (csv, svg) = (dir.join("t.csv"), dir.join("t.svg"));
    let out = plc(&[
        "trace",
        &program.segment,
        "elapsed",
        "parts",
        "--for",
        "2s",
        "--out",
        csv.to_str().unwrap(),
        "--plot",
        svg.to_str().unwrap(),
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let text = std::fs::read_to_string(&svg).unwrap();
    let doc = roxmltree::Document::parse(&text).expect("the plot is well-formed SVG");
    let texts: Vec<&str> = doc
        .descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| n.text())
        .map(str::trim)
        .collect();
    assert!(texts.contains(&"elapsed (s)"), "{texts:?}");
    assert!(texts.contains(&"s"), "the timer's axis: {texts:?}");
    assert!(
        texts.contains(&"value"),
        "the counter's own axis: {texts:?}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
