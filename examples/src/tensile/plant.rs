//! A model of the tensile tester's mechanics, run on a thread against the simulated bus: it
//! reads the drive outputs the program sets (EL2889) and the crosshead's position as the
//! simulated AKD measures it, and sets the limit switches and the break detector (EL1004), so
//! the program runs real tests without hardware. The guard door and the overtravel switch are
//! not among the EL1004's 4 channels: they read 0, the door closed and the crosshead within its
//! travel, so the machine runs with no alarm.

use super::crosshead::INCREMENTS_PER_MM;
use super::position::{CROSSHEAD, INPUTS, OUTPUTS};
use ethercat_sim::SimBus;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

/// Seconds the centering jaws take to close and the lift to leave its limit.
const CENTERING_S: f64 = 0.8;
const LIFT_S: f64 = 0.4;
/// How far the crosshead pulls a specimen before it breaks, mm, specimen after specimen.
pub(super) const BREAK_MM: [f64; 4] = [5.0, 6.2, 4.4, 7.2];
/// The AKD's position actual value (0x6064), in increments.
const POSITION_ACTUAL: u16 = 0x6064;

/// The running model; stops and joins its thread when dropped.
pub struct Plant {
    stop: Arc<AtomicBool>,
    thread: Option<JoinHandle<()>>,
}

impl Plant {
    /// Starts the model against `bus`.
    pub fn spawn(bus: SimBus) -> std::io::Result<Plant> {
        let stop = Arc::new(AtomicBool::new(false));
        let flag = stop.clone();
        let thread = std::thread::Builder::new()
            .name("tensile-plant".into())
            .spawn(move || run(&bus, &flag))?;
        Ok(Plant {
            stop,
            thread: Some(thread),
        })
    }
}

impl Drop for Plant {
    fn drop(&mut self) {
        self.stop.store(true, Ordering::Relaxed);
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
    }
}

/// Where the crosshead is, mm from the drive's 0, as the drive measures it.
fn crosshead_mm(bus: &SimBus) -> f64 {
    let increments = bus.device(CROSSHEAD).sdo(POSITION_ACTUAL, 0).unwrap_or(0) as i32;
    f64::from(increments) / INCREMENTS_PER_MM
}

fn run(bus: &SimBus, stop: &AtomicBool) {
    let step = Duration::from_millis(5);
    let dt = step.as_secs_f64();
    let (mut jaws, mut lift) = (0.0f64, 0.0f64);
    // Where the crosshead stood when the jaws gripped the specimen.
    let mut gripped_at: Option<f64> = None;
    let mut tests = 0usize;
    let mut broken = false;
    let mut last = Instant::now();
    while !stop.load(Ordering::Relaxed) {
        std::thread::sleep(step.saturating_sub(last.elapsed()));
        last = Instant::now();
        let out = |bit| bus.output_bit(OUTPUTS, bit);
        let (brake_released, centering, lift_up) = (out(0), out(1), out(2));
        if centering {
            jaws = (jaws + dt / CENTERING_S).min(1.0);
        } else {
            // Jaws open and the specimen is replaced when the program lets go.
            jaws = (jaws - dt / CENTERING_S).max(0.0);
            if jaws == 0.0 {
                gripped_at = None;
                if broken {
                    broken = false;
                    tests += 1;
                }
            }
        }
        if brake_released && lift_up {
            lift = (lift + dt / LIFT_S).min(1.0);
        } else if !brake_released {
            lift = (lift - dt / LIFT_S).max(0.0);
        }
        // Gripped, the specimen stretches as far as the crosshead pulls it, and breaks.
        if jaws >= 1.0 && !broken {
            let at = crosshead_mm(bus);
            let from = *gripped_at.get_or_insert(at);
            broken = at - from >= BREAK_MM[tests % BREAK_MM.len()];
        }
        bus.set_input_bit(INPUTS, 0, jaws >= 1.0);
        bus.set_input_bit(INPUTS, 1, jaws >= 1.0);
        bus.set_input_bit(INPUTS, 2, lift <= 0.0);
        bus.set_input_bit(INPUTS, 3, broken);
    }
}
