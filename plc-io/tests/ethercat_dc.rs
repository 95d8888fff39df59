//! Distributed clocks through `plc_io::ethercat` on the simulated bus: a description's
//! `dc = { sync0, shift }` brings SYNC0 up on those devices through real ethercrab, the
//! backend cycles on the DC time and reports how well the clocks agree; a device without a
//! DC unit, or a cycle period that does not fit SYNC0, is refused before the bus runs. A
//! program's status block carries the clocks to the tools, and a program's cycle follows
//! SYNC0 (its frame `shift` after each pulse) however the reference clock drifts.

#[path = "common/sim_bench.rs"]
mod sim_bench;

use ethercat_sim::{Device, SimBus};
use plc_core::GlobalMemory;
use plc_core::Time;
use plc_io::ethercat::{BusConfig, DcConfig, EtherCatError};
use plc_io::shm::{BusState, DynSegment, Status};
use plc_io::{CyclePhase, IoBackend, IoError, IoStatus, Runtime, RuntimeError};
use sim_bench::{backend, description, sim};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// Ring positions of the simulated bus.
const COUPLER: usize = 0;
const DI: usize = 1;
const DQ4: usize = 2;
const DQ16: usize = 3;

/// The difference every clock must stay below (Beckhoff specifies < 100 ns).
const LIMIT_NS: u32 = 100;

#[derive(GlobalMemory, Debug, Clone)]
struct Io {
    #[plc(link = "ethercat.di.input1", direction = "input")]
    in1: bool,
    #[plc(link = "ethercat.dq16.output1", direction = "output")]
    q16_1: bool,
}

const SYNC0: Duration = Duration::from_millis(1);

fn dc() -> DcConfig {
    DcConfig {
        sync0: Time::from_millis(1),
        shift: Time::from_micros(250),
    }
}

/// The test bench's description with `dc` on the devices at `positions`.
fn with_dc(positions: &[usize]) -> BusConfig {
    let mut bus = description();
    for &p in positions {
        bus.devices[p].dc = Some(dc());
    }
    bus
}

#[test]
fn a_description_with_dc_comes_up_cycles_on_sync0_and_keeps_the_clocks_within_100_ns() {
    let bus = sim();
    let mut backend = backend::<Io>(&bus, with_dc(&[DQ4, DQ16]));
    backend.start().unwrap();
    let mut gm = Io {
        q16_1: true,
        ..Io::default()
    };
    let mut status = backend.status();
    let mut offsets = Vec::new();
    // Half a second of 1 ms cycles: SYNC0 starts 100 ms after configuration.
    let began = Instant::now();
    for i in 0..500u32 {
        status = backend.exchange(&mut gm);
        assert!(status.inputs_valid, "cycle {i}: {status:?}");
        offsets.push(status.dc.map(|d| d.sync0_offset_ns));
        std::thread::sleep((began + SYNC0 * (i + 1)).saturating_duration_since(Instant::now()));
    }
    let dc = status.dc.expect("a DC bus reports its clocks");
    println!(
        "{dc:?}; SYNC0 {:?} {:?}; system times {:?}",
        bus.sync0(DQ4),
        bus.sync0(DQ16),
        bus.system_times()
    );
    assert_eq!(dc.sync0_period_ns, 1_000_000);
    let difference = dc.max_time_difference_ns.expect("0x092C was read");
    assert!(difference < LIMIT_NS, "largest difference {difference} ns");
    assert!(
        offsets.iter().all(|o| o.is_some_and(|ns| ns < 1_000_000)),
        "the offset to SYNC0 lies within one period: {offsets:?}"
    );
    for pos in [DQ4, DQ16] {
        let s = bus.sync0(pos);
        assert!(s.active, "device {pos}: {s:?}");
        assert!(s.pulses > 200, "device {pos}: only {} pulses", s.pulses);
        assert_eq!(s.last_pulse.map(|t| t % 1_000_000), Some(0), "{s:?}");
    }
    assert_eq!(
        bus.sync0(DI).pulses,
        0,
        "a device without `dc` takes no SYNC0"
    );
    assert_eq!(bus.outputs(DQ16)[0] & 1, 1, "the process data flows");
    backend.stop();
}

#[test]
fn a_description_without_dc_reports_no_clocks() {
    let bus = sim();
    let mut backend = backend::<Io>(&bus, description());
    backend.start().unwrap();
    let status = backend.exchange(&mut Io::default());
    assert!(status.inputs_valid && status.dc.is_none(), "{status:?}");
    assert_eq!(bus.sync0(DQ4).pulses, 0);
    backend.stop();
}

#[test]
fn dc_on_a_device_without_a_dc_unit_is_refused_at_start_naming_it() {
    let bus = sim();
    // The EL1004 announces DC in its features but has no system-time unit.
    let mut backend = backend::<Io>(&bus, with_dc(&[DI, DQ4]));
    let err = backend.start().unwrap_err();
    let text = err.to_string();
    assert!(
        matches!(err, EtherCatError::DistributedClocks(ref p) if p.len() == 1),
        "{text}"
    );
    assert!(text.contains("position 1 (`di`, EL1004)"), "{text}");
    assert!(text.contains("remove `dc` from it"), "{text}");
    std::thread::sleep(Duration::from_millis(150));
    assert_eq!(bus.sync0(DQ4).pulses, 0, "nothing was configured");
}

#[test]
fn a_cycle_period_that_does_not_divide_sync0_is_refused_when_the_runtime_is_built() {
    let bus = sim();
    let refused = Runtime::<Io>::builder()
        .period(Duration::from_micros(300))
        .backend(backend::<Io>(&bus, with_dc(&[DQ4])))
        .handle_signals(false)
        .build();
    let Err(RuntimeError::Io(e)) = refused else {
        panic!("a 300 us period with a 1 ms SYNC0 was accepted");
    };
    assert!(
        e.to_string()
            .contains("not a whole multiple of the cycle's period"),
        "{e}"
    );
    for fits in [Duration::from_millis(1), Duration::from_micros(500)] {
        let built = Runtime::<Io>::builder()
            .period(fits)
            .backend(backend::<Io>(&bus, with_dc(&[DQ4])))
            .handle_signals(false)
            .build();
        assert!(built.is_ok(), "{fits:?}");
    }
}

#[test]
fn a_clock_that_runs_away_shows_in_the_largest_difference() {
    let bus = sim();
    let mut backend = backend::<Io>(&bus, with_dc(&[DQ4, DQ16]));
    backend.start().unwrap();
    let mut gm = Io::default();
    // A crystal 1 % off: more than any time control loop follows.
    bus.set_clock_drift(DQ16, 10_000_000);
    let began = Instant::now();
    let mut largest = None;
    for i in 0..300u32 {
        largest = backend
            .exchange(&mut gm)
            .dc
            .and_then(|d| d.max_time_difference_ns);
        std::thread::sleep((began + SYNC0 * (i + 1)).saturating_duration_since(Instant::now()));
    }
    let largest = largest.expect("0x092C was read");
    assert!(largest > LIMIT_NS, "largest difference {largest} ns");
    backend.stop();
}

/// Runs a program on `config` with segment `name` until `done` holds for its status (read
/// through the segment, as a tool does, at most 10 s), and returns that status.
fn status_of_a_running_program(
    name: &str,
    config: BusConfig,
    done: impl Fn(&Status) -> bool,
) -> Status {
    let bus = sim();
    let builder = Runtime::<Io>::builder()
        .period(SYNC0)
        .backend(backend::<Io>(&bus, config))
        .segment(name)
        .handle_signals(false);
    let stop = builder.stop_handle();
    let program = std::thread::spawn(move || {
        builder
            .build()
            .expect("the runtime's settings are valid")
            .run(|_| {})
    });
    let began = Instant::now();
    let status = loop {
        if let Ok(seg) = DynSegment::attach(name) {
            let status = seg.status();
            if done(&status) {
                break status;
            }
        }
        if began.elapsed() > Duration::from_secs(10) || program.is_finished() {
            stop.stop();
            panic!("the program's status never came: {:?}", program.join());
        }
        std::thread::sleep(Duration::from_millis(10));
    };
    stop.stop();
    program.join().unwrap().unwrap();
    status
}

#[test]
fn a_running_program_on_dc_shows_its_clocks_to_the_tools() {
    let name = format!("dc_status_{}", std::process::id());
    // Half a second of cycles: SYNC0 starts 100 ms after configuration, the difference is
    // read every 100 ms.
    let status = status_of_a_running_program(&name, with_dc(&[DQ4, DQ16]), |s| {
        s.cycle_count >= 500 && s.clocks.is_some_and(|c| c.max_time_difference_ns.is_some())
    });
    assert_eq!(status.bus_state, BusState::Op, "{status:?}");
    let clocks = status.clocks.expect("checked above");
    println!("{clocks:?}: {clocks}");
    assert_eq!(clocks.sync0_period_ns, 1_000_000);
    let difference = clocks.max_time_difference_ns.expect("checked above");
    assert!(difference < LIMIT_NS, "largest difference {difference} ns");
    assert!(
        clocks.sync0_offset_ns < 1_000_000,
        "the offset to SYNC0 lies within one period: {clocks:?}"
    );
}

#[test]
fn a_running_program_without_dc_shows_no_clocks() {
    let name = format!("no_dc_status_{}", std::process::id());
    let status = status_of_a_running_program(&name, description(), |s| {
        s.cycle_count >= 20 && s.bus_state == BusState::Op
    });
    assert_eq!(status.clocks, None, "{status:?}");
}

/// One exchange as the runtime made it.
#[derive(Clone, Copy, Debug)]
struct Sample {
    /// When it began.
    began: Instant,
    /// How long it took.
    took: Duration,
    /// The offset to SYNC0 it measured (ns), if it did.
    offset: Option<u64>,
}

/// The EtherCAT backend as the runtime drives it, each exchange recorded; with `lock` false
/// it hides its phase from the runtime, whose cycle then runs on the host's clock alone.
struct Recorded {
    inner: plc_io::ethercat::EtherCatBackend<Io>,
    lock: bool,
    samples: Arc<Mutex<Vec<Sample>>>,
}

impl IoBackend<Io> for Recorded {
    fn start(&mut self) -> Result<(), IoError> {
        IoBackend::start(&mut self.inner)
    }
    fn exchange(&mut self, gm: &mut Io) -> IoStatus {
        let began = Instant::now();
        let status = IoBackend::exchange(&mut self.inner, gm);
        let took = began.elapsed();
        let offset = self.inner.cycle_phase().map(|p| p.offset.as_nanos() as u64);
        if let Ok(mut s) = self.samples.lock() {
            s.push(Sample {
                began,
                took,
                offset,
            });
        }
        status
    }
    fn fault(&mut self, gm: &mut Io) {
        IoBackend::fault(&mut self.inner, gm)
    }
    fn stop(&mut self) {
        IoBackend::stop(&mut self.inner)
    }
    fn check_period(&self, period: Duration) -> Result<(), IoError> {
        IoBackend::check_period(&self.inner, period)
    }
    fn cycle_phase(&self) -> Option<CyclePhase> {
        self.inner.cycle_phase().filter(|_| self.lock)
    }
}

/// `cycles` cycles of a runtime at 1 ms on `bus` (the bench with `dc` on DQ4 and DQ16),
/// locked to SYNC0 or not; every exchange.
fn run_recorded(bus: &SimBus, lock: bool, cycles: u64) -> Vec<Sample> {
    let samples = Arc::new(Mutex::new(Vec::with_capacity(cycles as usize + 1)));
    let backend = Recorded {
        inner: backend::<Io>(bus, with_dc(&[DQ4, DQ16])),
        lock,
        samples: samples.clone(),
    };
    Runtime::<Io>::builder()
        .period(SYNC0)
        .backend(backend)
        .max_cycles(cycles)
        .handle_signals(false)
        .build()
        .unwrap()
        .run(|_| {})
        .unwrap();
    samples.lock().unwrap().clone()
}

/// The bench's devices on a bus whose clocks come from seed 7 (the coupler, the reference
/// clock, drifts +89 ppm), with the reference clock then set to drift `drift_ppb`.
fn drifting_bus(drift_ppb: i64) -> SimBus {
    let bus = SimBus::with_clock_seed(
        vec![
            Device::ek1100(),
            Device::el1004(),
            Device::el2004(),
            Device::el2889(),
        ],
        7,
    );
    bus.set_clock_drift(COUPLER, drift_ppb);
    bus
}

/// The offsets to SYNC0 (ns) of the cycles that came on time, from cycle `from` on: the
/// exchange took under 150 us (a frame held up on its way, 25-50 us when the machine is
/// idle, reads as a late SYNC0 phase), and this cycle and the three before it started within
/// 100 us of a period after the one before (a cycle woken late, or the one that follows an
/// overrun at once, says nothing about the lock, nor do the few after it while the lock
/// undoes what that cycle made it correct). What a loaded machine does to the cycles is
/// left out; what remains is the lock.
fn on_time_offsets(samples: &[Sample], from: usize) -> Vec<u64> {
    let gap_ok = |i: usize| {
        i > 0 && {
            let gap = samples[i].began - samples[i - 1].began;
            gap.abs_diff(SYNC0) < Duration::from_micros(100)
        }
    };
    (from.max(4)..samples.len())
        .filter(|&i| samples[i].took < Duration::from_micros(150))
        .filter(|&i| (i - 3..=i).all(gap_ok))
        .filter_map(|i| samples[i].offset)
        .collect()
}

/// How far an offset to SYNC0 lies from the shift (ns), the short way round the 1 ms period.
fn from_shift(offset: u64, shift: u64) -> u64 {
    let d = offset.abs_diff(shift) % 1_000_000;
    d.min(1_000_000 - d)
}

/// Where the frame of a cycle that came on time passes the reference clock, against SYNC0 +
/// shift: every one within a quarter of the period, nine in ten within a tenth. Locked, the
/// cycles stay within about 20 us when the machine is idle: the exchange's own jitter (its
/// 25-50 us through the simulated transport) and the lock's residual (four times the drift
/// per cycle, 5 us here). On a loaded machine a cycle held up by less than the criteria of
/// [`on_time_offsets`] see, or one after a disturbance the lock is still undoing (it moves
/// at most a sixteenth of the period per cycle), can reach about 200 us. Unlocked, the
/// cycles sweep through the whole period with the clocks' drift.
const PHASE_BOUND_NS: u64 = 250_000;
const NEAR_NS: u64 = 100_000;

/// Of `offsets`, how many lie within `within` ns of `shift`, and those beyond `bound`.
fn spread(offsets: &[u64], shift: u64, within: u64, bound: u64) -> (usize, Vec<u64>) {
    let near = offsets
        .iter()
        .filter(|o| from_shift(**o, shift) < within)
        .count();
    let beyond = offsets
        .iter()
        .copied()
        .filter(|o| from_shift(*o, shift) >= bound)
        .collect();
    (near, beyond)
}

#[test]
fn the_runtime_cycles_on_the_dc_time_while_the_reference_clock_drifts() {
    let shift = dc().shift.as_nanos() as u64;
    // 1200 ppm: twelve times a poor crystal, so that a few hundred cycles show it (0.6 ms
    // in 500); the lock follows any drift below a sixteenth of the period per cycle.
    const DRIFT_PPB: i64 = 1_200_000;

    // The phase is measured on this machine's scheduler: a burst of load from elsewhere
    // (another build) can delay wake-ups by a few hundred microseconds. A lock that works
    // meets the bounds on a quiet attempt; one that does not never does (the free run below
    // shows how far off that is), so up to three attempts are made.
    let mut attempt = 0;
    let (offsets, near, beyond) = loop {
        attempt += 1;
        let locked = run_recorded(&drifting_bus(DRIFT_PPB), true, 600);
        // 100 cycles to lock from wherever the first cycle fell (at most half a period off,
        // at most a sixteenth of the period per cycle).
        let offsets = on_time_offsets(&locked, 100);
        let (near, beyond) = spread(&offsets, shift, NEAR_NS, PHASE_BOUND_NS);
        println!(
            "locked, attempt {attempt}: {} of 500 cycles on time, {near} within {NEAR_NS} ns \
             of the shift, beyond {PHASE_BOUND_NS} ns: {beyond:?}",
            offsets.len(),
        );
        let met = offsets.len() >= 50 && beyond.is_empty() && near * 10 >= offsets.len() * 9;
        if met || attempt == 3 {
            break (offsets, near, beyond);
        }
    };
    assert!(
        offsets.len() >= 50,
        "only {} of 500 cycles came on time: {offsets:?}",
        offsets.len(),
    );
    assert!(
        beyond.is_empty(),
        "cycles on time {PHASE_BOUND_NS} ns or more from the shift ({shift} ns): {beyond:?}"
    );
    assert!(
        near * 10 >= offsets.len() * 9,
        "only {near} of {} cycles on time within {NEAR_NS} ns of the shift: {offsets:?}",
        offsets.len()
    );

    // The same bus without the lock: the cycle keeps the host's time and its phase against
    // SYNC0 sweeps with the drift (0.72 ms in 600 cycles), so the test above can fail.
    let free = run_recorded(&drifting_bus(DRIFT_PPB), false, 600);
    let offsets = on_time_offsets(&free, 100);
    let (near, beyond) = spread(&offsets, shift, NEAR_NS, PHASE_BOUND_NS);
    println!(
        "free: {} of 500 cycles on time, {near} within {NEAR_NS} ns of the shift, {} beyond \
         {PHASE_BOUND_NS} ns",
        offsets.len(),
        beyond.len()
    );
    // The control is that the lock's own criteria fail without it. How many free cycles
    // happen to fall near the shift depends on where the sweep starts (a CI run once had 66 %
    // near, against a bound of 60 % this assertion used to have): what cannot happen is the
    // whole run staying within the bounds while the phase sweeps 0.72 ms.
    let meets_the_lock = offsets.len() >= 50 && beyond.is_empty() && near * 10 >= offsets.len() * 9;
    assert!(
        !meets_the_lock,
        "without the lock the cycles kept their phase ({near} of {} on time near the shift,          none beyond {PHASE_BOUND_NS} ns): the test cannot tell a lock from none: {offsets:?}",
        offsets.len()
    );
}
