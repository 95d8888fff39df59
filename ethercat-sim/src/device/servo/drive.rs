//! One cycle of the drive's firmware: the controlword through the state machine, the mode's
//! controller and the motor over the time since the last cycle, the supervision (following
//! error, SYNC0), and the actual values and statusword written back to the objects.

use super::motor::{Limits, Motor};
use super::objects::{self as o, i8_of, i32_of, u16_of, u32_of};
use super::state_machine::State;
use crate::coe::Dictionary;

/// Modes of operation (0x6060) the drive runs; 0 ("no mode") holds the motor still.
const HOMING: i8 = 6;
const CSP: i8 = 8;
const CSV: i8 = 9;
/// Error codes (0x603F, CiA 402 / CiA 301): following error, and sync controller (the
/// SYNC0 the cyclic synchronous modes run on has stopped).
pub(crate) const FOLLOWING_ERROR: u16 = 0x8611;
pub(crate) const SYNC_ERROR: u16 = 0x8700;
/// Homing methods that take the current position as home (CiA 402: 37; 35 is its older
/// number). Other methods need switches the simulation does not have.
const HOME_HERE: [i8; 2] = [37, 35];
/// A gap longer than this between two exchanges counts as this long: the motor model
/// needs no more to settle, and a paused test must not cost minutes of integration.
const MAX_GAP_NS: u64 = 1_000_000_000;
/// Following error window 0xFFFF_FFFF switches the supervision off (CiA 402, 0x6065).
const WINDOW_OFF: u32 = u32::MAX;

/// Statusword bits beside the state's (IEC 61800-7-201 table 31 and the mode tables).
mod sw {
    /// Bit 9: the drive takes commands from the controlword.
    pub(super) const REMOTE: u16 = 1 << 9;
    /// Bit 10: target reached (homing: the home position is reached).
    pub(super) const TARGET_REACHED: u16 = 1 << 10;
    /// Bit 11: a speed or torque limit cuts the command.
    pub(super) const INTERNAL_LIMIT: u16 = 1 << 11;
    /// Bit 12: CSP/CSV "drive follows the command value"; homing "homing attained".
    pub(super) const MODE_12: u16 = 1 << 12;
    /// Bit 13: CSP "following error"; homing "homing error".
    pub(super) const MODE_13: u16 = 1 << 13;
}

/// The outcome of the last homing start.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
enum Homing {
    #[default]
    Idle,
    Attained,
    Failed,
}

/// What the drive's firmware keeps from cycle to cycle.
#[derive(Clone, Debug, Default)]
pub(crate) struct Drive {
    state: State,
    motor: Motor,
    /// Bus time of the last cycle.
    last_ns: Option<u64>,
    last_controlword: u16,
    /// The mode in use (0x6061).
    mode: i8,
    /// The last CSP target as received and unwrapped, the start of the next interpolation.
    previous_target: Option<(i32, f64)>,
    homing: Homing,
    /// How long the following error has been over the window, seconds.
    over_window: f64,
    /// The last fault's code (0x603F), until a fault reset.
    error_code: u16,
    /// SYNC0 ran while the drive followed a cyclic synchronous mode.
    sync_seen: bool,
}

impl Drive {
    /// One process-data cycle at bus time `now_ns`: `outputs_valid` is false outside OP (the
    /// MainDevice's outputs do not count, as if the controlword were 0); `sync0_running` is
    /// whether the ESC's SYNC0 is active (None: the ESC has no SYNC unit).
    pub(crate) fn cycle(
        &mut self,
        d: &mut Dictionary,
        now_ns: u64,
        outputs_valid: bool,
        sync0_running: Option<bool>,
    ) {
        let gap = self
            .last_ns
            .map_or(0, |last| now_ns.saturating_sub(last).min(MAX_GAP_NS));
        self.last_ns = Some(now_ns);
        let dt = gap as f64 * 1e-9;
        let cw = if outputs_valid {
            u16_of(d, o::CONTROLWORD)
        } else {
            0
        };
        let reset = cw & 0x0080 != 0 && self.last_controlword & 0x0080 == 0;
        let before = self.state;
        self.state = self.state.on_command(cw, reset);
        if before == State::Fault && self.state != State::Fault {
            self.error_code = 0;
        }
        let requested = i8_of(d, o::MODES_OF_OPERATION);
        if matches!(requested, 0 | HOMING | CSP | CSV) {
            self.mode = requested;
        }
        let limits = Limits {
            velocity: u32_of(d, o::MAX_VELOCITY) as f64,
            acceleration: u32_of(d, o::MAX_ACCELERATION) as f64,
        };
        let csp = self.state == State::OperationEnabled && self.mode == CSP;
        if !csp {
            self.previous_target = None;
            self.over_window = 0.0;
        }
        self.run(d, cw, dt, limits);
        if csp {
            self.supervise_following_error(d, dt);
        }
        self.supervise_sync(sync0_running);
        self.last_controlword = cw;
        self.publish(d, limits);
    }

    /// The state's and the mode's controller drive the motor for `dt` seconds.
    fn run(&mut self, d: &Dictionary, cw: u16, dt: f64, limits: Limits) {
        let quick_stop = u32_of(d, o::QUICK_STOP_DECELERATION) as f64;
        match (self.state, self.mode) {
            (State::OperationEnabled, CSP) => {
                let target = i32_of(d, o::TARGET_POSITION);
                let to = self.unwrap(target);
                let from = self.previous_target.map_or(to, |(_, t)| t);
                self.previous_target = Some((target, to));
                if dt > 0.0 {
                    self.motor.follow(from, to, dt, limits);
                } else {
                    self.motor.demand = to;
                }
            }
            (State::OperationEnabled, CSV) => {
                let target = i32_of(d, o::TARGET_VELOCITY) as f64;
                self.motor.run_at(target, limits.acceleration, dt, limits);
            }
            (State::OperationEnabled, mode) => {
                if mode == HOMING && cw & 0x0010 != 0 && self.last_controlword & 0x0010 == 0 {
                    self.start_homing(d);
                }
                self.motor.run_at(0.0, limits.acceleration, dt, limits);
            }
            (State::QuickStopActive | State::FaultReactionActive, _) => {
                self.motor.run_at(0.0, quick_stop, dt, limits);
                if self.motor.stopped() {
                    self.state = match self.state {
                        State::QuickStopActive => State::SwitchOnDisabled,
                        _ => State::Fault,
                    };
                }
            }
            _ => self.motor.coast(dt, limits),
        }
    }

    /// A homing start (controlword bit 4 rising in homing mode): the supported methods
    /// take the current position as the home offset 0x607C at once.
    fn start_homing(&mut self, d: &Dictionary) {
        let method = i8_of(d, o::HOMING_METHOD);
        self.homing = if HOME_HERE.contains(&method) {
            self.motor.set_position(i32_of(d, o::HOME_OFFSET) as f64);
            Homing::Attained
        } else {
            Homing::Failed
        };
    }

    /// The target `target` (i32, may have rolled over) as a position near the last one, so
    /// a target crossing ±2^31 is a small step, not a jump of 2^32.
    fn unwrap(&self, target: i32) -> f64 {
        let (raw, base) = self
            .previous_target
            .unwrap_or((wrap(self.motor.position), self.motor.position.round()));
        base + target.wrapping_sub(raw) as f64
    }

    /// Faults the drive when the following error stays over the window 0x6065 longer than
    /// the time out 0x6066.
    fn supervise_following_error(&mut self, d: &Dictionary, dt: f64) {
        let window = u32_of(d, o::FOLLOWING_ERROR_WINDOW);
        let error = (self.motor.demand - self.motor.position).abs();
        if window == WINDOW_OFF || error <= window as f64 {
            self.over_window = 0.0;
            return;
        }
        self.over_window += dt;
        let time_out = u16_of(d, o::FOLLOWING_ERROR_TIME_OUT) as f64 * 1e-3;
        if self.over_window >= time_out {
            self.fault(FOLLOWING_ERROR);
        }
    }

    /// Faults the drive when SYNC0 stops while it follows a cyclic synchronous mode that
    /// SYNC0 was driving (a drive in free run, never synchronised, is left alone).
    fn supervise_sync(&mut self, sync0_running: Option<bool>) {
        let cyclic = self.state == State::OperationEnabled && matches!(self.mode, CSP | CSV);
        match (cyclic, sync0_running) {
            (true, Some(true)) => self.sync_seen = true,
            (true, Some(false)) if self.sync_seen => {
                self.sync_seen = false;
                self.fault(SYNC_ERROR);
            }
            (false, _) => self.sync_seen = false,
            _ => {}
        }
    }

    /// A fault: the drive stops on the quick stop ramp, then shows fault.
    fn fault(&mut self, code: u16) {
        if !matches!(self.state, State::Fault | State::FaultReactionActive) {
            self.state = State::FaultReactionActive;
            self.error_code = code;
            self.previous_target = None;
        }
    }

    /// The actual values and the statusword into their objects.
    fn publish(&self, d: &mut Dictionary, limits: Limits) {
        let following = if self.state == State::OperationEnabled && self.mode == CSP {
            (self.motor.demand - self.motor.position).round()
        } else {
            0.0
        };
        let torque = if limits.acceleration > 0.0 && self.state.torque() {
            (self.motor.acceleration / limits.acceleration * 1000.0).round()
        } else {
            0.0
        };
        let position = wrap(self.motor.position) as u32;
        let values = [
            (o::STATUSWORD, self.statusword(d) as u32),
            (o::MODES_DISPLAY, self.mode as u8 as u32),
            (o::POSITION_ACTUAL, position),
            (o::POSITION_INTERNAL, position),
            (
                o::VELOCITY_ACTUAL,
                self.motor.velocity.round() as i32 as u32,
            ),
            (o::FOLLOWING_ERROR_ACTUAL, following as i32 as u32),
            (o::TORQUE_ACTUAL, torque as i16 as u16 as u32),
            (o::ERROR_CODE, self.error_code as u32),
        ];
        for (index, value) in values {
            o::store(d, index, 0, value);
        }
    }

    fn statusword(&self, d: &Dictionary) -> u16 {
        let mut bits = self.state.bits() | sw::REMOTE;
        if self.state.torque() && self.motor.limited {
            bits |= sw::INTERNAL_LIMIT;
        }
        if self.state == State::OperationEnabled {
            bits |= match self.mode {
                CSP => {
                    let window = u32_of(d, o::FOLLOWING_ERROR_WINDOW);
                    let error = (self.motor.demand - self.motor.position).abs();
                    let over = window != WINDOW_OFF && error > window as f64;
                    sw::MODE_12 | if over { sw::MODE_13 } else { 0 }
                }
                CSV => sw::MODE_12,
                _ => 0,
            };
        }
        if self.mode == HOMING {
            bits |= match self.homing {
                Homing::Attained => sw::MODE_12 | sw::TARGET_REACHED,
                Homing::Failed => sw::MODE_13,
                Homing::Idle => 0,
            };
        }
        bits
    }
}

/// A position as a 32-bit position object shows it: rolled over at ±2^31.
fn wrap(position: f64) -> i32 {
    position.round() as i64 as i32
}

#[cfg(test)]
mod tests {
    use super::*;

    const MS: u64 = 1_000_000;

    fn drive() -> (Drive, Dictionary) {
        (Drive::default(), o::akd(0x6A, 0x0041_4B44, 2, 0))
    }

    fn enable(drive: &mut Drive, d: &mut Dictionary, t: &mut u64) {
        for cw in [0x0000u16, 0x0006, 0x0007, 0x000F] {
            o::store(d, o::CONTROLWORD, 0, cw as u32);
            *t += MS;
            drive.cycle(d, *t, true, None);
        }
        assert_eq!(drive.state, State::OperationEnabled);
    }

    #[test]
    fn a_stopped_sync0_faults_a_synchronised_drive_with_0x8700() {
        let (mut drive, mut d) = drive();
        let mut t = 0;
        enable(&mut drive, &mut d, &mut t);
        for running in [Some(true), Some(true), Some(false)] {
            t += MS;
            drive.cycle(&mut d, t, true, running);
        }
        assert_eq!(u16_of(&d, o::ERROR_CODE), SYNC_ERROR);
        assert!(matches!(
            drive.state,
            State::FaultReactionActive | State::Fault
        ));
    }

    #[test]
    fn a_drive_in_free_run_does_not_fault_without_sync0() {
        let (mut drive, mut d) = drive();
        let mut t = 0;
        enable(&mut drive, &mut d, &mut t);
        for _ in 0..3 {
            t += MS;
            drive.cycle(&mut d, t, true, Some(false));
        }
        assert_eq!(drive.state, State::OperationEnabled);
    }

    #[test]
    fn outside_op_the_outputs_do_not_count_and_the_drive_disables() {
        let (mut drive, mut d) = drive();
        let mut t = 0;
        enable(&mut drive, &mut d, &mut t);
        drive.cycle(&mut d, t + MS, false, None);
        assert_eq!(drive.state, State::SwitchOnDisabled);
    }

    #[test]
    fn time_going_backwards_or_absurd_objects_do_not_panic() {
        let (mut drive, mut d) = drive();
        for (index, value) in [
            (o::MAX_VELOCITY, u32::MAX),
            (o::MAX_ACCELERATION, 0),
            (o::TARGET_POSITION, i32::MIN as u32),
            (o::TARGET_VELOCITY, i32::MAX as u32),
            (o::MODES_OF_OPERATION, 0x80),
        ] {
            o::store(&mut d, index, 0, value);
        }
        let mut t = u64::MAX - 5 * MS;
        enable(&mut drive, &mut d, &mut t);
        for now in [0, u64::MAX, 3] {
            drive.cycle(&mut d, now, true, Some(true));
        }
    }
}
