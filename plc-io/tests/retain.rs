//! Retained variables: round trips, edits of the declaration, damaged files, and crashes at
//! every step of a save.

mod common;

use common::{kill9, role, spawn_role};
use plc_core::{FixedString, GlobalMemory, IecType};
use plc_io::retain::{RetainError, RetainStore};
use std::path::PathBuf;
use std::time::Duration;

fn temp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("plc-retain-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[derive(GlobalMemory, Debug, Clone, PartialEq)]
pub struct V1 {
    #[plc(nonvolatile, initial = 12.5)]
    home_offset_mm: f64,
    #[plc(nonvolatile)]
    cycles: i16,
    #[plc(nonvolatile)]
    max_force: i32,
    #[plc(nonvolatile)]
    gain: f32,
    #[plc(nonvolatile)]
    old_name: u8,
    #[plc(nonvolatile)]
    table: [u16; 3],
    #[plc(nonvolatile, initial = "A")]
    recipe: FixedString<16>,
    not_kept: u32,
}

/// The next version of the program: `cycles` widened INT -> DINT, `max_force` narrowed DINT ->
/// INT, `gain` REAL -> LREAL, `old_name` renamed, `table` resized, `added` new.
#[derive(GlobalMemory, Debug, Clone, PartialEq)]
pub struct V2 {
    #[plc(nonvolatile, initial = 12.5)]
    home_offset_mm: f64,
    #[plc(nonvolatile)]
    cycles: i32,
    #[plc(nonvolatile, initial = 9)]
    max_force: i16,
    #[plc(nonvolatile)]
    gain: f64,
    #[plc(nonvolatile)]
    new_name: u8,
    #[plc(nonvolatile)]
    table: [u16; 4],
    #[plc(nonvolatile, initial = "A")]
    recipe: FixedString<16>,
    #[plc(nonvolatile, initial = 5)]
    added: u8,
}

fn v1() -> V1 {
    V1 {
        home_offset_mm: 3.25,
        cycles: -300,
        max_force: 70_000,
        gain: 0.5,
        old_name: 8,
        table: [1, 2, 3],
        recipe: FixedString::from_str_truncate("steel \"S235\""),
        not_kept: 99,
    }
}

#[test]
fn values_survive_a_restart() {
    let store = RetainStore::new(temp_dir("roundtrip").join("m.retain"));
    store.save(&v1()).unwrap();
    let mut gm = V1::default();
    let report = store.load(&mut gm).unwrap();
    assert_eq!(
        gm,
        V1 {
            not_kept: 0,
            ..v1()
        }
    );
    assert_eq!(report.restored.len(), 7);
    assert!(report.new.is_empty() && report.removed.is_empty() && report.reset.is_empty());
}

#[test]
fn a_missing_file_means_every_variable_is_new() {
    let store = RetainStore::new(temp_dir("missing").join("none.retain"));
    let mut gm = V1::default();
    let report = store.load(&mut gm).unwrap();
    assert_eq!(report.new.len(), 7);
    assert_eq!(gm.home_offset_mm, 12.5);
}

#[test]
fn edits_of_the_declaration_are_reported_and_widened_where_allowed() {
    let store = RetainStore::new(temp_dir("schema").join("m.retain"));
    store.save(&v1()).unwrap();
    let mut gm = V2::default();
    let r = store.load(&mut gm).unwrap();
    assert_eq!(gm.home_offset_mm, 3.25);
    assert_eq!(gm.cycles, -300, "INT widens to DINT");
    assert_eq!(gm.gain, 0.5, "REAL widens to LREAL");
    assert_eq!(gm.max_force, 9, "DINT does not narrow to INT: initial kept");
    assert_eq!(gm.table, [0; 4], "a resized array keeps its initial values");
    assert_eq!(gm.added, 5);
    assert_eq!(gm.recipe, "steel \"S235\"");
    assert_eq!(
        r.converted,
        [
            ("cycles".to_string(), IecType::Int, IecType::Dint),
            ("gain".to_string(), IecType::Real, IecType::Lreal)
        ]
    );
    assert_eq!(r.removed, ["old_name"]);
    assert_eq!(r.new, ["new_name", "added"]);
    let reset: Vec<&str> = r.reset.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(reset, ["max_force", "table"]);
    assert!(r.reset[0].1.contains("DINT to INT"));
}

#[test]
fn a_damaged_file_is_an_error_naming_it_and_is_left_untouched() {
    let dir = temp_dir("corrupt");
    let path = dir.join("m.retain");
    let store = RetainStore::new(&path);
    store.save(&v1()).unwrap();
    let mut bytes = std::fs::read(&path).unwrap();
    let at = bytes.len() - 10;
    bytes[at] ^= 1;
    std::fs::write(&path, &bytes).unwrap();
    let err = store.load(&mut V1::default()).unwrap_err();
    assert!(matches!(err, RetainError::Corrupt { .. }));
    assert!(err.to_string().contains(&path.display().to_string()));
    assert_eq!(std::fs::read(&path).unwrap(), bytes, "kept as it was");

    std::fs::write(&path, &bytes[..bytes.len() / 2]).unwrap();
    assert!(matches!(
        store.load(&mut V1::default()),
        Err(RetainError::Corrupt { .. })
    ));
    std::fs::write(&path, b"hello").unwrap();
    assert!(matches!(
        store.load(&mut V1::default()),
        Err(RetainError::Corrupt { .. })
    ));
}

/// kill -9s at arbitrary moments of a save loop (each costs a process start and ~25 ms).
const KILLS: u64 = 100;

#[test]
fn a_crash_at_any_step_of_a_save_leaves_the_old_or_the_new_file() {
    if role().as_deref() == Some("saver") {
        let store = RetainStore::new(std::env::var("RETAIN").unwrap());
        let mut gm = v1();
        gm.cycles = 2;
        store.save(&gm).unwrap(); // aborts at the step PLC_RETAIN_FAULT names
        return;
    }
    if role().as_deref() == Some("looper") {
        let store = RetainStore::new(std::env::var("RETAIN").unwrap());
        let mut gm = v1();
        loop {
            gm.cycles = gm.cycles.wrapping_add(1);
            gm.table = [gm.cycles as u16; 3];
            store.save(&gm).unwrap();
        }
    }
    if role().is_some() {
        return;
    }
    let dir = temp_dir("crash");
    let path = dir.join("m.retain");
    let store = RetainStore::new(&path);
    let test = "a_crash_at_any_step_of_a_save_leaves_the_old_or_the_new_file";
    // Steps of a save: 1 file created, 2 written, 3 fsynced, 4 renamed, 5 directory fsynced.
    for (step, expect) in [(1, -300), (2, -300), (3, -300), (4, 2), (5, 2)] {
        store.save(&v1()).unwrap();
        let env = [
            ("RETAIN", path.display().to_string()),
            ("PLC_RETAIN_FAULT", step.to_string()),
        ];
        let status = spawn_role(test, "saver", &env).wait().unwrap();
        assert!(!status.success(), "the saver was stopped at step {step}");
        let mut gm = V1::default();
        let report = store
            .load(&mut gm)
            .unwrap_or_else(|e| panic!("fault at step {step}: {e}"));
        assert_eq!(
            gm.cycles, expect,
            "fault at step {step}: the old or the new file"
        );
        assert_eq!(
            gm,
            V1 {
                cycles: expect,
                not_kept: 0,
                ..v1()
            },
            "fault at step {step}: every value of that file"
        );
        assert_eq!(report.restored.len(), 7, "fault at step {step}");
        // A save stopped before its rename left its temporary file; loading removes it.
        assert_eq!(
            report.stale_temps.len(),
            usize::from(step <= 3),
            "fault at step {step}: {:?}",
            report.stale_temps
        );
        assert_eq!(temporary_files(&dir), Vec::<String>::new(), "step {step}");
    }
    // And kill -9 at arbitrary moments while saving in a loop. The file before the first kill
    // holds the looper's invariant too, since a kill may come before its first save.
    let mut before = v1();
    before.table = [before.cycles as u16; 3];
    store.save(&before).unwrap();
    let env = [("RETAIN", path.display().to_string())];
    for i in 0..KILLS {
        let mut child = spawn_role(test, "looper", &env);
        std::thread::sleep(Duration::from_millis(5 + (i * 7) % 40));
        kill9(&mut child);
        let mut gm = V1::default();
        store
            .load(&mut gm)
            .unwrap_or_else(|e| panic!("after kill {i}: {e}"));
        assert_eq!(
            gm.table, [gm.cycles as u16; 3],
            "a consistent file after kill {i}"
        );
        assert_eq!(temporary_files(&dir), Vec::<String>::new(), "kill {i}");
    }
}

/// Names of the files in `dir` other than retain files.
fn temporary_files(dir: &std::path::Path) -> Vec<String> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| !n.ends_with(".retain"))
        .collect()
}

#[derive(GlobalMemory, Debug, Clone, PartialEq)]
pub struct Texts {
    #[plc(nonvolatile)]
    a: FixedString<16>,
    #[plc(nonvolatile)]
    b: FixedString<16>,
    #[plc(nonvolatile)]
    c: FixedString<16>,
    #[plc(nonvolatile)]
    nan: f32,
    #[plc(nonvolatile)]
    inf: f64,
}

#[test]
fn text_that_reads_like_a_number_is_restored_as_text_and_non_finite_reals_as_reals() {
    let store = RetainStore::new(temp_dir("texts").join("t.retain"));
    let saved = Texts {
        a: FixedString::from_str_truncate("inf"),
        b: FixedString::from_str_truncate("NaN"),
        c: FixedString::from_str_truncate("-infinity"),
        nan: f32::NAN,
        inf: f64::NEG_INFINITY,
    };
    store.save(&saved).unwrap();
    let mut gm = Texts::default();
    let report = store.load(&mut gm).unwrap();
    assert!(report.reset.is_empty(), "{:?}", report.reset);
    assert_eq!(
        (gm.a.as_str(), gm.b.as_str(), gm.c.as_str()),
        ("inf", "NaN", "-infinity")
    );
    assert!(gm.nan.is_nan());
    assert_eq!(gm.inf, f64::NEG_INFINITY);
}

#[test]
fn a_retain_writer_with_an_enormous_interval_still_saves() {
    use plc_io::retain::RetainWriter;
    let path = temp_dir("interval").join("m.retain");
    let writer = RetainWriter::spawn::<V1>(RetainStore::new(&path), Duration::MAX);
    writer.offer(v1().to_image());
    writer.finish(None).unwrap();
    let mut gm = V1::default();
    RetainStore::new(&path).load(&mut gm).unwrap();
    assert_eq!(gm.cycles, v1().cycles);
}

#[test]
fn a_failed_save_keeps_the_values_and_saves_them_when_it_can_again() {
    use plc_io::retain::RetainWriter;
    let dir = temp_dir("failing");
    let path = dir.join("gone").join("m.retain");
    // The directory does not exist yet: every save fails, as on a full or unmounted disk.
    let writer = RetainWriter::spawn::<V1>(RetainStore::new(&path), Duration::from_millis(20));
    writer.offer(v1().to_image());
    let deadline = std::time::Instant::now() + Duration::from_secs(10);
    while writer.failed_saves() == 0 {
        assert!(
            std::time::Instant::now() < deadline,
            "the save never failed"
        );
        std::thread::sleep(Duration::from_millis(5));
    }
    std::fs::create_dir_all(path.parent().unwrap()).unwrap();
    while !path.exists() {
        assert!(
            std::time::Instant::now() < deadline,
            "the values were dropped"
        );
        std::thread::sleep(Duration::from_millis(5));
    }
    writer.finish(None).unwrap();
    let mut gm = V1::default();
    RetainStore::new(&path).load(&mut gm).unwrap();
    assert_eq!(gm.cycles, v1().cycles);
}

mod structures {
    use super::temp_dir;
    use plc_core::{GlobalMemory, PlcStruct};
    use plc_io::retain::RetainStore;

    #[derive(PlcStruct, Debug, Clone, Copy, PartialEq)]
    pub struct AxisV1 {
        pub pos: f64,
        #[plc(nonvolatile)]
        pub cycles: u16,
        #[plc(nonvolatile)]
        pub offset: f32,
        #[plc(nonvolatile)]
        pub gone: u8,
    }

    #[derive(GlobalMemory, Debug, Clone, PartialEq)]
    pub struct V1 {
        pub lift: AxisV1,
        pub axes: [AxisV1; 3],
    }

    /// The next version: a member added before the others, `cycles` widened, `offset`
    /// retyped to a type it does not widen to, `gone` removed; the array grown to 4.
    #[derive(PlcStruct, Debug, Clone, Copy, PartialEq)]
    pub struct AxisV2 {
        #[plc(nonvolatile, initial = 9)]
        pub added: i32,
        pub pos: f64,
        #[plc(nonvolatile)]
        pub cycles: u32,
        #[plc(nonvolatile)]
        pub offset: i8,
    }

    #[derive(GlobalMemory, Debug, Clone, PartialEq)]
    pub struct V2 {
        pub lift: AxisV2,
        pub axes: [AxisV2; 4],
    }

    #[test]
    fn nonvolatile_members_are_kept_by_path_across_edits() {
        let dir = temp_dir("members");
        let store = RetainStore::new(dir.join("m.retain"));
        let mut v1 = V1::default();
        v1.lift.cycles = 11;
        v1.lift.pos = 5.0;
        for (i, a) in v1.axes.iter_mut().enumerate() {
            a.cycles = 100 + i as u16;
            a.offset = 0.5;
        }
        store.save(&v1).unwrap();
        let text = std::fs::read_to_string(store.path()).unwrap();
        assert!(text.contains("\"axes[2].cycles\""), "{text}");
        assert!(
            !text.contains("\"lift.pos\""),
            "only nonvolatile members: {text}"
        );

        // The same declaration restores every member.
        let mut same = V1::default();
        let report = store.load(&mut same).unwrap();
        assert_eq!(same.axes, v1.axes);
        assert_eq!(same.lift.cycles, 11);
        assert_eq!(same.lift.pos, 0.0, "not nonvolatile");
        assert!(report.restored.contains(&"lift.gone".to_string()));

        let mut v2 = V2::default();
        let report = store.load(&mut v2).unwrap();
        assert_eq!(v2.lift.cycles, 11);
        assert_eq!(
            v2.axes.map(|a| a.cycles),
            [100, 101, 102, 0],
            "the overlapping elements are kept, the new one starts at its initial value"
        );
        assert_eq!(v2.axes[3].added, 9);
        assert!(report.new.contains(&"axes[3].cycles".to_string()));
        assert!(report.new.contains(&"lift.added".to_string()));
        assert!(report.removed.contains(&"axes[1].gone".to_string()));
        assert!(
            report
                .converted
                .iter()
                .any(|(n, _, _)| n == "axes[0].cycles"),
            "{report:?}"
        );
        assert!(
            report.reset.iter().any(|(n, _)| n == "lift.offset"),
            "REAL does not widen to SINT: {report:?}"
        );
        assert_eq!(v2.lift.offset, 0);
    }
}

#[derive(GlobalMemory, Debug, Clone, PartialEq)]
pub struct Durations {
    #[plc(nonvolatile, initial = "T#5s")]
    dwell: plc_core::Time,
    #[plc(nonvolatile)]
    steps: [plc_core::Time; 2],
}

/// The same program, with `dwell` retyped to a number: a duration does not become one.
#[derive(GlobalMemory, Debug, Clone, PartialEq)]
pub struct DurationsRetyped {
    #[plc(nonvolatile, initial = 7)]
    dwell: i64,
    #[plc(nonvolatile)]
    steps: [plc_core::Time; 2],
}

#[test]
fn durations_are_kept_as_literals_to_the_nanosecond() {
    use plc_core::Time;
    let dir = temp_dir("durations");
    let store = RetainStore::new(dir.join("d.retain"));
    let saved = Durations {
        dwell: Time::from_nanos(-1_500_000_001),
        steps: [Time::MIN, Time::MAX],
    };
    store.save(&saved).unwrap();
    let text = std::fs::read_to_string(dir.join("d.retain")).unwrap();
    assert!(text.contains("\"LTIME#-1s500ms1ns\""), "{text}");
    let mut gm = Durations::default();
    let report = store.load(&mut gm).unwrap();
    assert!(report.reset.is_empty(), "{:?}", report.reset);
    assert_eq!(gm, saved);
    let mut retyped = DurationsRetyped::default();
    let report = store.load(&mut retyped).unwrap();
    assert_eq!(
        retyped.dwell, 7,
        "LTIME does not widen to LINT: initial kept"
    );
    assert_eq!(retyped.steps, saved.steps);
    assert_eq!(report.reset.len(), 1, "{:?}", report.reset);
}
