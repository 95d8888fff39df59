//! The time control loop of an ESC (ET1100 datasheet, Section I "Distributed Clocks",
//! "Drift compensation"; registers 0x0910-0x0935 in Section II): each system time the
//! reference clock's FRMW brings in is compared with the local copy,
//!
//! `Δt = (local time + offset − delay) − received system time` (lower 32 bits),
//!
//! and the local clock is sped up when Δt < 0 and slowed down when Δt > 0. Δt, averaged with
//! the filter depth of 0x0934, is the system time difference 0x092C. The correction comes in
//! two parts, each bounded per received time, so the clock never jumps:
//!
//! - rate ("speed counter", 0x0932: the deviation between the local clock period and the
//!   reference clock's): the oscillator's time elapsed since an anchor sample compared with
//!   the reference's time elapsed over the same frames, which measures the drift exactly
//!   whatever the intervals between frames; the rate moves towards it by at most 10 ppm per
//!   received time, within ±(speed counter start − 0x7F) units of 0.25 ppm;
//! - phase: half of Δt, made up at no more than 1 % of the time that passes
//!   ([`super::clock`]).
//!
//! Not the ESC's gate-level arithmetic: the model settles within about a hundred received
//! times (ethercrab's `dc_static_sync_iterations`), where an ET1100 needs thousands; its
//! speed counter filter depth (0x0935) is kept but not used.

/// One unit of the speed counter diff register 0x0932, in parts per trillion (0.25 ppm, near
/// the step of an ET1100 at the default speed counter start 0x1000).
const UNIT_PPT: i64 = 250_000;

/// The largest change of the rate correction per received time (10 ppm).
const MAX_STEP_PPT: i64 = 10_000_000;

/// The drift is measured once the reference's time has advanced this far since the anchor
/// (100 µs): shorter, the nanosecond steps of the received times make it too coarse.
const MIN_BASELINE_NS: i64 = 100_000;

/// The anchor moves on once the baseline reaches 1 s, so a drift that changes is followed.
const MAX_BASELINE_NS: i64 = 1_000_000_000;

/// A measured drift beyond 2 % is no drift: the received time jumped (a MainDevice wrote the
/// reference clock's offset). The measurement starts again from there.
const PLAUSIBLE_PPT: i128 = 20_000_000_000;

/// Parts per trillion in one.
const PPT: i128 = 1_000_000_000_000;

/// The loop's settings as the registers hold them.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Params {
    /// Speed counter start (0x0930, bits 0-14; minimum 0x0080).
    pub(crate) speed_counter_start: u16,
    /// System time difference filter depth (0x0934, bits 0-3).
    pub(crate) difference_filter_depth: u8,
}

impl Params {
    /// The largest rate correction, in ppt: ±(speed counter start − 0x7F) units.
    fn limit_ppt(&self) -> i64 {
        let start = (self.speed_counter_start & 0x7FFF).max(0x0080);
        (start - 0x7F) as i64 * UNIT_PPT
    }
}

/// What the clock is to do from the received time on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Correction {
    /// Rate correction in parts per trillion of oscillator time.
    pub(crate) rate_ppt: i64,
    /// Phase correction to make up (ps).
    pub(crate) slew_ps: i128,
}

/// A received time on the loop's two time lines: the local oscillator's and the reference's
/// (unwrapped from the 32 bits the loop receives).
#[derive(Clone, Copy, Debug)]
struct Mark {
    oscillator: u64,
    received: u64,
}

/// The loop's state.
#[derive(Clone, Debug, Default)]
pub(crate) struct ControlLoop {
    /// Δt averaged (0x092C), or None before the first received time.
    mean: Option<i64>,
    /// The last received time and the 32 bits that came.
    last: Option<(Mark, u32)>,
    /// Where the drift is measured from, and the next anchor once the baseline is long.
    anchor: Option<Mark>,
    next_anchor: Option<Mark>,
    /// Rate correction (ppt).
    rate_ppt: i64,
}

impl ControlLoop {
    /// Starts again (a write of speed counter start 0x0930 resets the filters, 0x092C and
    /// 0x0932).
    pub(crate) fn reset(&mut self) {
        *self = ControlLoop::default();
    }

    /// A received system time: `diff` is Δt (see the module), `oscillator` the local
    /// oscillator's time then (ns) and `received` the low 32 bits of the received time.
    pub(crate) fn update(
        &mut self,
        diff: i32,
        oscillator: u64,
        received: u32,
        params: Params,
    ) -> Correction {
        let mark = self.unwrap(oscillator, received);
        self.last = Some((mark, received));
        self.measure_rate(mark, params.limit_ppt());
        let diff = diff as i64;
        let depth = params.difference_filter_depth & 0x0F;
        self.mean = Some(match self.mean {
            Some(mean) => mean + ((diff - mean) >> depth),
            None => diff,
        });
        Correction {
            rate_ppt: self.rate_ppt,
            slew_ps: -(diff as i128) * 500,
        }
    }

    /// The received time on the reference's time line: the 32 bits that came, placed
    /// nearest to where the oscillator's elapsed time says they should be (so any pause
    /// between frames, even beyond the 4.3 s the low 32 bits cover, unwraps right).
    fn unwrap(&self, oscillator: u64, received: u32) -> Mark {
        let Some((last, last_received)) = self.last else {
            return Mark {
                oscillator,
                received: received as u64,
            };
        };
        let elapsed = oscillator.wrapping_sub(last.oscillator);
        let expected = last_received.wrapping_add(elapsed as u32);
        let off = received.wrapping_sub(expected) as i32;
        Mark {
            oscillator,
            received: last
                .received
                .wrapping_add(elapsed)
                .wrapping_add(off as i64 as u64),
        }
    }

    /// Measures the drift from the anchor to `mark` and moves the rate correction towards
    /// cancelling it, by at most [`MAX_STEP_PPT`].
    fn measure_rate(&mut self, mark: Mark, limit: i64) {
        let anchor = *self.anchor.get_or_insert(mark);
        let baseline = mark.received.wrapping_sub(anchor.received) as i64;
        if baseline < MIN_BASELINE_NS {
            if baseline < 0 {
                self.restart_measurement(mark);
            }
            return;
        }
        let gained = mark.oscillator.wrapping_sub(anchor.oscillator) as i64 - baseline;
        let drift = gained as i128 * PPT / baseline as i128;
        if drift.abs() > PLAUSIBLE_PPT {
            self.restart_measurement(mark);
            return;
        }
        // The correction counts oscillator time, which runs (1 + drift) as fast as the
        // reference's: -drift / (1 + drift) cancels it exactly.
        let target = (-drift * PPT / (PPT + drift)) as i64;
        let step = (target.clamp(-limit, limit) - self.rate_ppt).clamp(-MAX_STEP_PPT, MAX_STEP_PPT);
        self.rate_ppt = (self.rate_ppt + step).clamp(-limit, limit);
        if baseline >= MAX_BASELINE_NS {
            self.anchor = Some(self.next_anchor.take().unwrap_or(mark));
        } else if baseline >= MAX_BASELINE_NS / 2 && self.next_anchor.is_none() {
            self.next_anchor = Some(mark);
        }
    }

    fn restart_measurement(&mut self, mark: Mark) {
        self.anchor = Some(mark);
        self.next_anchor = None;
    }

    /// The system time difference register 0x092C: |mean Δt| in bits 0-30 (saturated), bit
    /// 31 set when the local copy is smaller than the received time.
    pub(crate) fn difference_register(&self) -> u32 {
        let mean = self.mean.unwrap_or(0);
        let magnitude = mean.unsigned_abs().min(0x7FFF_FFFF) as u32;
        if mean < 0 {
            0x8000_0000 | magnitude
        } else {
            magnitude
        }
    }

    /// The speed counter diff register 0x0932 (two's complement, units of 0.25 ppm).
    pub(crate) fn speed_counter_diff(&self) -> u16 {
        (self.rate_ppt / UNIT_PPT) as i16 as u16
    }
}

#[cfg(test)]
mod tests {
    use super::super::clock::Clock;
    use super::*;

    /// What ethercrab writes at start-up: 0x0934 = 0x00, 0x0930 = 0x1000.
    const ETHERCRAB: Params = Params {
        speed_counter_start: 0x1000,
        difference_filter_depth: 0,
    };

    /// Runs a reference clock and a second device's clock through `frames` FRMWs, the
    /// intervals from `interval(k)`, the loop correcting the second one if `correcting`.
    /// Returns Δt at every received time.
    fn run(
        reference_drift: i64,
        drift: i64,
        frames: usize,
        interval: impl Fn(usize) -> u64,
        correcting: bool,
    ) -> Vec<i32> {
        let reference = Clock::new(7_000_000, reference_drift);
        // 5 µs behind the reference at the start (an offset measured before the clocks
        // drifted apart).
        let mut local = Clock::new(7_000_000 - 5_000, drift);
        let mut control = ControlLoop::default();
        let (mut t, mut diffs) = (0u64, Vec::new());
        for k in 0..frames {
            let received = reference.local(t);
            let diff = local.local(t).wrapping_sub(received) as u32 as i32;
            diffs.push(diff);
            let c = control.update(diff, local.oscillator(t), received as u32, ETHERCRAB);
            if correcting {
                local.correct(t, c.rate_ppt, c.slew_ps);
            }
            t += interval(k);
        }
        diffs
    }

    /// Back-to-back FRMWs 20-80 µs apart with a pause of 1-20 ms every 97th, as a MainDevice
    /// on a busy machine sends them.
    fn busy(k: usize) -> u64 {
        if k % 97 == 96 {
            1_000_000 + (k as u64 * 7_919) % 19_000_000
        } else {
            20_000 + (k as u64 * 104_729) % 60_000
        }
    }

    #[test]
    fn the_loop_brings_clocks_200_ppm_apart_within_100_ns_and_keeps_them_there() {
        for (reference, drift) in [(100_000, -100_000), (-100_000, 100_000), (-3_000, 42_000)] {
            let diffs = run(reference, drift, 2_000, busy, true);
            let worst_after = |from: usize| diffs[from..].iter().map(|d| d.unsigned_abs()).max();
            assert!(
                worst_after(200) < Some(100),
                "{reference}/{drift}: {diffs:?}"
            );
            assert!(worst_after(1_000) <= Some(5), "{reference}/{drift}");
        }
    }

    #[test]
    fn without_the_loop_the_same_clocks_drift_apart() {
        let diffs = run(100_000, -100_000, 2_000, busy, false);
        assert!(
            diffs.last().unwrap().unsigned_abs() > 10_000,
            "{:?}",
            diffs.last()
        );
    }

    #[test]
    fn each_received_time_corrects_by_a_bounded_step() {
        let mut control = ControlLoop::default();
        let mut rate = 0;
        // The local oscillator gains 1 % on the reference: far more than a step covers.
        for k in 1..20u64 {
            let c = control.update(i32::MAX, k * 1_010_000, (k * 1_000_000) as u32, ETHERCRAB);
            assert!((c.rate_ppt - rate).abs() <= MAX_STEP_PPT);
            assert_eq!(c.slew_ps, -(i32::MAX as i128) * 500);
            rate = c.rate_ppt;
        }
        assert!(rate < 0);
        assert_eq!(control.difference_register(), 0x7FFF_FFFF);
        assert_eq!(control.speed_counter_diff() as i16 as i64, rate / UNIT_PPT);
    }

    #[test]
    fn the_difference_register_is_sign_and_magnitude_and_filtered_by_depth() {
        let mut control = ControlLoop::default();
        control.update(-600, 0, 0, ETHERCRAB);
        assert_eq!(control.difference_register(), 0x8000_0000 | 600);
        let depth_2 = Params {
            difference_filter_depth: 2,
            ..ETHERCRAB
        };
        control.update(200, 10, 10, depth_2); // -600 + (200 + 600) / 4
        assert_eq!(control.difference_register(), 0x8000_0000 | 400);
        control.reset();
        assert_eq!(control.difference_register(), 0);
    }

    #[test]
    fn a_jump_of_the_received_time_restarts_the_drift_measurement() {
        let mut control = ControlLoop::default();
        control.update(0, 0, 0, ETHERCRAB);
        // The reference's offset was rewritten: 50 ms more in 1 ms.
        let c = control.update(0, 1_000_000, 51_000_000, ETHERCRAB);
        assert_eq!(c.rate_ppt, 0);
        // Measured from the jump on: the oscillator gains 20 ppm.
        let c = control.update(0, 2_000_020, 52_000_000, ETHERCRAB);
        assert_eq!(c.rate_ppt, -MAX_STEP_PPT);
    }
}
