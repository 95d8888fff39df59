//! A device's local clock: its oscillator, which starts at its own time and runs at its own
//! rate (drift), and the corrections its time control loop ([`super::control`]) makes.
//!
//! Time is kept in picoseconds so that corrections far below a nanosecond per frame add up
//! exactly; registers see whole nanoseconds. Corrections are counted in oscillator time, as
//! the ESC makes them per tick of its own clock (ET1100 datasheet, Section I "Distributed
//! Clocks": the loop changes how much each local clock tick adds, see `data/README.md`).

/// The fastest phase correction: 1 % of the elapsed time (an ESC adds 9 or 11 ns instead of
/// 10 on some of its 10 ns ticks; the model stays well inside that).
const SLEW_DIVISOR: i128 = 100;

/// Picoseconds per nanosecond.
const PS: i128 = 1_000;

/// Parts per trillion in one.
const PPT: i128 = 1_000_000_000_000;

/// Largest oscillator error a test may set (±1 %): far beyond any crystal (the ESCs require
/// ±25 ppm), and small enough that no arithmetic below leaves its range.
pub(crate) const MAX_DRIFT_PPB: i64 = 10_000_000;

/// A device's local clock.
#[derive(Clone, Debug, Default)]
pub(crate) struct Clock {
    /// Oscillator error in parts per billion: the oscillator advances `1 + drift` ns per ns
    /// of bus time.
    drift_ppb: i64,
    /// Bus time when the drift last changed, and the oscillator's time then (ps).
    osc_since_bus: u64,
    osc_since_ps: i128,
    /// Oscillator time (ps) of the last correction, and the corrections applied up to then.
    adjusted_at_ps: i128,
    adjustment_ps: i128,
    /// Rate correction since then, in parts per trillion of oscillator time.
    rate_ppt: i64,
    /// Phase correction still to make (ps), at most 1 % of the time that passes.
    slew_ps: i128,
}

impl Clock {
    /// A clock whose oscillator reads `start_ns` at bus time 0 and drifts by `drift_ppb`.
    pub(crate) fn new(start_ns: u64, drift_ppb: i64) -> Clock {
        let start = start_ns as i128 * PS;
        Clock {
            drift_ppb: drift_ppb.clamp(-MAX_DRIFT_PPB, MAX_DRIFT_PPB),
            osc_since_ps: start,
            adjusted_at_ps: start,
            ..Clock::default()
        }
    }

    /// The oscillator's error in parts per billion.
    pub(crate) fn drift_ppb(&self) -> i64 {
        self.drift_ppb
    }

    /// From bus time `bus` on, the oscillator drifts by `drift_ppb` (clamped to
    /// ±[`MAX_DRIFT_PPB`]); its time does not jump.
    pub(crate) fn set_drift(&mut self, bus: u64, drift_ppb: i64) {
        self.osc_since_ps = self.oscillator_ps(bus);
        self.osc_since_bus = bus.max(self.osc_since_bus);
        self.drift_ppb = drift_ppb.clamp(-MAX_DRIFT_PPB, MAX_DRIFT_PPB);
    }

    /// Oscillator time in ps at bus time `bus`. A bus time before the last drift change
    /// reads as that change: the clock never runs backwards.
    fn oscillator_ps(&self, bus: u64) -> i128 {
        let dt = bus.saturating_sub(self.osc_since_bus) as i128;
        self.osc_since_ps + dt * PS + dt * self.drift_ppb as i128 / 1_000_000
    }

    /// The corrections applied up to oscillator time `osc` (ps).
    fn adjustment_at(&self, osc: i128) -> i128 {
        let run = (osc - self.adjusted_at_ps).max(0);
        let slew = self.slew_ps.clamp(-run / SLEW_DIVISOR, run / SLEW_DIVISOR);
        self.adjustment_ps + run * self.rate_ppt as i128 / PPT + slew
    }

    /// The uncorrected oscillator time in ns at bus time `bus`: what the loop measures its
    /// own rate with.
    pub(crate) fn oscillator(&self, bus: u64) -> u64 {
        self.oscillator_ps(bus).div_euclid(PS) as u64
    }

    /// Local time in ns at bus time `bus`: oscillator plus corrections. It wraps as the
    /// ESC's 64-bit counter does.
    pub(crate) fn local(&self, bus: u64) -> u64 {
        let osc = self.oscillator_ps(bus);
        (osc + self.adjustment_at(osc)).div_euclid(PS) as u64
    }

    /// From bus time `bus` on, the clock runs `rate_ppt` parts per trillion faster than its
    /// oscillator and makes up `slew_ps` (this replaces what was left of the last phase
    /// correction).
    pub(crate) fn correct(&mut self, bus: u64, rate_ppt: i64, slew_ps: i128) {
        let osc = self.oscillator_ps(bus);
        self.adjustment_ps = self.adjustment_at(osc);
        self.adjusted_at_ps = osc.max(self.adjusted_at_ps);
        self.rate_ppt = rate_ppt;
        self.slew_ps = slew_ps;
    }

    /// Forgets every correction (a power cycle restarts the ESC's loop): local time falls
    /// back to the oscillator's.
    pub(crate) fn forget_corrections(&mut self) {
        self.adjustment_ps = 0;
        self.rate_ppt = 0;
        self.slew_ps = 0;
    }
}

/// The clock of the device at `index` on a bus seeded with `seed`: its oscillator starts
/// `base_ns` plus up to 16.7 ms (real terminals power up at different times) and drifts
/// between 5 and 100 ppm, either way. The same seed and index give the same clock.
pub(crate) fn seeded(seed: u64, index: usize, base_ns: u64) -> Clock {
    let mut state = seed ^ (index as u64).wrapping_mul(0xA076_1D64_78BD_642F);
    let start = base_ns + (splitmix64(&mut state) & 0x00FF_FFFF);
    let r = splitmix64(&mut state);
    let magnitude = 5_000 + (r >> 1) % 95_001;
    let drift = if r & 1 == 0 {
        magnitude as i64
    } else {
        -(magnitude as i64)
    };
    Clock::new(start, drift)
}

/// SplitMix64 (Steele, Lea and Flood, 2014): a small generator whose sequence depends only on
/// its seed, so a bus's clocks are the same on every run and machine.
fn splitmix64(state: &mut u64) -> u64 {
    *state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
    let mut z = *state;
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_drifting_oscillator_gains_its_drift() {
        let c = Clock::new(1_000, 100_000); // +100 ppm
        assert_eq!(c.local(0), 1_000);
        assert_eq!(c.local(1_000_000_000), 1_000 + 1_000_000_000 + 100_000);
        let slow = Clock::new(0, -50_000);
        assert_eq!(slow.local(2_000_000), 2_000_000 - 100);
    }

    /// Whether two clock readings agree to the nanosecond (readings are truncated).
    fn near(a: u64, b: u64) -> bool {
        a.abs_diff(b) <= 1
    }

    #[test]
    fn a_phase_correction_is_made_gradually_and_a_rate_correction_cancels_drift() {
        let mut c = Clock::new(0, 100_000);
        // -r/(1+r) for r = +100 ppm cancels the drift; then 500 ns back.
        c.correct(0, -99_990_001, -500_000);
        // 1 % of the first 10 µs (of oscillator time): 100 of the 500 ns so far.
        assert!(near(c.local(10_000), 10_000 - 100), "{}", c.local(10_000));
        assert!(near(c.local(1_000_000), 1_000_000 - 500));
        assert!(near(c.local(3_000_000_000), 3_000_000_000 - 500));
        assert_eq!(c.oscillator(1_000_000), 1_000_100);
    }

    #[test]
    fn changing_the_drift_does_not_move_the_clock_and_time_never_runs_back() {
        let mut c = Clock::new(0, 100_000);
        c.set_drift(1_000_000, -100_000);
        assert_eq!(c.local(1_000_000), 1_000_100);
        assert_eq!(c.local(2_000_000), 2_000_000);
        assert_eq!(
            c.local(5),
            1_000_100,
            "an earlier bus time reads as the change"
        );
        c.set_drift(0, i64::MIN);
        assert_eq!(c.drift_ppb(), -MAX_DRIFT_PPB);
        let _ = c.local(u64::MAX);
    }

    #[test]
    fn seeded_clocks_differ_by_device_and_repeat_by_seed() {
        let drifts: Vec<i64> = (0..64).map(|i| seeded(7, i, 0).drift_ppb()).collect();
        assert!(drifts.iter().all(|d| (5_000..=100_000).contains(&d.abs())));
        assert!(drifts.iter().any(|d| *d > 0) && drifts.iter().any(|d| *d < 0));
        assert_eq!(seeded(7, 3, 0).local(99), seeded(7, 3, 0).local(99));
        assert_ne!(seeded(7, 3, 0).local(0), seeded(8, 3, 0).local(0));
    }
}
