//! The blocks against a small CiA 402 drive: its state machine as IEC 61800-7-201 draws it, a
//! position that follows the target one cycle late, and a following error window.

use super::*;

/// A drive as the tests need one.
struct Drive {
    state: DriveState,
    position: i32,
    last_target: i32,
    last_controlword: u16,
    error_code: u16,
    /// The following error window, in increments.
    window: i32,
}

impl Drive {
    fn new() -> Drive {
        Drive {
            state: DriveState::SwitchOnDisabled,
            position: 5_000,
            last_target: 5_000,
            last_controlword: 0,
            error_code: 0,
            window: 1_000_000,
        }
    }

    /// One bus cycle: takes the axis's outputs, answers its inputs.
    fn exchange(&mut self, d: &mut Cia402) {
        use DriveState::*;
        let cw = d.controlword;
        let reset_edge = cw & 0x80 != 0 && self.last_controlword & 0x80 == 0;
        self.last_controlword = cw;
        self.state = match self.state {
            Fault if reset_edge => {
                self.error_code = 0;
                SwitchOnDisabled
            }
            Fault => Fault,
            _ if cw & 0x02 == 0 => SwitchOnDisabled,
            SwitchOnDisabled if cw & 0x87 == 0x06 => ReadyToSwitchOn,
            ReadyToSwitchOn if cw & 0x8F == 0x07 => SwitchedOn,
            SwitchedOn | OperationEnabled if cw & 0x8F == 0x0F => OperationEnabled,
            OperationEnabled if cw & 0x8F == 0x07 => SwitchedOn,
            s => s,
        };
        let fe = d.target_position.wrapping_sub(self.position);
        if self.state == OperationEnabled {
            if fe.abs() > self.window {
                self.state = Fault;
                self.error_code = 0x8611; // following error
            } else {
                self.position = self.last_target;
                self.last_target = d.target_position;
            }
        } else {
            self.last_target = self.position;
        }
        d.statusword = self.state.statusword_bits();
        d.position_actual_value = self.position;
        d.following_error_actual_value = fe;
        d.error_code = self.error_code;
        d.modes_of_operation_display = d.modes_of_operation;
    }
}

/// A program with one axis and its blocks, cycled at 1 ms.
struct Machine {
    drive: Drive,
    axis: Axis,
    power: McPower,
    home: McHome,
    to: McMoveAbsolute,
    by: McMoveRelative,
    run: McMoveVelocity,
    stop: McStop,
    reset: McReset,
}

const DT: f64 = 0.001;

impl Machine {
    fn new() -> Machine {
        Machine {
            drive: Drive::new(),
            axis: Axis::default(),
            power: McPower::default(),
            home: McHome::default(),
            to: McMoveAbsolute::default(),
            by: McMoveRelative::default(),
            run: McMoveVelocity::default(),
            stop: McStop::default(),
            reset: McReset::default(),
        }
    }

    /// One cycle: the bus, then `program` calls blocks, then the axis advances.
    fn cycle(&mut self, program: impl FnOnce(&mut Machine)) {
        self.drive.exchange(&mut self.axis.drive);
        self.axis.read_drive();
        program(self);
        self.axis.cycle(DT);
    }

    /// Cycles until `until` holds (at most `most` cycles); how many it took.
    fn until(
        &mut self,
        most: usize,
        mut program: impl FnMut(&mut Machine),
        mut until: impl FnMut(&Machine) -> bool,
    ) -> usize {
        for n in 1..=most {
            self.cycle(&mut program);
            if until(self) {
                return n;
            }
        }
        panic!("not within {most} cycles: {:?}", self.axis);
    }

    fn powered() -> Machine {
        let mut m = Machine::new();
        let n = m.until(
            20,
            |m| {
                m.power.call(&mut m.axis, true);
            },
            |m| m.power.Status,
        );
        assert!(n <= 5, "powered in {n} cycles");
        m
    }
}

#[test]
fn power_takes_the_drive_from_switch_on_disabled_to_operation_enabled_and_back() {
    let mut m = Machine::new();
    let mut states = vec![m.drive.state];
    m.until(
        20,
        |m| {
            m.power.call(&mut m.axis, true);
        },
        |m| {
            states.push(m.drive.state);
            m.power.Status
        },
    );
    states.dedup();
    use DriveState::*;
    assert_eq!(
        states,
        [
            SwitchOnDisabled,
            ReadyToSwitchOn,
            SwitchedOn,
            OperationEnabled
        ]
    );
    assert_eq!(m.axis.state(), AxisState::Standstill);
    // Enabled where it stood: the first target is the drive's own position.
    assert_eq!(m.axis.drive.target_position, 5_000);
    assert_eq!(m.axis.actual_position, 5.0);
    m.until(
        5,
        |m| {
            m.power.call(&mut m.axis, false);
        },
        |m| m.drive.state == SwitchOnDisabled,
    );
    m.cycle(|m| {
        m.power.call(&mut m.axis, false);
    });
    assert!(!m.power.Status);
    assert_eq!(m.axis.state(), AxisState::Disabled);
}

#[test]
fn homing_on_the_current_position_then_an_absolute_move_within_its_limits() {
    let mut m = Machine::powered();
    m.cycle(|m| {
        m.home.call(&mut m.axis, true, 0.0);
    });
    assert!(m.home.Done && m.axis.homed);
    assert_eq!(m.axis.actual_position, 0.0);
    let (v, a, d) = (50.0, 400.0, 200.0);
    let mut last = (m.axis.set_position, m.axis.set_velocity);
    let mut most_speed: f64 = 0.0;
    let cycles = m.until(
        5_000,
        |m| {
            m.to.call(&mut m.axis, true, 30.0, v, a, d);
        },
        |m| m.to.Done,
    );
    // Checked cycle by cycle over a second run of the same move back.
    assert!(m.axis.state() == AxisState::Standstill && m.to.Done && !m.to.Busy);
    assert!((m.axis.set_position - 30.0).abs() < 1e-12);
    m.cycle(|m| {
        m.to.call(&mut m.axis, false, 30.0, v, a, d);
    });
    assert!(!m.to.Done, "Done is reset on Execute's falling edge");
    for _ in 0..5_000 {
        m.cycle(|m| {
            m.to.call(&mut m.axis, true, 0.0, v, a, d);
        });
        let (p, s) = (m.axis.set_position, m.axis.set_velocity);
        let accel = (s - last.1) / DT;
        assert!(
            accel.abs() <= a.max(d) * (1.0 + 1e-9),
            "acceleration {accel}"
        );
        assert!(s.abs() <= v * (1.0 + 1e-9), "speed {s}");
        assert!((-1e-9..=30.0 + 1e-9).contains(&p), "position {p}");
        most_speed = most_speed.max(s.abs());
        last = (p, s);
        if m.to.Done {
            break;
        }
    }
    assert!(m.to.Done, "{:?}", m.axis);
    assert_eq!(most_speed, v, "the long move cruised at its velocity");
    // 30 mm at 50 mm/s with 0.125 s up and 0.25 s down: about 0.79 s.
    assert!((700..900).contains(&cycles), "{cycles} cycles");
    // The drive followed: it stands where it was told to.
    m.cycle(|_| {});
    assert!(
        m.axis.actual_position.abs() < 1e-9,
        "{}",
        m.axis.actual_position
    );
}

#[test]
fn a_new_move_aborts_the_running_one_which_reports_command_aborted() {
    let mut m = Machine::powered();
    for _ in 0..100 {
        m.cycle(|m| {
            m.to.call(&mut m.axis, true, 100.0, 50.0, 500.0, 500.0);
        });
    }
    assert!(m.to.Busy && m.axis.set_velocity > 0.0);
    m.cycle(|m| {
        m.to.call(&mut m.axis, true, 100.0, 50.0, 500.0, 500.0);
        m.by.call(&mut m.axis, true, -1.0, 20.0, 500.0, 500.0);
    });
    m.cycle(|m| {
        m.to.call(&mut m.axis, true, 100.0, 50.0, 500.0, 500.0);
        m.by.call(&mut m.axis, true, -1.0, 20.0, 500.0, 500.0);
    });
    assert!(m.to.CommandAborted && !m.to.Busy && !m.to.Done);
    assert!(m.by.Busy);
    let start = m.axis.target;
    m.until(
        3_000,
        |m| {
            m.by.call(&mut m.axis, true, -1.0, 20.0, 500.0, 500.0);
        },
        |m| m.by.Done,
    );
    assert_eq!(m.axis.set_position, start);
}

#[test]
fn a_following_error_faults_the_drive_stops_the_axis_and_a_reset_recovers_it() {
    let mut m = Machine::powered();
    m.drive.window = 20; // increments: 20 µm at the default scale
    m.until(
        2_000,
        |m| {
            m.run.call(&mut m.axis, true, 100.0, 5_000.0, 5_000.0, 1.0);
        },
        |m| m.axis.state() == AxisState::ErrorStop,
    );
    assert_eq!(m.axis.error_id, error::DRIVE_FAULT);
    m.cycle(|m| {
        m.power.call(&mut m.axis, true);
        m.run.call(&mut m.axis, true, 100.0, 5_000.0, 5_000.0, 1.0);
    });
    assert!(m.power.Error && m.power.ErrorID == 0x8611, "{:?}", m.power);
    assert!(
        m.run.Error && m.run.ErrorID == error::DRIVE_FAULT,
        "{:?}",
        m.run
    );
    // Moves are refused until a reset.
    m.cycle(|m| {
        m.to.call(&mut m.axis, true, 0.0, 10.0, 100.0, 100.0);
    });
    assert_eq!((m.to.Error, m.to.ErrorID), (true, error::ERROR_STOP));
    m.drive.window = 1_000_000;
    m.until(
        20,
        |m| {
            m.power.call(&mut m.axis, true);
            m.reset.call(&mut m.axis, true);
        },
        |m| m.reset.Done,
    );
    m.until(
        20,
        |m| {
            m.power.call(&mut m.axis, true);
        },
        |m| m.power.Status,
    );
    assert_eq!(m.axis.state(), AxisState::Standstill);
    assert_eq!(m.axis.error_id, 0);
}

#[test]
fn a_stop_brings_the_axis_to_rest_and_holds_it_until_released() {
    let mut m = Machine::powered();
    m.until(
        1_000,
        |m| {
            m.run.call(&mut m.axis, true, 40.0, 400.0, 400.0, -1.0);
        },
        |m| m.run.InVelocity,
    );
    assert_eq!(m.axis.set_velocity, -40.0);
    m.until(
        1_000,
        |m| {
            m.run.call(&mut m.axis, true, 40.0, 400.0, 400.0, -1.0);
            m.stop.call(&mut m.axis, true, 800.0);
        },
        |m| m.stop.Done,
    );
    assert!(m.run.CommandAborted);
    assert_eq!(m.axis.set_velocity, 0.0);
    assert_eq!(m.axis.state(), AxisState::Stopping);
    m.cycle(|m| {
        m.stop.call(&mut m.axis, true, 800.0);
        m.to.call(&mut m.axis, true, 0.0, 10.0, 100.0, 100.0);
    });
    assert_eq!((m.to.Error, m.to.ErrorID), (true, error::STOPPING));
    m.cycle(|m| {
        m.stop.call(&mut m.axis, false, 800.0);
    });
    assert_eq!(m.axis.state(), AxisState::Standstill);
}

#[test]
fn a_stop_goes_straight_to_stopping_a_second_stop_takes_over_and_done_ends_busy() {
    let mut m = Machine::powered();
    // From Standstill: Stopping at once, never through another state.
    m.cycle(|m| {
        m.stop.call(&mut m.axis, true, 800.0);
    });
    assert_eq!(m.axis.state(), AxisState::Stopping);
    m.cycle(|m| {
        m.stop.call(&mut m.axis, true, 800.0);
    });
    // Done ends Busy (PLCopen: Busy while not finished); the axis stays held.
    assert!(
        m.stop.Done && !m.stop.Busy && !m.stop.Active,
        "{:?}",
        m.stop
    );
    assert_eq!(m.axis.state(), AxisState::Stopping);
    // A second stop while Stopping takes the axis over.
    let mut second = McStop::default();
    m.cycle(|m| {
        m.stop.call(&mut m.axis, true, 800.0);
        second.call(&mut m.axis, true, 400.0);
    });
    assert!(second.Busy || second.Done, "{second:?}");
    assert!(!second.Error, "{second:?}");
    assert_eq!(m.axis.state(), AxisState::Stopping);
    // The first one's release no longer frees the axis: the second holds it.
    m.cycle(|m| {
        m.stop.call(&mut m.axis, false, 800.0);
        second.call(&mut m.axis, true, 400.0);
    });
    assert_eq!(m.axis.state(), AxisState::Stopping);
    m.cycle(|m| {
        second.call(&mut m.axis, false, 400.0);
    });
    assert_eq!(m.axis.state(), AxisState::Standstill);
    assert!(!second.Done, "Done is reset on Execute's falling edge");
}

#[test]
fn power_is_not_valid_while_it_reports_an_error() {
    let mut m = Machine::powered();
    assert!(m.power.Valid && !m.power.Error);
    m.drive.window = 20;
    m.until(
        2_000,
        |m| {
            m.power.call(&mut m.axis, true);
            m.run.call(&mut m.axis, true, 100.0, 5_000.0, 5_000.0, 1.0);
        },
        |m| m.power.Error,
    );
    assert!(!m.power.Valid, "Error and Valid never both: {:?}", m.power);
    let mut read = McReadActualPosition::default();
    read.call(&m.axis, true);
    assert!(read.Error && !read.Valid && read.ErrorID == error::DRIVE_FAULT);
    read.call(&m.axis, false);
    assert!(!read.Error && !read.Valid && !read.Busy);
}

#[test]
fn moves_with_bad_limits_or_of_an_unpowered_axis_are_refused() {
    let mut m = Machine::new();
    m.cycle(|m| {
        m.to.call(&mut m.axis, true, 1.0, 10.0, 100.0, 100.0);
    });
    assert_eq!((m.to.Error, m.to.ErrorID), (true, error::NOT_POWERED));
    let mut m = Machine::powered();
    for (v, a, d) in [(0.0, 1.0, 1.0), (1.0, f64::NAN, 1.0), (1.0, 1.0, -2.0)] {
        m.cycle(|m| {
            m.to.call(&mut m.axis, false, 1.0, v, a, d);
        });
        m.cycle(|m| {
            m.to.call(&mut m.axis, true, 1.0, v, a, d);
        });
        assert_eq!((m.to.Error, m.to.ErrorID), (true, error::INVALID_PARAMETER));
    }
    assert_eq!(m.axis.state(), AxisState::Standstill);
}

#[test]
fn the_blocks_and_the_axis_are_structures_of_the_image() {
    use crate::PlcType;
    let names: Vec<&str> = McPower::MEMBERS.iter().map(|m| m.name).collect();
    assert_eq!(names, ["Enable", "Status", "Valid", "Error", "ErrorID"]);
    assert_eq!(McMoveAbsolute::TYPE_NAME, Some("MC_MoveAbsolute"));
    assert_eq!(Axis::TYPE_NAME, Some("AXIS_REF"));
    assert_eq!(Axis::default().scale, 1000.0);
}
