//! The `plc` command on a program with structures, in another process: paths in `get` and
//! `set`, IN parameters writable, read-only members refused, and a nonvolatile member kept
//! across a restart and across an edit of the declaration.

use plc_core::{GlobalMemory, PlcStruct};
mod common;

use common::{ChildGuard, SpawnGuarded, plc, stderr, stdout, terminate, wait_until};
use plc_io::Runtime;
use plc_test_support::TmuxSession;
use std::path::PathBuf;
use std::process::{Command, Stdio};
use std::time::Duration;

#[derive(PlcStruct, Debug, Clone, Copy, PartialEq)]
pub struct Axis {
    /// Actual position
    pub pos: f64,
    #[plc(initial = 250.0)]
    pub target: f64,
    #[plc(direction = "input")]
    pub enable: bool,
    #[plc(read_only, initial = 3)]
    pub drive_id: u16,
    #[plc(nonvolatile)]
    pub moves: u32,
}

#[derive(GlobalMemory, Debug, Clone)]
pub struct Gm {
    pub counter: u64,
    pub lift: Axis,
    pub axes: [Axis; 2],
    pub grid: [[i16; 3]; 2],
}

/// The next version of the program: a member added to `Axis`, and `axes` grown.
#[derive(PlcStruct, Debug, Clone, Copy, PartialEq)]
#[plc(name = "Axis")]
pub struct AxisV2 {
    #[plc(nonvolatile, initial = 5)]
    pub torque_limit: u8,
    pub pos: f64,
    pub target: f64,
    #[plc(direction = "input")]
    pub enable: bool,
    #[plc(read_only, initial = 3)]
    pub drive_id: u16,
    #[plc(nonvolatile)]
    pub moves: u32,
}

#[derive(GlobalMemory, Debug, Clone)]
pub struct GmV2 {
    pub counter: u64,
    pub lift: AxisV2,
    pub axes: [AxisV2; 3],
}

/// Runs as the control program when `PLC_TEST_ROLE` is `owner` or `owner_v2`: each axis
/// follows its target while enabled.
#[test]
fn owner_role() {
    let role = std::env::var("PLC_TEST_ROLE");
    let segment = std::env::var("SEGMENT").unwrap_or_default();
    let retain = std::env::var("RETAIN").map(PathBuf::from);
    match role.as_deref() {
        Ok("owner") => {
            Runtime::<Gm>::builder()
                .period(Duration::from_millis(5))
                .segment(segment)
                .retain(retain.unwrap())
                .build()
                .expect("the runtime's settings are valid")
                .run(|ctx| {
                    let gm = &mut ctx.gm;
                    gm.counter += 1;
                    for a in std::iter::once(&mut gm.lift).chain(gm.axes.iter_mut()) {
                        if a.enable {
                            a.pos = a.target;
                        }
                    }
                })
                .unwrap();
        }
        Ok("owner_v2") => {
            Runtime::<GmV2>::builder()
                .period(Duration::from_millis(5))
                .segment(segment)
                .retain(retain.unwrap())
                .build()
                .expect("the runtime's settings are valid")
                .run(|ctx| ctx.gm.counter += 1)
                .unwrap();
        }
        _ => {}
    }
}

struct Owner {
    child: ChildGuard,
}

impl Owner {
    fn start(role: &str, segment: &str, retain: &std::path::Path) -> Owner {
        let child = Command::new(std::env::current_exe().unwrap())
            .args(["owner_role", "--exact", "--nocapture"])
            .env("PLC_TEST_ROLE", role)
            .env("SEGMENT", segment)
            .env("RETAIN", retain)
            .stdout(Stdio::null())
            .spawn_guarded()
            .unwrap();
        let owner = Owner { child };
        wait_until("the owner to start", || {
            plc(&["get", segment, "counter"]).status.success()
        });
        owner
    }

    /// Stops it cleanly (SIGTERM: the final retain save, the segment removed).
    fn stop(mut self) {
        assert!(terminate(&mut self.child), "the owner stopped cleanly");
    }
}

impl Drop for Owner {
    fn drop(&mut self) {
        terminate(&mut self.child);
    }
}

fn get(segment: &str, path: &str) -> String {
    let out = plc(&["get", segment, path]);
    assert!(out.status.success(), "plc get {path}: {}", stderr(&out));
    stdout(&out).trim().to_string()
}

fn temp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("plc-cli-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    std::fs::set_permissions(&d, std::os::unix::fs::PermissionsExt::from_mode(0o700)).unwrap();
    d
}

#[test]
fn get_and_set_reach_members_by_path() {
    let dir = temp_dir("paths");
    let segment = format!("cli_struct_paths_{}", std::process::id());
    let owner = Owner::start("owner", &segment, &dir.join("s.retain"));
    assert_eq!(get(&segment, "axes[1].target"), "axes[1].target = 250.0");
    assert_eq!(get(&segment, "AXES[1].Drive_Id"), "AXES[1].Drive_Id = 3");

    // An IN parameter and a member are written; the program sees them.
    let out = plc(&[
        "set",
        &segment,
        "axes[1].target=12.5",
        "axes[1].enable=true",
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    wait_until("the axis to follow", || {
        get(&segment, "axes[1].pos") == "axes[1].pos = 12.5"
    });
    assert_eq!(
        get(&segment, "axes[0].pos"),
        "axes[0].pos = 0.0",
        "only axes[1] moved"
    );

    // A whole structure prints every member.
    let lift = get(&segment, "lift");
    assert!(
        lift.contains("lift.target = 250.0") && lift.contains("lift.moves = 0"),
        "{lift}"
    );
    assert_eq!(lift.lines().count(), 5, "{lift}");

    // Coordinates and the flat index name the same element.
    let out = plc(&["set", &segment, "grid[1,2]=-7"]);
    assert!(out.status.success(), "{}", stderr(&out));
    wait_until("the element", || get(&segment, "grid[5]") == "grid[5] = -7");

    // Refusals name the member and why; nothing is written.
    let out = plc(&["set", &segment, "axes[0].drive_id=9"]);
    assert!(!out.status.success());
    assert!(stderr(&out).contains("read-only"), "{}", stderr(&out));
    let out = plc(&["set", &segment, "axes[2].pos=1"]);
    assert!(!out.status.success());
    assert!(
        stderr(&out).contains("out of range 0..2"),
        "{}",
        stderr(&out)
    );
    let out = plc(&["get", &segment, "lift.speed"]);
    assert!(
        stderr(&out).contains("`lift` has no member `speed`"),
        "{}",
        stderr(&out)
    );
    assert_eq!(get(&segment, "axes[0].drive_id"), "axes[0].drive_id = 3");

    // The list shows each structure with its members under it.
    let list = stdout(&plc(&["list", &segment]));
    let line = |start: &str| {
        list.lines()
            .find(|l| l.starts_with(start))
            .map(str::to_string)
    };
    assert!(
        line("axes ").is_some_and(|l| l.contains("Axis[2]")),
        "{list}"
    );
    assert!(
        line("  drive_id ").is_some_and(|l| l.contains("read-only")),
        "{list}"
    );
    assert!(
        line("  enable ").is_some_and(|l| l.contains("input")),
        "{list}"
    );
    owner.stop();
}

#[test]
fn a_nonvolatile_member_survives_a_restart_and_an_edit() {
    let dir = temp_dir("retain");
    let retain = dir.join("s.retain");
    let segment = format!("cli_struct_retain_{}", std::process::id());
    let owner = Owner::start("owner", &segment, &retain);
    // `moves` is not read-only: written by a tool as a commissioning engineer would.
    let out = plc(&["set", &segment, "axes[1].moves=42", "lift.moves=7"]);
    assert!(out.status.success(), "{}", stderr(&out));
    wait_until("the write", || {
        get(&segment, "axes[1].moves") == "axes[1].moves = 42"
    });
    owner.stop();

    let owner = Owner::start("owner", &segment, &retain);
    assert_eq!(get(&segment, "axes[1].moves"), "axes[1].moves = 42");
    assert_eq!(get(&segment, "lift.moves"), "lift.moves = 7");
    owner.stop();

    // The edited program: a member added, the array grown.
    let owner = Owner::start("owner_v2", &segment, &retain);
    assert_eq!(get(&segment, "axes[1].moves"), "axes[1].moves = 42");
    assert_eq!(get(&segment, "lift.moves"), "lift.moves = 7");
    assert_eq!(get(&segment, "axes[2].moves"), "axes[2].moves = 0");
    assert_eq!(
        get(&segment, "axes[2].torque_limit"),
        "axes[2].torque_limit = 5"
    );
    owner.stop();
}

#[test]
fn watch_shows_structures_as_a_tree_and_writes_a_member() {
    let dir = temp_dir("watch");
    let segment = format!("cli_struct_watch_{}", std::process::id());
    let owner = Owner::start("owner", &segment, &dir.join("s.retain"));
    let cmd = format!("{} watch {} --rate 20", env!("CARGO_BIN_EXE_plc"), segment);
    let session = TmuxSession::start("plcwatchstruct", 150, 40, &cmd).unwrap();
    let screen = || session.screen();
    wait_until("the watch window", || screen().contains("▸ axes"));
    assert!(screen().contains("Axis[2]"), "{}", screen());
    assert!(
        !screen().contains("drive_id"),
        "closed at first:\n{}",
        screen()
    );

    // Select `axes` (the filter leaves it first), open it, then its element [1].
    session.send_keys(&["/", "axes", "Enter"]);
    wait_until("the filter", || !screen().contains("│counter"));
    session.send_keys(&["Right"]);
    wait_until("axes open", || {
        screen().contains("▾ axes") && screen().contains("▸ [1]")
    });
    session.send_keys(&["Down", "Down", "Right"]);
    wait_until("axes[1] open", || screen().contains("▾ [1]"));
    assert!(screen().contains("target"), "{}", screen());

    // Down to `axes[1].target`, then write it from the window.
    session.send_keys(&["Down", "Down", "Enter", "75.5", "Enter"]);
    wait_until("the write to reach the program", || {
        get(&segment, "axes[1].target") == "axes[1].target = 75.5"
    });
    assert!(
        screen().contains("wrote axes[1].target = 75.5"),
        "{}",
        screen()
    );
    session.send_keys(&["q"]);
    wait_until("watch to quit", || !session.is_running());
    owner.stop();
}

#[test]
fn log_records_members_by_path() {
    let dir = temp_dir("log");
    let segment = format!("cli_struct_log_{}", std::process::id());
    let owner = Owner::start("owner", &segment, &dir.join("s.retain"));
    let csv = dir.join("log.csv");
    let out = plc(&[
        "log",
        &segment,
        "axes[1].target",
        "lift",
        "counter",
        "--csv",
        csv.to_str().unwrap(),
        "--rate",
        "50",
        "--seconds",
        "0.3",
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    let header = lines.next().unwrap();
    assert!(
        header.starts_with("time_s,cycle,axes[1].target,lift.pos,lift.target,"),
        "{header}"
    );
    assert!(header.ends_with(",lift.moves,counter"), "{header}");
    let row: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!((row[2], row[4]), ("250.0", "250.0"), "{row:?}");
    owner.stop();
}
