//! Where the cost goes, each step alone on a bare owner of `Gm1k`, beside the floors
//! ([`floor`](super::floor)): what any implementation pays for the same bytes.

use super::super::gm1k::Gm1k;
use super::super::owner::leaf_paths;
use super::super::timing::median_per_iter;
use super::compare::BATCH;
use super::floor;
use super::tool::{FORCED, forces_of, spread, traced_paths};
use plc_core::GlobalMemory;
use plc_io::shm::trace::Trace;
use plc_io::shm::{DynSegment, PathLocation, SharedGlobalMemory};
use std::fmt::Write as _;
use std::hint::black_box;
use std::time::{Duration, Instant};

/// Where the forced and traced values are in the image, for [`floor`].
#[derive(Clone)]
struct Places {
    forced: Vec<floor::Place>,
    traced: Vec<floor::Place>,
}

/// The steps' medians and their floors, each per application.
pub struct Steps {
    /// `apply_forces` with [`FORCED`] held (the cycle calls it twice).
    pub apply: Duration,
    /// `record_traces` with one [`TRACED`](super::tool::TRACED)-value trace.
    pub record: Duration,
    /// [`FORCED`] values stored at both boundaries at offsets known in advance.
    pub forces_floor: Duration,
    /// [`TRACED`](super::tool::TRACED) values gathered at offsets known in advance.
    pub trace_floor: Duration,
}

impl Steps {
    /// Their `name: value` lines.
    pub fn write(&self, out: &mut String) {
        let _ = writeln!(out, "forces_apply_32_ns: {}", self.apply.as_nanos());
        let _ = writeln!(out, "trace_record_64_ns: {}", self.record.as_nanos());
        let _ = writeln!(
            out,
            "forces_floor_32_twice_ns: {}",
            self.forces_floor.as_nanos()
        );
        let _ = writeln!(out, "trace_floor_64_ns: {}", self.trace_floor.as_nanos());
    }
}

/// `apply_forces` with [`FORCED`] held and `record_traces` with one
/// [`TRACED`](super::tool::TRACED)-value trace, each alone on a bare owner of `Gm1k`, a tool
/// on another thread forcing and tracing.
pub fn steps(name: &str, batches: usize) -> Result<Steps, String> {
    let shm = |e: plc_io::shm::ShmError| e.to_string();
    let mut owner = SharedGlobalMemory::<Gm1k>::create(name).map_err(shm)?;
    let mut gm = Gm1k::default();
    let mut image = Box::new(gm.to_image());
    owner.publish_image(&image).map_err(shm)?;
    let (tool_tx, tool_rx) = std::sync::mpsc::channel::<Result<Places, String>>();
    let (done_tx, done_rx) = std::sync::mpsc::channel::<()>();
    let tool_name = name.to_string();
    let tool = std::thread::spawn(move || {
        let held = (|| {
            let seg = DynSegment::attach(&tool_name).map_err(|e| e.to_string())?;
            let paths = leaf_paths(&seg);
            let forces = forces_of(&seg, &paths)?;
            seg.force(&forces).map_err(|e| e.to_string())?;
            let traced = traced_paths(&seg, &paths)?;
            let trace = seg.trace(&traced, 1).map_err(|e| e.to_string())?;
            let place = |at: &PathLocation| (at.var.offset, at.var.size);
            let places = Places {
                // The paths `forces_of` chose.
                forced: spread(&paths.iter().collect::<Vec<_>>(), FORCED)
                    .map(|p| seg.locate(p).map(|at| place(&at)))
                    .collect::<Result<_, _>>()
                    .map_err(|e| e.to_string())?,
                traced: traced.iter().map(place).collect(),
            };
            Ok::<(DynSegment, Trace, Places), String>((seg, trace, places))
        })();
        let _ = tool_tx.send(held.as_ref().map(|h| h.2.clone()).map_err(Clone::clone));
        // Attached until the steps are timed: the trace records while it is.
        let _ = done_rx.recv();
        drop(held);
    });
    // The owner's side of the tool's requests: applied, published, answered.
    let end = Instant::now() + Duration::from_secs(30);
    let told = loop {
        owner.apply_requests(&mut gm);
        gm.store_image(&mut image);
        owner.publish_image(&image).map_err(shm)?;
        if let Ok(told) = tool_rx.try_recv() {
            break told;
        }
        if Instant::now() > end {
            break Err("the tool did not force and trace in 30 s".into());
        }
        std::thread::sleep(Duration::from_micros(100));
    };
    // The trace's recording was queued before its answer: this takes it in.
    owner.apply_requests(&mut gm);
    let timed = told.and_then(|places| {
        if owner.forces_held() != FORCED {
            return Err(format!("{} forces held, not {FORCED}", owner.forces_held()));
        }
        let apply = median_per_iter(batches, BATCH, || owner.apply_forces(black_box(&mut gm)));
        let mut cycle = 0u64;
        // Once round the ring first (16,384 rows: a bare owner's period is zero).
        for _ in 0..16_384 {
            cycle += 1;
            owner.record_traces(&image, cycle, cycle);
        }
        let record = median_per_iter(batches, BATCH, || {
            cycle += 1;
            owner.record_traces(black_box(&image), cycle, cycle);
        });
        let bytes = zerocopy::IntoBytes::as_mut_bytes(&mut *image);
        let forces_floor = floor::forces(bytes, &places.forced, batches, BATCH);
        let trace_floor = floor::trace(bytes, &places.traced, batches, BATCH);
        Ok((apply, record, forces_floor, trace_floor))
    });
    let _ = done_tx.send(());
    let _ = tool.join();
    let (apply, record, forces_floor, trace_floor) = timed?;
    Ok(Steps {
        apply,
        record,
        forces_floor,
        trace_floor,
    })
}
