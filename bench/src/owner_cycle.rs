//! A running owner's cycle time, read from its status block while something else loads the
//! machine: the groups that compare the cycle with a tool attached against without
//! (`cycle_with_opcua_clients_ratio`, `cycle_with_mqtt_ratio`) take their windows here.

use crate::owner::PERIOD;
use plc_io::shm::DynSegment;
use std::time::{Duration, Instant};

/// The owner's cycle times in one window.
pub struct Window {
    /// The median of the cycles sampled.
    pub median_us: f64,
    /// The mean of all cycles of the window.
    pub mean_us: f64,
}

/// The owner's cycle time over some windows: the median of the windows' medians and means.
pub struct Cycles {
    /// The median of the windows' medians.
    pub median_us: f64,
    /// The median of the windows' means.
    pub mean_us: f64,
}

impl Cycles {
    /// The median of `windows`' figures (NaN for none).
    pub fn of(windows: &[Window]) -> Cycles {
        let median = |mut v: Vec<f64>| {
            v.sort_by(f64::total_cmp);
            v.get(v.len() / 2).copied().unwrap_or(f64::NAN)
        };
        Cycles {
            median_us: median(windows.iter().map(|w| w.median_us).collect()),
            mean_us: median(windows.iter().map(|w| w.mean_us).collect()),
        }
    }
}

/// The owner's cycle time over the next `window`, from its status block: the time of the
/// last cycle, sampled every millisecond or so (each cycle at most once), and the mean of all
/// the window's cycles from the running mean times the cycle count at both ends. A cycle the
/// machine preempts for milliseconds moves the mean by as much as a thousand cycles of
/// work; the median is the typical cycle. Blocks the calling thread for the window.
pub fn sample(seg: &DynSegment, window: Duration) -> Window {
    let total = |seg: &DynSegment| {
        let s = seg.status();
        (
            s.cycle_count,
            s.stats.mean.as_secs_f64() * s.cycle_count as f64,
        )
    };
    let (c1, t1) = total(seg);
    let end = Instant::now() + window;
    let mut seen = c1;
    let mut last = Vec::new();
    while Instant::now() < end {
        let s = seg.status();
        if s.cycle_count != seen {
            seen = s.cycle_count;
            last.push(s.stats.last.as_secs_f64() * 1e6);
        }
        std::thread::sleep(PERIOD);
    }
    let (c2, t2) = total(seg);
    last.sort_by(f64::total_cmp);
    Window {
        median_us: last.get(last.len() / 2).copied().unwrap_or(f64::NAN),
        mean_us: if c2 > c1 {
            (t2 - t1) / (c2 - c1) as f64 * 1e6
        } else {
            f64::NAN
        },
    }
}
