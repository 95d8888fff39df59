//! The cycle's side of the alarm journal allocates nothing: handing over a transition (queued
//! or, the queue full, only counted) takes no memory from the allocator; nor does the
//! runtime's cycle that evaluates a program's alarms and hands their transitions over. A test
//! binary of its own, for its counting allocator.

use plc_core::GlobalMemory;
use plc_core::alarm::{AlarmEvent, EventKind, Level};
use plc_runtime::Runtime;
use plc_runtime::alarm_journal::{AlarmJournal, JournalOptions};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::os::unix::fs::PermissionsExt;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Duration;

/// Counts the allocations of the threads that asked for it (not the writer's).
struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);
thread_local! {
    static COUNTING: Cell<bool> = const { Cell::new(false) };
}

// SAFETY: every call is passed to the system allocator unchanged.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if COUNTING.with(Cell::get) {
            ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        }
        // SAFETY: the caller's layout, as GlobalAlloc::alloc requires.
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: `ptr` came from `alloc` with this layout.
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        if COUNTING.with(Cell::get) {
            ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        }
        // SAFETY: as `GlobalAlloc::realloc` requires, passed on.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// A fresh directory of mode 0700 for `name`, as the journal requires.
fn private_dir(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::set_permissions(&dir, std::fs::Permissions::from_mode(0o700)).unwrap();
    dir
}

#[test]
fn recording_a_transition_allocates_nothing_queued_or_counted() {
    let dir = private_dir("plc-journal-alloc");
    let options = JournalOptions {
        queue: 64,
        ..JournalOptions::default()
    };
    let journal = AlarmJournal::open_with(dir.join("j.alarms"), options).unwrap();
    let sender = journal.sender(vec!["door".to_string(), "oil".to_string()]);
    let event = |t: i64| AlarmEvent {
        alarm: (t % 2) as usize,
        time_ns: t,
        kind: EventKind::Raised {
            level: Level::Active,
        },
    };
    COUNTING.with(|c| c.set(true));
    // Far more than the queue holds: some queued, most only counted.
    for t in 0..10_000 {
        sender.record(&event(t), 1.0);
    }
    COUNTING.with(|c| c.set(false));
    assert_eq!(ALLOCATIONS.load(Ordering::Relaxed), 0);
    assert!(sender.summarised() > 0, "the queue was full at times");
    journal.finish().unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
}

#[derive(GlobalMemory, Debug, Clone)]
struct Gm {
    #[plc(alarm = "Limit switch")]
    limits: [bool; 64],
    #[plc(alarm(text = "Pressure", high = 10.0, high_high = 12.0, deadband = 0.5))]
    pressure: f64,
}

#[test]
fn a_cycle_whose_alarms_all_change_allocates_nothing() {
    let dir = private_dir("plc-alarm-cycle-alloc");
    let runtime = Runtime::<Gm>::builder()
        .period(Duration::from_micros(200))
        .handle_signals(false)
        .alarm_journal(dir.join("gm.alarms"))
        .max_cycles(400)
        .build()
        .unwrap();
    // The run happens on this thread: counted from the 100th tick (every vector grown by
    // then) to the last, each alarm raised or cleared in every cycle between.
    let gm = runtime
        .run(|ctx| {
            let on = ctx.cycle % 2 == 0;
            ctx.gm.limits = [on; 64];
            ctx.gm.pressure = if on { 13.0 } else { 0.0 };
            if ctx.cycle == 100 {
                COUNTING.with(|c| c.set(true));
            }
            if ctx.cycle == 400 {
                COUNTING.with(|c| c.set(false));
            }
        })
        .unwrap();
    assert_eq!(gm.limits.len(), 64);
    assert_eq!(ALLOCATIONS.load(Ordering::Relaxed), 0);
    std::fs::remove_dir_all(&dir).unwrap();
}
