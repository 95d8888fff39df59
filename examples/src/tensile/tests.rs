//! The program against a drive without a bus: a test run, its waits, faults and timeouts.
// Tests set the variables a scenario needs after `Default`, as a program would.
#![allow(clippy::field_reassign_with_default)]

use super::drive::Drive;
use super::*;
use plc_core::motion::AxisState;
use plc_core::{GlobalMemory, Time};
use std::time::Duration;

const CYCLE: Duration = Duration::from_millis(10);

/// `n` cycles of 10 ms from `start_ms`, each exchanging with `drive` first.
fn run(gm: &mut Gm, drive: &mut Drive, start_ms: i64, n: i64) {
    for k in 0..n {
        drive.exchange(gm);
        process_tick(
            gm,
            TickInfo {
                period: CYCLE,
                inputs_valid: true,
                now: Time::from_millis(start_ms + 10 * k),
            },
        );
    }
}

/// A machine started and powered, its crosshead homed, waiting for a start.
fn powered() -> (Gm, Drive) {
    let mut gm = Gm::default();
    gm.auto_start = false;
    let mut drive = Drive::new();
    run(&mut gm, &mut drive, 0, 10);
    assert!(gm.power.Status && gm.crosshead.homed && gm.to_start.Done);
    assert_eq!(gm.machine_state, State::Idle as u8);
    (gm, drive)
}

/// A machine started, its specimen centred and lifted: the crosshead about to pull.
fn testing() -> (Gm, Drive) {
    let (mut gm, mut drive) = powered();
    gm.cmd_start = true;
    run(&mut gm, &mut drive, 0, 1);
    assert_eq!(gm.machine_state, State::Centering as u8);
    run(&mut gm, &mut drive, 0, 1);
    assert!(gm.cr_centering_drive);
    gm.ls_centering_neg = true;
    gm.ls_centering_pos = true;
    gm.ls_lift_neg = true;
    run(&mut gm, &mut drive, 0, 1);
    assert_eq!(gm.machine_state, State::Lifting as u8);
    gm.ls_lift_neg = false;
    run(&mut gm, &mut drive, 0, 60);
    assert_eq!(gm.machine_state, State::Testing as u8);
    assert!(gm.cr_test_drive && gm.lamp_yellow);
    (gm, drive)
}

#[test]
fn a_test_pulls_with_the_crosshead_until_the_break_and_stops_it() {
    let (mut gm, mut drive) = testing();
    // At the test speed of 2 mm/s (reached after 0.04 s at 50 mm/s²): 4 mm in 2 s.
    run(&mut gm, &mut drive, 0, 10);
    assert!(gm.test_move.InVelocity);
    let before = gm.crosshead.actual_position;
    run(&mut gm, &mut drive, 0, 200);
    assert_eq!(gm.crosshead.state(), AxisState::ContinuousMotion);
    let travel = gm.crosshead.actual_position - before;
    assert!((travel - 4.0).abs() < 1e-3, "pulled {travel} mm");
    // The elongation is the travel since the test started, as the drive measured it.
    let since_start = gm.crosshead.actual_position - gm.test_start_mm;
    assert!(
        (gm.elongation_mm - since_start).abs() < 0.03,
        "{}",
        gm.elongation_mm
    );
    assert!(gm.force_kn > 0.0);
    gm.specimen_broken = true;
    run(&mut gm, &mut drive, 0, 2);
    assert_eq!(gm.machine_state, State::Done as u8);
    assert_eq!(gm.tests_completed, 1);
    assert!(gm.max_force_kn > 0.0);
    assert!(!gm.cr_test_drive);
    // MC_Stop brakes at 100 mm/s²: at rest within 20 ms, 0.02 mm further.
    run(&mut gm, &mut drive, 0, 5);
    assert!(gm.stop.Done && !gm.test_move.Busy);
    assert_eq!(gm.crosshead.state(), AxisState::Stopping);
    let rest = gm.crosshead.actual_position;
    run(&mut gm, &mut drive, 0, 10);
    assert_eq!(gm.crosshead.actual_position, rest, "held where it stopped");
    assert_eq!(gm.axes[axis::TEST_DRIVE].pos_mm, gm.elongation_mm);
    assert_eq!(
        gm.axes[axis::TEST_DRIVE].moves,
        1,
        "the test drive's move completed"
    );
    assert!(!gm.axes[axis::TEST_DRIVE].enable);
    // Idle again, the crosshead goes back to its start for the next test.
    gm.specimen_broken = false;
    run(&mut gm, &mut drive, 0, 200);
    assert_eq!(gm.machine_state, State::Idle as u8);
    assert!(gm.to_start.Done && gm.crosshead.actual_position.abs() < 1e-6);
}

#[test]
fn a_start_waits_for_the_crosshead_to_be_powered_and_homed() {
    let mut gm = Gm::default();
    gm.cmd_start = true;
    let mut drive = Drive::new();
    run(&mut gm, &mut drive, 0, 1);
    assert_eq!(gm.machine_state, State::Idle as u8);
    assert!(
        gm.cmd_start,
        "the start is kept until the crosshead is ready"
    );
    run(&mut gm, &mut drive, 10, 10);
    assert_eq!(gm.machine_state, State::Centering as u8);
    assert!(gm.home.Done || gm.crosshead.homed);
}

#[test]
fn a_drive_fault_faults_the_machine_and_the_operators_reset_clears_it() {
    let (mut gm, mut drive) = powered();
    gm.machine_state = State::Testing as u8;
    run(&mut gm, &mut drive, 0, 50);
    assert_eq!(gm.crosshead.state(), AxisState::ContinuousMotion);
    drive.fault(0x8611);
    run(&mut gm, &mut drive, 0, 2);
    assert_eq!(gm.machine_state, State::Fault as u8);
    assert_eq!(
        gm.fault_text.as_str(),
        "crosshead drive fault 16#8611: reset to go on"
    );
    assert!(gm.lamp_red && !gm.cr_test_drive);
    assert_eq!(gm.crosshead.state(), AxisState::ErrorStop);
    assert_eq!((gm.power.Error, gm.power.ErrorID), (true, 0x8611));
    // Nothing happens until the operator acknowledges.
    run(&mut gm, &mut drive, 0, 20);
    assert_eq!(gm.machine_state, State::Fault as u8);
    gm.cmd_reset = true;
    run(&mut gm, &mut drive, 0, 10);
    assert!(!gm.cmd_reset);
    assert_eq!(gm.machine_state, State::Idle as u8);
    assert!(gm.fault_text.is_empty());
    assert_eq!(gm.crosshead.error_id, 0);
    run(&mut gm, &mut drive, 0, 200);
    assert!(gm.power.Status && gm.to_start.Done, "{:?}", gm.crosshead);
}

#[test]
fn a_bus_fault_during_a_test_stops_the_drives() {
    let mut gm = Gm::default();
    gm.machine_state = State::Testing as u8;
    process_tick(
        &mut gm,
        TickInfo {
            period: Duration::from_millis(1),
            inputs_valid: false,
            now: Time::ZERO,
        },
    );
    assert_eq!(gm.machine_state, State::Fault as u8);
    assert!(!gm.cr_test_drive && !gm.cr_lift_brake && gm.lamp_red);
}

#[test]
fn a_step_that_takes_too_long_faults_through_its_timer() {
    let (mut gm, mut drive) = powered();
    gm.cmd_start = true;
    let tick = |gm: &mut Gm, drive: &mut Drive, ms: i64| run(gm, drive, ms, 1);
    tick(&mut gm, &mut drive, 0);
    assert_eq!(gm.machine_state, State::Centering as u8);
    tick(&mut gm, &mut drive, 10);
    assert!(gm.centering_timeout.IN && !gm.centering_timeout.Q);
    tick(&mut gm, &mut drive, 4_000);
    assert_eq!(gm.centering_timeout.ET, Time::from_millis(3_990));
    assert_eq!(gm.machine_state, State::Centering as u8);
    tick(&mut gm, &mut drive, 5_010);
    assert_eq!(gm.machine_state, State::Fault as u8);
    assert_eq!(
        gm.fault_text.as_str(),
        "centering jaws did not close within 5 s"
    );
    assert!(gm.centering_timed_out, "its alarm's variable is set");
    tick(&mut gm, &mut drive, 5_020);
    assert!(
        !gm.centering_timeout.Q,
        "the timer resets when the step ends"
    );
    assert!(gm.centering_timed_out, "until the fault is reset");
    gm.cmd_reset = true;
    run(&mut gm, &mut drive, 5_030, 5);
    assert_eq!(gm.machine_state, State::Idle as u8);
    assert!(!gm.centering_timed_out);
}

#[test]
fn an_open_guard_door_holds_the_start_and_faults_a_running_test() {
    let (mut gm, mut drive) = powered();
    gm.guard_door_open = true;
    gm.cmd_start = true;
    run(&mut gm, &mut drive, 0, 3);
    assert_eq!(gm.machine_state, State::Idle as u8, "no start");
    gm.guard_door_open = false;
    run(&mut gm, &mut drive, 30, 1);
    assert_eq!(gm.machine_state, State::Centering as u8);
    gm.ls_crosshead_overtravel = true;
    run(&mut gm, &mut drive, 40, 1);
    assert_eq!(gm.machine_state, State::Fault as u8);
    assert_eq!(
        gm.fault_text.as_str(),
        "guard door opened or crosshead overtravel during a test"
    );
}

#[test]
fn the_machine_declares_its_five_alarms() {
    let paths = plc_core::alarm::alarm_paths(Gm::VARIABLES, Gm::ALARMS);
    let texts: Vec<_> = Gm::ALARMS.iter().map(|a| a.text).collect();
    assert_eq!(
        paths,
        [
            "guard_door_open",
            "ls_crosshead_overtravel",
            "crosshead_error_code",
            "force_kn",
            "centering_timed_out"
        ]
    );
    assert_eq!(
        texts,
        [
            "Guard door open",
            "Crosshead overtravel",
            "Crosshead drive fault",
            "Force above the machine's rating",
            "Specimen not centred in time"
        ]
    );
}

#[test]
fn the_longest_simulated_specimen_breaks_below_the_force_warning() {
    let (mut gm, mut drive) = testing();
    // The model sees the break within its 5 ms step and the program a cycle later: at the
    // fastest test speed, 0.1 mm is more than the crosshead pulls past the break in that time.
    let longest = plant::BREAK_MM.iter().copied().fold(0.0, f64::max) + 0.1;
    for _ in 0..1_000 {
        if gm.elongation_mm >= longest {
            break;
        }
        run(&mut gm, &mut drive, 0, 1);
    }
    assert!(gm.elongation_mm >= longest, "{} mm", gm.elongation_mm);
    let high = Gm::ALARMS
        .iter()
        .find_map(|a| match a.condition.kind {
            plc_core::alarm::AlarmKind::Limit(l) if a.text.starts_with("Force") => l.high,
            _ => None,
        })
        .expect("the force alarm's warning limit");
    assert!(
        gm.max_force_kn < high - 0.5,
        "{} kN at {} mm: a normal test would raise the force alarm",
        gm.max_force_kn,
        gm.elongation_mm
    );
}
