//! A model of the tensile tester's mechanics, run on a thread against the simulated bus: it
//! reads the drive outputs the program sets (EL2889) and sets the limit switches and the break
//! detector (EL1004), so the program runs real tests without hardware.

use super::position::{INPUTS, OUTPUTS};
use ethercat_sim::SimBus;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

/// Seconds the centering jaws take to close, the lift to leave its limit, a specimen to break.
const CENTERING_S: f64 = 0.8;
const LIFT_S: f64 = 0.4;
const BREAK_S: [f64; 4] = [2.5, 3.1, 2.2, 3.6];

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

fn run(bus: &SimBus, stop: &AtomicBool) {
    let step = Duration::from_millis(5);
    let dt = step.as_secs_f64();
    let (mut jaws, mut lift, mut pulled) = (0.0f64, 0.0f64, 0.0f64);
    let mut tests = 0usize;
    let mut broken = false;
    let mut last = Instant::now();
    while !stop.load(Ordering::Relaxed) {
        std::thread::sleep(step.saturating_sub(last.elapsed()));
        last = Instant::now();
        let out = |bit| bus.output_bit(OUTPUTS, bit);
        let (brake_released, centering, lift_up, test_drive) = (out(0), out(1), out(2), out(3));
        if centering {
            jaws = (jaws + dt / CENTERING_S).min(1.0);
        } else {
            // Jaws open and the specimen is replaced when the program lets go.
            jaws = (jaws - dt / CENTERING_S).max(0.0);
            if jaws == 0.0 && broken {
                broken = false;
                pulled = 0.0;
                tests += 1;
            }
        }
        if brake_released && lift_up {
            lift = (lift + dt / LIFT_S).min(1.0);
        } else if !brake_released {
            lift = (lift - dt / LIFT_S).max(0.0);
        }
        if test_drive && !broken {
            pulled += dt;
            broken = pulled >= BREAK_S[tests % BREAK_S.len()];
        }
        bus.set_input_bit(INPUTS, 0, jaws >= 1.0);
        bus.set_input_bit(INPUTS, 1, jaws >= 1.0);
        bus.set_input_bit(INPUTS, 2, lift <= 0.0);
        bus.set_input_bit(INPUTS, 3, broken);
    }
}
