//! The runtime reports through the `log` crate, so a program decides where its messages go (a
//! terminal, the journal, its own UI) and can act on them: here a logger that keeps records.

use log::{Level, LevelFilter, Log, Metadata, Record};
use plc_core::GlobalMemory;
use plc_io::Runtime;
use plc_io::retain::RetainStore;
use std::sync::Mutex;
use std::time::Duration;

/// Level, target and text of every record.
struct Keep(Mutex<Vec<(Level, String, String)>>);

impl Log for Keep {
    fn enabled(&self, _: &Metadata) -> bool {
        true
    }
    fn log(&self, record: &Record) {
        let kept = (
            record.level(),
            record.target().to_owned(),
            record.args().to_string(),
        );
        self.0.lock().unwrap().push(kept);
    }
    fn flush(&self) {}
}

static KEPT: Keep = Keep(Mutex::new(Vec::new()));

/// The declaration a machine ran with before an update.
#[derive(GlobalMemory, Clone, Debug)]
struct Before {
    #[plc(nonvolatile)]
    count: u32,
    #[plc(nonvolatile)]
    old_offset: f64,
}

/// The declaration after it: `old_offset` is gone.
#[derive(GlobalMemory, Clone, Debug)]
struct After {
    #[plc(nonvolatile)]
    count: u32,
}

#[test]
fn a_program_captures_the_runtimes_log_records() {
    log::set_logger(&KEPT).expect("the only logger of this test binary");
    log::set_max_level(LevelFilter::Trace);
    let dir = std::env::temp_dir().join(format!("plc-log-records-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("machine.retain");
    let before = Before {
        count: 3,
        old_offset: 1.5,
    };
    RetainStore::new(&path).save(&before).unwrap();

    let gm = Runtime::<After>::builder()
        .period(Duration::from_millis(1))
        .retain(&path)
        .max_cycles(1)
        .handle_signals(false)
        .build()
        .expect("the runtime's settings are valid")
        .run(|_| {})
        .unwrap();
    assert_eq!(gm.count, 3, "the value still declared is restored");

    let kept = KEPT.0.lock().unwrap();
    let (level, target, text) = kept
        .iter()
        .find(|(_, _, text)| text.contains("`old_offset`"))
        .unwrap_or_else(|| panic!("no record names the removed variable: {kept:?}"));
    assert_eq!(*level, Level::Warn);
    assert!(target.starts_with("plc_io::retain"), "{target}");
    assert!(
        text.contains(&path.display().to_string()),
        "names the file: {text}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
