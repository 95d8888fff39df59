//! The set point of an axis, one cycle at a time: a trapezoidal profile (accelerate, cruise,
//! decelerate) computed online at the cycle's period, as cyclic synchronous position mode
//! wants a new target every cycle. Online, so that a move may be replaced by another at any
//! cycle (PLCopen's aborting moves) from wherever the axis is and however fast it goes.
//!
//! The braking distance is the discrete one: from a speed of `n·a·dt` the axis stops in `n`
//! cycles over `a·dt²·n(n+1)/2`, so the axis slows down in time and stops on the target
//! without overshooting it and without braking harder than its deceleration.

/// Where the set point is and how fast it goes, in user units and units per second.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SetPoint {
    /// Position.
    pub position: f64,
    /// Velocity.
    pub velocity: f64,
}

/// The limits of a move: each positive and finite.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Limits {
    /// Highest speed.
    pub velocity: f64,
    /// Highest rate of speeding up.
    pub acceleration: f64,
    /// Highest rate of slowing down.
    pub deceleration: f64,
}

impl Limits {
    /// Whether every limit is positive and finite (what a move may be started with).
    pub fn valid(&self) -> bool {
        [self.velocity, self.acceleration, self.deceleration]
            .iter()
            .all(|x| x.is_finite() && *x > 0.0)
    }
}

/// `x.sqrt()` without the standard library (plc-core also builds `no_std`): Newton's method
/// from an estimate halving the exponent; exact to the last bits for the distances here.
fn sqrt(x: f64) -> f64 {
    if x <= 0.0 || !x.is_finite() {
        return if x == f64::INFINITY { x } else { 0.0 };
    }
    let mut y = f64::from_bits((x.to_bits() >> 1) + (1023u64 << 51));
    for _ in 0..6 {
        y = 0.5 * (y + x / y);
    }
    y
}

/// The highest speed from which an axis slowing down by at most `dec·dt` each cycle of `dt`
/// (the position advancing by each cycle's new speed) comes to rest exactly after `distance`.
/// With `n` whole steps of `dec·dt` the speeds `n·dec·dt + e, ..., e, 0` cover
/// `dec·dt²·n(n+1)/2 + (n+1)·e·dt`; `n` is the most whole steps that fit and `e` (at most
/// `dec·dt`) takes the rest, so the last step's slowing down is within the limit too.
fn stopping_speed(distance: f64, dec: f64, dt: f64) -> f64 {
    let step = dec * dt;
    let unit = step * dt;
    let mut n = (sqrt(0.25 + 2.0 * distance / unit) - 0.5).max(0.0) as u64 as f64;
    // The square root's last bits may put `n` one off: settle it on the exact sum.
    if unit * n * (n + 1.0) / 2.0 > distance && n > 0.0 {
        n -= 1.0;
    } else if unit * (n + 1.0) * (n + 2.0) / 2.0 <= distance {
        n += 1.0;
    }
    let rest = distance - unit * n * (n + 1.0) / 2.0;
    step * n + (rest / ((n + 1.0) * dt)).clamp(0.0, step)
}

/// Moves `v` towards `wanted` by at most what `limits` allow in `dt`: speeding up (away from
/// zero) at most by the acceleration, slowing down by the deceleration.
fn approach(v: f64, wanted: f64, limits: &Limits, dt: f64) -> f64 {
    let dv = wanted - v;
    let speeding_up = (v >= 0.0 && dv > 0.0) || (v <= 0.0 && dv < 0.0);
    let most = if speeding_up {
        limits.acceleration
    } else {
        limits.deceleration
    } * dt;
    v + dv.clamp(-most, most)
}

impl SetPoint {
    /// One cycle of `dt` seconds of a move to `target`: the set point after it, and whether it
    /// is on the target at rest.
    pub fn towards(&self, target: f64, limits: &Limits, dt: f64) -> (SetPoint, bool) {
        let distance = target - self.position;
        // On the target and slow enough to stop within this cycle: at rest there.
        if distance == 0.0 && self.velocity.abs() <= limits.deceleration * dt {
            let rest = SetPoint {
                position: target,
                velocity: 0.0,
            };
            return (rest, true);
        }
        let direction = if distance >= 0.0 { 1.0 } else { -1.0 };
        let brake = stopping_speed(distance.abs(), limits.deceleration, dt);
        let wanted = direction * limits.velocity.min(brake);
        let v = approach(self.velocity, wanted, limits, dt);
        let landing = distance / dt;
        let most = limits.acceleration.max(limits.deceleration) * dt;
        if v * direction > 0.0
            && v * direction * dt >= distance.abs()
            && (landing - self.velocity).abs() <= most
        {
            // This cycle reaches the target: land on it (the next one comes to rest). Where
            // the rounding of a long move's positions makes the landing speed differ from the
            // last step's by a hair more than the limit, the axis instead passes the target by
            // as much (far below a nanometre) and lands on the next cycle.
            let landing = SetPoint {
                position: target,
                velocity: landing,
            };
            return (landing, false);
        }
        let next = SetPoint {
            position: self.position + v * dt,
            velocity: v,
        };
        (next, false)
    }

    /// One cycle of `dt` seconds towards the speed `velocity` (signed): the set point after
    /// it, and whether it runs at that speed.
    pub fn at_speed(&self, velocity: f64, limits: &Limits, dt: f64) -> (SetPoint, bool) {
        let v = approach(self.velocity, velocity, limits, dt);
        (
            SetPoint {
                position: self.position + v * dt,
                velocity: v,
            },
            v == velocity,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn square_roots_are_exact_enough() {
        for x in [1e-12, 0.5, 2.0, 1e6, 12345.678, 1e300] {
            let s = sqrt(x);
            assert!((s * s - x).abs() <= x * 1e-15, "{x}: {s}");
        }
        assert_eq!(sqrt(0.0), 0.0);
        assert_eq!(sqrt(-1.0), 0.0);
    }

    /// Runs a move from rest at `from` to `to`, checking every cycle; the cycles it took.
    fn run(from: f64, to: f64, limits: Limits, dt: f64) -> Result<usize, TestCaseError> {
        let mut sp = SetPoint {
            position: from,
            velocity: 0.0,
        };
        let (lo, hi) = (from.min(to), from.max(to));
        let slack = 1e-9;
        let most_cycles = 10_000_000;
        for cycle in 1..most_cycles {
            let (next, done) = sp.towards(to, &limits, dt);
            let accel = (next.velocity - sp.velocity) / dt;
            // Slowing down may use the deceleration, speeding up the acceleration.
            let bound = limits.acceleration.max(limits.deceleration);
            prop_assert!(
                accel.abs() <= bound * (1.0 + slack) + slack,
                "cycle {cycle}: acceleration {accel} over {bound}"
            );
            prop_assert!(
                next.velocity.abs() <= limits.velocity * (1.0 + slack),
                "cycle {cycle}: speed {} over {}",
                next.velocity,
                limits.velocity
            );
            let span = (hi - lo).max(1.0) * slack;
            prop_assert!(
                next.position >= lo - span && next.position <= hi + span,
                "cycle {cycle}: {} outside {lo}..{hi}",
                next.position
            );
            sp = next;
            if done {
                prop_assert_eq!(sp.position, to);
                prop_assert_eq!(sp.velocity, 0.0);
                return Ok(cycle);
            }
        }
        Err(TestCaseError::fail("never arrived"))
    }

    #[test]
    fn a_long_move_accelerates_cruises_and_decelerates_onto_its_target() {
        let limits = Limits {
            velocity: 100.0,
            acceleration: 1000.0,
            deceleration: 500.0,
        };
        let cycles = run(0.0, 50.0, limits, 0.001).unwrap();
        // 0.1 s up, 0.2 s down, the rest at 100 mm/s: 0.5 + 0.1/2... about 0.65 s.
        assert!((640..=660).contains(&cycles), "{cycles} cycles");
    }

    proptest! {
        #[test]
        fn moves_never_exceed_their_limits_and_end_on_their_target(
            from in -1000.0f64..1000.0,
            to in -1000.0f64..1000.0,
            velocity in 1.0f64..500.0,
            acceleration in 50.0f64..20_000.0,
            deceleration in 50.0f64..20_000.0,
            dt_us in prop::sample::select(vec![250u32, 500, 1000, 2000, 4000]),
        ) {
            let limits = Limits { velocity, acceleration, deceleration };
            run(from, to, limits, f64::from(dt_us) * 1e-6)?;
        }
    }

    #[test]
    fn a_speed_is_reached_at_the_acceleration() {
        let limits = Limits {
            velocity: 10.0,
            acceleration: 100.0,
            deceleration: 100.0,
        };
        let mut sp = SetPoint::default();
        let mut cycles = 0;
        loop {
            let (next, there) = sp.at_speed(-20.0, &limits, 0.01);
            cycles += 1;
            assert!((next.velocity - sp.velocity).abs() <= 1.0 + 1e-12);
            sp = next;
            if there {
                break;
            }
        }
        assert_eq!(cycles, 20);
        assert_eq!(sp.velocity, -20.0);
    }
}
