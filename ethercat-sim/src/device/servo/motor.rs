//! The motor and its load as the drive's controllers see them: an inertia that the peak
//! torque accelerates at most at the acceleration limit, a speed limit, and a proportional
//! position loop with velocity feed-forward, so the position lags a moving target a little.
//! Integrated in small fixed steps, whatever the time between two process-data exchanges.

/// Integration step: small against the position loop's time constant (1 / [`KP`]), so the
/// loop is stable and a 1 ms cycle takes 8 steps.
const STEP_S: f64 = 125e-6;
/// Position loop gain (1/s): each increment of position error asks for KP increments/s more.
/// Invented: with the feed-forward the lag at constant speed is a few increments, and a
/// jump of the target still shows as a following error for tens of milliseconds.
const KP: f64 = 200.0;
/// Deceleration of a coasting motor (power stage off), as a fraction of the acceleration
/// limit: friction only (invented).
const COAST_FRACTION: f64 = 0.1;

/// The limits the drive's objects set.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Limits {
    /// Speed limit, increments/s (0x607F).
    pub(crate) velocity: f64,
    /// Acceleration limit, increments/s² (0x60C5): peak torque over inertia.
    pub(crate) acceleration: f64,
}

/// The motor's state. Positions are kept unwrapped in f64; the drive reports them wrapped
/// to i32 as a 32-bit position object does.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Motor {
    /// Position, increments.
    pub(crate) position: f64,
    /// Velocity, increments/s.
    pub(crate) velocity: f64,
    /// Acceleration of the last step, increments/s² (the torque, over the inertia).
    pub(crate) acceleration: f64,
    /// The position the position loop aims at (the interpolated target).
    pub(crate) demand: f64,
    /// Whether a limit (speed or acceleration) cut the last command: statusword bit 11.
    pub(crate) limited: bool,
}

impl Motor {
    /// Cyclic synchronous position over `dt` seconds: the demand moves linearly from `from`
    /// to `to` (the previous and the current target, as the drive interpolates between
    /// SYNC events); the velocity command is the demand's slope plus the position loop.
    pub(crate) fn follow(&mut self, from: f64, to: f64, dt: f64, limits: Limits) {
        let steps = steps(dt);
        if steps == 0 {
            return;
        }
        let feed_forward = (to - from) / dt;
        let h = dt / steps as f64;
        self.limited = false;
        for i in 0..steps {
            // Demand and position of the same instant, the step's start: the demand of its
            // end would make the loop lead the target by one step's travel.
            let demand = from + (to - from) * i as f64 / steps as f64;
            let command = feed_forward + KP * (demand - self.position);
            self.step(command, h, limits.acceleration, limits);
        }
        self.demand = to;
    }

    /// Runs towards velocity `target` over `dt` seconds, changing speed at most at
    /// `acceleration` (CSV, a hold at 0, a stop on a ramp). The demand follows the position.
    pub(crate) fn run_at(&mut self, target: f64, acceleration: f64, dt: f64, limits: Limits) {
        let steps = steps(dt);
        if steps == 0 {
            return;
        }
        let h = dt / steps as f64;
        self.limited = false;
        for _ in 0..steps {
            self.step(target, h, acceleration, limits);
        }
        self.demand = self.position;
    }

    /// The power stage is off: the motor coasts to a stop on friction.
    pub(crate) fn coast(&mut self, dt: f64, limits: Limits) {
        self.run_at(0.0, limits.acceleration * COAST_FRACTION, dt, limits);
        self.limited = false;
    }

    /// Sets the position (homing): the demand goes with it, so the loop does not move.
    pub(crate) fn set_position(&mut self, position: f64) {
        self.position = position;
        self.demand = position;
    }

    /// Whether the motor has stopped.
    pub(crate) fn stopped(&self) -> bool {
        self.velocity == 0.0
    }

    /// One step of `h` seconds towards velocity `command`, within the speed limit and at
    /// most `acceleration`.
    fn step(&mut self, command: f64, h: f64, acceleration: f64, limits: Limits) {
        let wanted = command.clamp(-limits.velocity, limits.velocity);
        let dv = (wanted - self.velocity).clamp(-acceleration * h, acceleration * h);
        self.limited |= wanted != command || dv != wanted - self.velocity;
        self.velocity += dv;
        self.acceleration = dv / h;
        // Semi-implicit Euler: the new velocity moves the position, which keeps the loop
        // stable at this step size.
        self.position += self.velocity * h;
    }
}

/// Steps for `dt` seconds (0 for no time or a time that is not a number).
fn steps(dt: f64) -> usize {
    if dt.is_finite() && dt > 0.0 {
        (dt / STEP_S).ceil().clamp(1.0, 1e6) as usize
    } else {
        0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const LIMITS: Limits = Limits {
        velocity: 1.0e6,
        acceleration: 1.0e7,
    };

    #[test]
    fn a_ramp_is_followed_with_a_small_lag() {
        let mut m = Motor::default();
        let v = 2.0e5; // increments/s, within the limits
        let dt = 1e-3;
        for k in 0..500 {
            let (from, to) = (v * k as f64 * dt, v * (k + 1) as f64 * dt);
            m.follow(from, to, dt, LIMITS);
        }
        let lag = m.demand - m.position;
        assert!(lag.abs() < 10.0, "lag {lag}");
        assert!((m.velocity - v).abs() < 1.0, "velocity {}", m.velocity);
    }

    #[test]
    fn a_jump_is_limited_by_speed_and_acceleration() {
        let mut m = Motor::default();
        m.follow(0.0, 1.0e6, 1e-3, LIMITS);
        // 1 ms at 1e7 increments/s²: at most 10 000 increments/s, ~5 increments.
        assert!(m.velocity <= 1.0e4 + 1e-6, "{}", m.velocity);
        assert!(m.position < 10.0 && m.limited);
    }

    #[test]
    fn no_time_or_a_bad_time_does_nothing() {
        let mut m = Motor::default();
        m.run_at(1.0e5, 1.0e7, 0.0, LIMITS);
        m.follow(0.0, 5.0, f64::NAN, LIMITS);
        m.run_at(1.0e5, 1.0e7, -1.0, LIMITS);
        assert_eq!(m, Motor::default());
    }
}
