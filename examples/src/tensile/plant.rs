//! A model of the tensile tester's mechanics, run on a thread against the simulated bus: it
//! reads the drive outputs the program sets (EL2889) and the crosshead's position as the
//! simulated AKD measures it, and sets the limit switches and the break detector (EL1004), so
//! the program runs real tests without hardware. It names the I/O by the links of the bus
//! description, as the program's declaration does. The guard door and the overtravel switch are
//! not among the EL1004's 4 channels: they read 0, the door closed and the crosshead within its
//! travel, so the machine runs with no alarm.

use super::crosshead::INCREMENTS_PER_MM;
use plc_io::ethercat::PdoDirection;
use plc_io::ethercat::sim::SimBus;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

/// Seconds the centering jaws take to close and the lift to leave its limit.
const CENTERING_S: f64 = 0.8;
const LIFT_S: f64 = 0.4;
/// How far the crosshead pulls a specimen before it breaks, mm, specimen after specimen.
pub(super) const BREAK_MM: [f64; 4] = [5.0, 6.2, 4.4, 7.2];
/// The impact67 input word: bit 0 centering jaw negative limit, 1 positive limit, 2 lift
/// lower limit, 3 specimen break detector.
const DIGITAL_INPUTS: &str = "ethercat.impact67_0.digital_inputs";
/// The impact67 output word: bit 0 lift brake release, 1 centering drive, 2 lift drive up.
const DIGITAL_OUTPUTS: &str = "ethercat.impact67_0.digital_outputs";
/// The AKD's position actual value (0x6064), in increments, as the drive sends it.
const POSITION_ACTUAL: &str = "ethercat.crosshead.position_actual_value";

/// The running model; stops and joins its thread when dropped.
pub struct Plant {
    stop: Arc<AtomicBool>,
    thread: Option<JoinHandle<()>>,
}

impl Plant {
    /// Starts the model against `bus`, a bus made from the tensile tester's description
    /// (one whose links differ is refused, naming the link: the model would animate nothing).
    pub fn spawn(bus: SimBus) -> std::io::Result<Plant> {
        for (link, direction) in [
            (DIGITAL_INPUTS, PdoDirection::Input),
            (DIGITAL_OUTPUTS, PdoDirection::Output),
            (POSITION_ACTUAL, PdoDirection::Input),
        ] {
            let problem = match bus.link_direction(link) {
                Ok(d) if d == direction => continue,
                Ok(d) => format!("`{link}` is an {d} entry, and the model needs an {direction}"),
                Err(e) => e.to_string(),
            };
            return Err(std::io::Error::new(
                std::io::ErrorKind::InvalidInput,
                format!("the tensile tester's plant model needs its links: {problem}"),
            ));
        }
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
    let increments = bus.input::<i32>(POSITION_ACTUAL).unwrap_or(0);
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
        // Spawn checked the links: a read cannot fail, and 0 would be "all drives off".
        let outputs = bus.output::<u16>(DIGITAL_OUTPUTS).unwrap_or(0);
        let out = |bit: u32| outputs >> bit & 1 == 1;
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
        let closed = u16::from(jaws >= 1.0);
        let inputs = closed | closed << 1 | u16::from(lift <= 0.0) << 2 | u16::from(broken) << 3;
        let _ = bus.set_input(DIGITAL_INPUTS, inputs);
    }
}

#[cfg(test)]
mod tests {
    use super::super::{BUS_TOML, simulated_bus};
    use super::Plant;
    use plc_io::ethercat::{BusConfig, Transport};

    #[test]
    fn the_built_in_description_makes_the_simulated_bus_and_the_plant_finds_its_links() {
        let bus = simulated_bus();
        assert_eq!(
            bus.device_names(),
            ["EK1100", "EL1004", "EL2889", "EL2004", "AKD"]
        );
        assert!(Plant::spawn(bus).is_ok());
    }

    #[test]
    fn the_plant_refuses_a_bus_without_its_links_naming_the_link() {
        let text = BUS_TOML.replace("\"digital_inputs\"", "\"inputs\"");
        let config = BusConfig::from_toml_str(&text).unwrap();
        let (_, bus) = Transport::simulated(&config).unwrap();
        let err = Plant::spawn(bus).err().expect("refused");
        assert!(
            err.to_string().contains(
                "`ethercat.impact67_0.digital_inputs`: device `impact67_0` has no entry \
                 `digital_inputs` (did you mean `digital_outputs`?): use one of `inputs`, \
                 `digital_outputs`"
            ),
            "{err}"
        );
    }
}
