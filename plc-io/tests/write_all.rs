//! `DynSegment::write_all`: a batch checked whole before anything is sent, then every element
//! of it applied in one cycle, and visible to a snapshot taken as soon as the call returns
//! (the owner answers "applied" once it has published the image holding the writes).

mod common;

use common::{unique, wait_for};
use plc_core::write::Write;
use plc_core::{GlobalMemory, Value};
use plc_io::shm::{DynSegment, SharedGlobalMemory, ShmError};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

#[derive(GlobalMemory, Debug, Clone)]
pub struct Recipe {
    #[plc(direction = "command")]
    steps: [i32; 8],
    #[plc(direction = "status")]
    done: u32,
    #[plc(direction = "command")]
    speed: f32,
    #[plc(direction = "command")]
    position: f64,
}

/// An owner of segment `name` on a thread of its own, applying writes and publishing every
/// 200 µs until its flag is set.
fn run_owner(name: &str) -> (Arc<AtomicBool>, std::thread::JoinHandle<()>) {
    let stop = Arc::new(AtomicBool::new(false));
    let (name, flag) = (name.to_string(), stop.clone());
    let owner = std::thread::spawn(move || {
        let mut owner = SharedGlobalMemory::<Recipe>::create(&name).unwrap();
        let mut gm = Recipe::default();
        while !flag.load(Ordering::Relaxed) {
            owner.apply_requests(&mut gm);
            owner.publish(&gm).unwrap();
            std::thread::sleep(Duration::from_micros(200));
        }
    });
    (stop, owner)
}

/// A write of `value` to element `leaf` of variable `index`.
fn w(index: usize, leaf: usize, value: Value) -> Write {
    Write { index, leaf, value }
}

#[test]
fn an_array_written_whole_is_applied_whole_and_a_batch_with_a_refused_write_not_at_all() {
    let name = unique("write_all");
    let (stop, owner) = run_owner(&name);
    let seg = wait_for(Duration::from_secs(10), || DynSegment::attach(&name).ok());
    for round in 1..=50i64 {
        let batch: Vec<Write> = (0..8).map(|e| w(0, e, Value::Int(round))).collect();
        seg.write_all(&batch).unwrap();
        let image = seg.snapshot_bytes().unwrap();
        for e in 0..8 {
            assert_eq!(
                seg.descriptor().variables[0].value_in(&image, e),
                Some(Value::Int(round)),
                "step {e}"
            );
        }
    }
    // One refused element: nothing of the batch is posted.
    let before = seg.status().writes_applied;
    let bad = [w(0, 0, Value::Int(99)), w(1, 0, Value::Int(1))];
    assert!(matches!(
        seg.write_all(&bad),
        Err(ShmError::NotWritable { .. })
    ));
    let bad = [w(0, 0, Value::Int(99)), w(0, 8, Value::Int(1))];
    assert!(matches!(
        seg.write_all(&bad),
        Err(ShmError::ElementOutOfRange { .. })
    ));
    std::thread::sleep(Duration::from_millis(20));
    assert_eq!(seg.status().writes_applied, before);
    assert_eq!(seg.read_element("steps", 0).unwrap(), Value::Int(50));
    stop.store(true, Ordering::Relaxed);
    owner.join().unwrap();
}

#[test]
fn nan_and_infinities_are_refused_with_one_message_by_the_tool_and_by_the_owner() {
    let name = unique("write_nan");
    let (stop, owner) = run_owner(&name);
    let seg = wait_for(Duration::from_secs(10), || DynSegment::attach(&name).ok());
    for (index, ty) in [(2, "REAL"), (3, "LREAL")] {
        let label = if index == 2 { "speed" } else { "position" };
        let message =
            format!("`{label}`: not a finite number: {ty} takes no NaN or infinity from a tool");
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            // The tool's check.
            let err = seg.write_all(&[w(index, 0, Value::Real(bad))]).unwrap_err();
            assert_eq!(err.to_string(), message, "{bad}");
            // The owner's, for a tool that skipped its own.
            let err = seg.write_unchecked(index, 0, Value::Real(bad)).unwrap_err();
            let ShmError::WriteRejected { reason, .. } = &err else {
                panic!("not refused by the owner: {err}");
            };
            assert_eq!(reason, &message, "{bad}");
        }
        // A finite number still goes through.
        seg.write_all(&[w(index, 0, Value::Real(2.5))]).unwrap();
        assert_eq!(seg.read(label).unwrap(), Value::Real(2.5));
    }
    stop.store(true, Ordering::Relaxed);
    owner.join().unwrap();
}
