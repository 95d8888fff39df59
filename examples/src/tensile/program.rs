//! The tensile tester's program: the machine's state machine, one call per cycle.

use super::crosshead;
use super::vars::{Gm, State, axis};
use plc_core::{FixedString, Time};
use std::time::Duration;

/// How long each step may take.
const CENTERING_TIMEOUT: Time = Time::from_secs(5);
const LIFTING_TIMEOUT: Time = Time::from_secs(5);
const TEST_TIMEOUT: Time = Time::from_secs(100);

/// What the cycle tells the program besides the variables.
#[derive(Clone, Copy, Debug)]
pub struct TickInfo {
    /// The cycle period.
    pub period: Duration,
    /// The inputs are this cycle's (the bus answered correctly).
    pub inputs_valid: bool,
    /// The cycle's start (`Context::now`), for the step timeouts.
    pub now: Time,
}

fn go(gm: &mut Gm, to: State) {
    gm.machine_state = to as u8;
    gm.machine_state_name.set(to.name());
    gm.state_cycles = 0;
}

fn fault(gm: &mut Gm, text: &str) {
    gm.fault_text.set(text);
    go(gm, State::Fault);
}

/// The range the test drive accepts for `test_speed_mm_s`, and a made-up stiffness in kN/mm for
/// the force display.
const TEST_SPEED_MM_S: std::ops::RangeInclusive<f64> = 0.1..=10.0;
const STIFFNESS_KN_MM: f64 = 9.0;

/// One cycle of the tensile tester's program.
pub fn process_tick(gm: &mut Gm, info: TickInfo) {
    let dt = info.period.as_secs_f64();
    let secs = |s: f64| (s / dt).ceil() as u32;
    gm.state_cycles = gm.state_cycles.saturating_add(1);
    crosshead::read(gm);
    let state = State::from_u8(gm.machine_state);
    let speed = gm
        .test_speed_mm_s
        .clamp(*TEST_SPEED_MM_S.start(), *TEST_SPEED_MM_S.end());

    // Drives are off unless the state below switches them on.
    gm.cr_centering_drive = false;
    gm.cr_lift_up = false;
    gm.cr_lift_brake = false;
    gm.cr_test_drive = false;
    gm.horn = false;

    let running = state != State::Idle && state != State::Fault;
    if !info.inputs_valid && running {
        fault(gm, "EtherCAT inputs invalid: bus fault during a test");
    } else if (gm.guard_door_open || gm.ls_crosshead_overtravel) && running {
        // The safety relay has stopped the drives already; the step would only time out.
        fault(
            gm,
            "guard door opened or crosshead overtravel during a test",
        );
    } else if crosshead::faulted(gm) && state != State::Fault {
        let mut text = FixedString::<128>::new();
        let _ = std::fmt::Write::write_fmt(
            &mut text,
            format_args!(
                "crosshead drive fault 16#{:04X}: reset to go on",
                gm.crosshead.drive.error_code
            ),
        );
        gm.fault_text = text;
        go(gm, State::Fault);
    }
    let state = State::from_u8(gm.machine_state);
    if state != State::Fault {
        gm.reset.call(&mut gm.crosshead, false);
    }
    // Each step's timer runs while the machine is in that step.
    let now = info.now;
    gm.centering_timeout
        .call(now, state == State::Centering, CENTERING_TIMEOUT);
    gm.lifting_timeout
        .call(now, state == State::Lifting, LIFTING_TIMEOUT);
    gm.test_timeout
        .call(now, state == State::Testing, TEST_TIMEOUT);
    match state {
        State::Idle => {
            // A start waits for the crosshead (powered, homed and back at its start) and for
            // the guard door closed and the crosshead within its travel.
            let asked = gm.cmd_start || (gm.auto_start && gm.state_cycles >= secs(1.0));
            let guarded = !gm.guard_door_open && !gm.ls_crosshead_overtravel;
            if asked && guarded && crosshead::ready(gm) {
                gm.cmd_start = false;
                let mut id = FixedString::<64>::new();
                let _ = std::fmt::Write::write_fmt(
                    &mut id,
                    format_args!("TEST-{:04}", gm.tests_completed + 1),
                );
                gm.info_test_id = id;
                gm.force_kn = 0.0;
                gm.elongation_mm = 0.0;
                gm.max_force_kn = 0.0;
                gm.fault_text.clear();
                go(gm, State::Centering);
            }
        }
        State::Centering => {
            gm.cr_centering_drive = true;
            if gm.ls_centering_neg && gm.ls_centering_pos {
                go(gm, State::Lifting);
            } else if gm.centering_timeout.Q {
                gm.centering_timed_out = true;
                fault(gm, "centering jaws did not close within 5 s");
            }
        }
        State::Lifting => {
            gm.cr_centering_drive = true;
            gm.cr_lift_brake = true;
            gm.cr_lift_up = true;
            if !gm.ls_lift_neg && gm.state_cycles > secs(0.5) {
                gm.test_start_mm = gm.crosshead.actual_position;
                go(gm, State::Testing);
            } else if gm.lifting_timeout.Q {
                fault(gm, "lift did not leave its lower limit within 5 s");
            }
        }
        State::Testing => {
            gm.cr_centering_drive = true;
            gm.cr_lift_brake = true;
            gm.cr_test_drive = true;
            // The crosshead pulls (`crosshead::command`); the elongation is its travel.
            gm.elongation_mm = (gm.crosshead.actual_position - gm.test_start_mm).max(0.0);
            // Elastic, then yielding: a curve that looks like a test on an HMI.
            let e = gm.elongation_mm;
            gm.force_kn = STIFFNESS_KN_MM * e / (1.0 + e / 2.0);
            gm.max_force_kn = gm.max_force_kn.max(gm.force_kn);
            if gm.specimen_broken {
                gm.force_kn = 0.0;
                go(gm, State::Done);
            } else if gm.test_timeout.Q {
                fault(gm, "specimen did not break within 100 s");
            } else if gm.test_move.Error {
                fault(gm, "the crosshead refused the test move");
            }
        }
        State::Done => {
            gm.horn = gm.state_cycles < secs(0.3);
            if gm.state_cycles == 1 {
                gm.tests_completed = gm.tests_completed.saturating_add(1);
            }
            if gm.state_cycles > secs(1.0) {
                go(gm, State::Idle);
            }
        }
        State::Fault => {
            // The operator's acknowledgement runs MC_Reset until the drive left its fault.
            let acknowledged = gm.cmd_start || gm.cmd_reset;
            gm.cmd_start = false;
            gm.cmd_reset = false;
            let resetting = acknowledged || gm.reset.Busy;
            gm.reset.call(&mut gm.crosshead, resetting);
            if gm.reset.Done {
                gm.fault_text.clear();
                gm.centering_timed_out = false;
                go(gm, State::Idle);
            }
        }
    }
    let state = State::from_u8(gm.machine_state);
    crosshead::command(gm, state, speed);
    crosshead::write(gm, dt);
    update_axes(gm, state);
    gm.lamp_green = state == State::Idle;
    gm.lamp_yellow = matches!(
        state,
        State::Centering | State::Lifting | State::Testing | State::Done
    );
    gm.lamp_red = state == State::Fault || !info.inputs_valid;
}

/// The drives' view of this cycle: each follows its output, counts its cycles on and its
/// completed moves (a move completes when its step ends with the drive at its end position).
fn update_axes(gm: &mut Gm, state: State) {
    let outputs = [
        (axis::LIFT, gm.cr_lift_up, !gm.ls_lift_neg),
        (
            axis::CENTERING,
            gm.cr_centering_drive,
            gm.ls_centering_neg && gm.ls_centering_pos,
        ),
        (axis::TEST_DRIVE, gm.cr_test_drive, gm.specimen_broken),
    ];
    for (i, on, at_end) in outputs {
        let a = &mut gm.axes[i];
        if a.enable && !on && a.done {
            a.moves = a.moves.saturating_add(1);
        }
        a.enable = on;
        a.done = at_end;
        a.on_cycles = if on { a.on_cycles.saturating_add(1) } else { 0 };
    }
    gm.axes[axis::TEST_DRIVE].pos_mm = gm.elongation_mm;
    gm.axes[axis::LIFT].pos_mm = if gm.ls_lift_neg { 0.0 } else { 5.0 };
    gm.axes[axis::CENTERING].pos_mm = if state == State::Idle { 20.0 } else { 0.0 };
}

/// The program's tick as a runtime or a module host calls it: [`process_tick`] with the
/// cycle's facts. All of the program's state is in [`Gm`] (its function block instances and
/// axes included), so a new build taking over between two cycles carries it on.
pub fn tick(ctx: &mut plc_io::Context<Gm>) {
    let info = TickInfo {
        period: ctx.stats.period,
        inputs_valid: ctx.inputs_valid,
        now: ctx.now(),
    };
    process_tick(&mut ctx.gm, info);
}
