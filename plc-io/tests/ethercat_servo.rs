//! A servo axis of `plc_core::motion` driving the simulated Kollmorgen AKD through real
//! ethercrab: the drive's entries linked at the top level and copied into the axis each
//! cycle, as docs/motion.md shows.

#[path = "common/servo.rs"]
mod servo;
#[path = "common/sim_bench.rs"]
mod sim_bench;

use ethercat_sim::{Device, SimBus, datagram_frame};
use plc_core::Time;
use plc_core::motion::{AxisState, error};
use plc_io::ethercat::{BusConfig, DcConfig, DeviceConfig, EtherCatBackend, StartupSdo, devices};
use servo::Machine;
use std::time::{Duration, Instant};

/// The AKD alone, named `servo`, with start-up SDOs.
fn description(startup: Vec<StartupSdo>) -> BusConfig {
    BusConfig {
        devices: vec![DeviceConfig {
            startup,
            ..devices::akd("servo")
        }],
    }
}

/// The program and its bus, cycled at 1 ms.
struct Running {
    bus: SimBus,
    backend: EtherCatBackend<Machine>,
    gm: Machine,
    last: Instant,
}

impl Running {
    fn start(startup: Vec<StartupSdo>) -> Running {
        Running::on(description(startup))
    }

    fn on(config: BusConfig) -> Running {
        let bus = SimBus::new(vec![Device::akd()]);
        let mut backend = sim_bench::backend::<Machine>(&bus, config);
        backend.start().unwrap();
        let gm = Machine::new();
        Running {
            bus,
            backend,
            gm,
            last: Instant::now(),
        }
    }

    /// One cycle: exchange, the drive's inputs into the axis, `program`, the axis's outputs
    /// out. The period the profile runs at is the time since the previous cycle.
    fn cycle(&mut self, program: impl FnOnce(&mut Machine)) {
        let status = self.backend.exchange(&mut self.gm);
        assert!(status.inputs_valid, "{status:?}");
        self.gm.cycle(program);
        // About 1 ms a cycle (the drive integrates the bus's real time).
        let next = self.last + Duration::from_millis(1);
        if let Some(wait) = next.checked_duration_since(Instant::now()) {
            std::thread::sleep(wait);
        }
        self.last = Instant::now();
    }

    fn until(
        &mut self,
        most: usize,
        mut program: impl FnMut(&mut Machine),
        mut done: impl FnMut(&Machine) -> bool,
    ) {
        for _ in 0..most {
            self.cycle(&mut program);
            if done(&self.gm) {
                return;
            }
        }
        panic!("not within {most} cycles: {:?}", self.gm.axis);
    }

    fn powered(&mut self) {
        self.until(
            500,
            |gm| {
                gm.power.call(&mut gm.axis, true);
            },
            |gm| gm.power.Status && gm.axis.state() == AxisState::Standstill,
        );
    }
}

#[test]
fn an_axis_powers_homes_and_moves_the_simulated_drive_to_its_target() {
    let mut m = Running::start(Vec::new());
    m.powered();
    m.cycle(|gm| {
        gm.power.call(&mut gm.axis, true);
        gm.home.call(&mut gm.axis, true, 0.0);
    });
    assert!(m.gm.home.Done && m.gm.axis.homed);
    // 20 mm at 20 mm/s (2 revolutions per second), 200 mm/s² both ways.
    let mut most_lag: f64 = 0.0;
    // The profile's limits, cycle by cycle: the set point's velocity, and its change from
    // one cycle to the next (at the profile's 1 ms step), within what the move asked.
    let (mut most_speed, mut most_accel, mut last_velocity) = (0.0f64, 0.0f64, 0.0);
    m.until(
        5_000,
        |gm| {
            gm.power.call(&mut gm.axis, true);
            gm.move_to
                .call(&mut gm.axis, true, 20.0, 20.0, 200.0, 200.0);
        },
        |gm| {
            most_lag = most_lag.max((gm.axis.set_position - gm.axis.actual_position).abs());
            let v = gm.axis.set_velocity;
            most_speed = most_speed.max(v.abs());
            most_accel = most_accel.max(((v - last_velocity) / 0.001).abs());
            last_velocity = v;
            gm.move_to.Done
        },
    );
    // It cruised at the speed asked, never faster.
    assert!(
        (19.9..=20.0 + 1e-9).contains(&most_speed),
        "set velocity reached {most_speed} mm/s"
    );
    assert!(
        (150.0..=200.0 * (1.0 + 1e-6)).contains(&most_accel),
        "set acceleration reached {most_accel} mm/s²"
    );
    // The set point is there at once; the drive within a few cycles.
    m.until(
        200,
        |gm| {
            gm.power.call(&mut gm.axis, true);
        },
        |gm| (gm.axis.actual_position - 20.0).abs() < 0.001,
    );
    assert_eq!(m.gm.axis.state(), AxisState::Standstill);
    assert!(
        most_lag < 1.0,
        "the drive lagged the set point by {most_lag} mm"
    );
    // Off again: the drive goes to switch on disabled.
    m.until(
        100,
        |gm| {
            gm.power.call(&mut gm.axis, false);
        },
        |gm| gm.statusword & 0x4F == 0x40,
    );
    m.backend.stop();
}

#[test]
fn a_stop_aborts_a_move_and_the_axis_rests_where_it_stopped() {
    let mut m = Running::start(Vec::new());
    m.powered();
    for _ in 0..200 {
        m.cycle(|gm| {
            gm.power.call(&mut gm.axis, true);
            gm.move_to
                .call(&mut gm.axis, true, 50.0, 30.0, 300.0, 300.0);
        });
    }
    m.until(
        2_000,
        |gm| {
            gm.power.call(&mut gm.axis, true);
            gm.move_to
                .call(&mut gm.axis, true, 50.0, 30.0, 300.0, 300.0);
            gm.stop.call(&mut gm.axis, true, 600.0);
        },
        |gm| gm.stop.Done,
    );
    assert!(m.gm.move_to.CommandAborted);
    let rest = m.gm.axis.set_position;
    assert!(rest > 0.5 && rest < 50.0, "stopped at {rest} mm");
    m.until(
        200,
        |gm| {
            gm.power.call(&mut gm.axis, true);
            gm.stop.call(&mut gm.axis, true, 600.0);
        },
        |gm| (gm.axis.actual_position - rest).abs() < 0.001,
    );
    m.backend.stop();
}

#[test]
fn a_following_error_faults_the_drive_and_mc_reset_recovers_the_axis() {
    // A window of 1,000 increments (0.01 mm), set by a start-up SDO.
    let window = StartupSdo {
        index: 0x6065,
        subindex: 0,
        value: 1_000,
        bits: 32,
    };
    let mut m = Running::start(vec![window]);
    m.powered();
    // A fast move lags more than that: the drive faults, the axis stops on the error.
    m.until(
        2_000,
        |gm| {
            gm.power.call(&mut gm.axis, true);
            gm.move_to
                .call(&mut gm.axis, true, 100.0, 200.0, 20_000.0, 20_000.0);
        },
        |gm| gm.axis.state() == AxisState::ErrorStop,
    );
    m.cycle(|gm| {
        gm.power.call(&mut gm.axis, true);
        gm.move_to
            .call(&mut gm.axis, true, 100.0, 200.0, 20_000.0, 20_000.0);
    });
    assert_eq!(m.gm.axis.error_id, error::DRIVE_FAULT);
    assert!(m.gm.move_to.Error && m.gm.move_to.ErrorID == error::DRIVE_FAULT);
    assert_eq!((m.gm.power.Error, m.gm.power.ErrorID), (true, 0x8611));
    m.until(
        500,
        |gm| {
            gm.power.call(&mut gm.axis, true);
            gm.reset.call(&mut gm.axis, true);
        },
        |gm| gm.reset.Done,
    );
    m.powered();
    assert_eq!(m.gm.axis.error_id, 0);
    assert_eq!(m.gm.error_code, 0);
    m.backend.stop();
}

#[test]
fn a_drive_that_loses_sync0_faults_and_the_axis_stops_on_its_error() {
    let mut config = description(Vec::new());
    config.devices[0].dc = Some(DcConfig {
        sync0: Time::from_millis(1),
        shift: Time::ZERO,
    });
    let mut m = Running::on(config);
    m.powered();
    let hold = |gm: &mut Machine| {
        gm.power.call(&mut gm.axis, true);
    };
    // Enabled in cyclic synchronous position, SYNC0 pulsing.
    m.until(200, hold, |gm| gm.mode_display == 8);
    // SYNC0 starts 100 ms after the bus was configured.
    for _ in 0..500 {
        m.cycle(hold);
        if m.bus.sync0(0).pulses >= 50 {
            break;
        }
    }
    let running = m.bus.sync0(0);
    assert!(
        running.active && running.pulses >= 50,
        "SYNC0 {running:?}; system times {:?}",
        m.bus.system_times()
    );
    // SYNC0 stops: another MainDevice on the wire switches the drive's SYNC unit off
    // (0x0981 = 0), as a second master or a tool writing registers would.
    let mut address = [0u8; 2];
    m.bus.device(0).register(0x0010, &mut address);
    let reply = m.bus.process_frame(&datagram_frame(
        0x05,
        u16::from_le_bytes(address),
        0x0981,
        &[0],
    ));
    // The working counter, after the headers (14 + 2 + 10 bytes) and the one data byte.
    assert_eq!(reply.map(|r| r[27]), Some(1), "the write reached the drive");
    assert!(!m.bus.sync0(0).active);
    // The drive faults with 0x8700 and stops; the axis goes to ErrorStop with its code.
    m.until(200, hold, |gm| gm.axis.state() == AxisState::ErrorStop);
    m.cycle(hold);
    assert_eq!(m.gm.error_code, 0x8700);
    assert_eq!((m.gm.power.Error, m.gm.power.ErrorID), (true, 0x8700));
    assert_eq!(
        m.gm.statusword & 0x4F,
        0x08,
        "fault: {:#06x}",
        m.gm.statusword
    );
    m.backend.stop();
}
