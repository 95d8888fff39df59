//! Group `drives`: a servo axis and distributed clocks on the simulated bus, through
//! `plc_io::ethercat` and real ethercrab (the in-process transport).
//!
//! - `dc_time_difference_max_ns`: the largest system time difference (register 0x092C) the
//!   backend reports over the run, after SYNC0 started (the first 200 cycles, SYNC0's start
//!   delay and more, are left out), with `dc` on the EL2004 and the AKD (seeded drifts up to
//!   100 ppm). Target < 100.
//! - `axis_following_error_max_mm`: a `plc_core::motion` axis on the simulated AKD moving at
//!   [`TEST_SPEED_MM_S`] (`MC_MoveVelocity`), the largest following error the drive reports
//!   (0x60F4) once at speed, in mm.
//! - `bus_with_drive_us_per_cycle` / `bus_without_drive_us_per_cycle`: the backend's exchange
//!   of the tensile tester's terminals (EK1100, EL1004, EL2889, EL2004) with the AKD after
//!   them and without, alternating blocks of 1,000 cycles at 1 ms; the median of each side's
//!   per-cycle medians.

use ethercat_sim::{Device, SimBus};
use plc_core::motion::{Axis, McMoveVelocity, McPower};
use plc_core::{GlobalMemory, Time};
use plc_io::ethercat::devices as descriptions;
use plc_io::ethercat::{BusConfig, DcConfig, EtherCatBackend, Options, PdoDirection, Transport};
use std::fmt::Write;
use std::time::{Duration, Instant};

/// The crosshead's test speed the following error is measured at.
pub const TEST_SPEED_MM_S: f64 = 10.0;
/// The AKD's 2^20 increments per revolution, one revolution per 10 mm.
const SCALE: f64 = 1_048_576.0 / 10.0;
const PERIOD: Duration = Duration::from_millis(1);

/// The axis program's variables: the AKD's entries, the axis and two blocks.
#[derive(GlobalMemory, Debug, Clone)]
pub struct Drive {
    #[plc(link = "ethercat.servo.controlword", direction = "output")]
    controlword: u16,
    #[plc(link = "ethercat.servo.modes_of_operation", direction = "output")]
    mode: i8,
    #[plc(link = "ethercat.servo.target_position", direction = "output")]
    target_position: i32,
    #[plc(link = "ethercat.servo.statusword", direction = "input")]
    statusword: u16,
    #[plc(link = "ethercat.servo.position_actual_value", direction = "input")]
    position: i32,
    #[plc(
        link = "ethercat.servo.following_error_actual_value",
        direction = "input"
    )]
    following_error: i32,
    #[plc(link = "ethercat.servo.error_code", direction = "input")]
    error_code: u16,
    axis: Axis,
    power: McPower,
    run: McMoveVelocity,
}

/// The tensile tester's terminals as a description (`examples/bus/tensile_tester.toml`'s
/// devices, named as there), with the AKD (`servo`) after them if `drive`.
fn description(drive: bool) -> BusConfig {
    let word = plc_core::IecType::Uint;
    let mut devices = vec![
        descriptions::ek1100("coupler"),
        descriptions::el1004("di").grouped(PdoDirection::Input, "digital_inputs", word),
        descriptions::el2889("dq").grouped(PdoDirection::Output, "digital_outputs", word),
        descriptions::el2004("lamps"),
    ];
    if drive {
        devices.push(descriptions::akd("servo"));
    }
    BusConfig { devices }
}

fn devices(drive: bool) -> Vec<Device> {
    let mut d = vec![
        Device::ek1100(),
        Device::el1004(),
        Device::el2889(),
        Device::el2004(),
    ];
    if drive {
        d.push(Device::akd());
    }
    d
}

fn backend<T: GlobalMemory + Clone + Send + 'static>(
    bus: &SimBus,
    config: BusConfig,
) -> Result<EtherCatBackend<T>, String> {
    let sim = bus.clone();
    let transport =
        Transport::custom(move |tx, rx| Ok(Box::new(ethercat_sim::inproc::spawn(tx, rx, sim)?)));
    let mut b = EtherCatBackend::<T>::new(config, transport, Options::simulated())
        .map_err(|e| e.to_string())?;
    b.start().map_err(|e| e.to_string())?;
    Ok(b)
}

/// Sleeps until `began + PERIOD * (i + 1)`.
fn pace(began: Instant, i: u32) {
    std::thread::sleep((began + PERIOD * (i + 1)).saturating_duration_since(Instant::now()));
}

/// Runs the group; its `name: value` lines.
pub fn run(quick: bool) -> Result<String, String> {
    let mut out = String::new();
    let seconds = if quick { 2 } else { 10 };
    let _ = writeln!(
        out,
        "drives_setup: in-process simulated bus, 1 ms cycles, {seconds} s each figure"
    );
    let dc = dc_difference(seconds)?;
    let _ = writeln!(out, "dc_time_difference_max_ns: {dc}");
    let fe = following_error(seconds)?;
    let _ = writeln!(out, "axis_following_error_max_mm: {fe:.4}");
    let _ = writeln!(out, "axis_test_speed_mm_s: {TEST_SPEED_MM_S}");
    let (with, without) = exchange_cost(if quick { 3 } else { 9 })?;
    let _ = writeln!(out, "bus_with_drive_us_per_cycle: {with:.1}");
    let _ = writeln!(out, "bus_without_drive_us_per_cycle: {without:.1}");
    Ok(out)
}

/// The largest 0x092C difference reported after SYNC0 started.
fn dc_difference(seconds: u32) -> Result<u32, String> {
    let mut config = description(true);
    let dc = DcConfig {
        sync0: Time::from_millis(1),
        shift: Time::from_micros(250),
    };
    for name in ["lamps", "servo"] {
        if let Some(d) = config.devices.iter_mut().find(|d| d.name == name) {
            d.dc = Some(dc);
        }
    }
    let bus = SimBus::new(devices(true));
    let mut b = backend::<Drive>(&bus, config)?;
    let mut gm = Drive::default();
    let mut most = 0;
    let began = Instant::now();
    for i in 0..seconds * 1000 {
        let status = b.exchange(&mut gm);
        if i >= 200 {
            let reading = status.dc.and_then(|d| d.max_time_difference_ns);
            most = most.max(reading.ok_or("the backend reported no clock difference")?);
        }
        pace(began, i);
    }
    b.stop();
    Ok(most)
}

/// The largest following error at the test speed, in mm.
fn following_error(seconds: u32) -> Result<f64, String> {
    let bus = SimBus::new(devices(true));
    let mut b = backend::<Drive>(&bus, description(true))?;
    let mut gm = Drive::default();
    gm.axis.scale = SCALE;
    let mut most: f64 = 0.0;
    let began = Instant::now();
    for i in 0..seconds * 1000 {
        b.exchange(&mut gm);
        let d = &mut gm.axis.drive;
        d.statusword = gm.statusword;
        d.position_actual_value = gm.position;
        d.following_error_actual_value = gm.following_error;
        d.error_code = gm.error_code;
        gm.axis.read_drive();
        let on = gm.power.call(&mut gm.axis, true);
        let at_speed = gm
            .run
            .call(&mut gm.axis, on, TEST_SPEED_MM_S, 100.0, 100.0, 1.0);
        gm.axis.cycle(PERIOD.as_secs_f64());
        gm.controlword = gm.axis.drive.controlword;
        gm.mode = gm.axis.drive.modes_of_operation;
        gm.target_position = gm.axis.drive.target_position;
        if at_speed {
            most = most.max(f64::from(gm.following_error).abs() / SCALE);
        }
        if gm.axis.drive.faulted() {
            return Err(format!("the drive faulted: {:#06x}", gm.error_code));
        }
        pace(began, i);
    }
    b.stop();
    if !gm.run.InVelocity {
        return Err("the axis never reached the test speed".into());
    }
    Ok(most)
}

/// The tensile tester's terminals alone: one linked output.
#[derive(GlobalMemory, Debug, Clone)]
pub struct Terminals {
    #[plc(link = "ethercat.lamps.output1", direction = "output")]
    green: bool,
}

/// The median of per-cycle exchange times over blocks of 1,000 cycles at 1 ms, with the drive
/// (its program linked and its axis powered) and without, alternating; in µs.
fn exchange_cost(blocks: usize) -> Result<(f64, f64), String> {
    let (mut with, mut without) = (Vec::new(), Vec::new());
    for _ in 0..blocks {
        let bus = SimBus::new(devices(true));
        let mut b = backend::<Drive>(&bus, description(true))?;
        let mut gm = Drive::default();
        with.push(block(|| {
            b.exchange(&mut gm);
            gm.axis.drive.statusword = gm.statusword;
            gm.axis.read_drive();
            gm.power.call(&mut gm.axis, true);
            gm.axis.cycle(PERIOD.as_secs_f64());
            gm.controlword = gm.axis.drive.controlword;
        }));
        b.stop();
        let bus = SimBus::new(devices(false));
        let mut b = backend::<Terminals>(&bus, description(false))?;
        let mut gm = Terminals { green: true };
        without.push(block(|| {
            b.exchange(&mut gm);
        }));
        b.stop();
    }
    Ok((median(with), median(without)))
}

/// The median time of `cycle` over 1,000 cycles paced at 1 ms, in µs.
fn block(mut cycle: impl FnMut()) -> f64 {
    let mut times = Vec::with_capacity(1000);
    let began = Instant::now();
    for i in 0..1000 {
        let t = Instant::now();
        cycle();
        times.push(t.elapsed().as_secs_f64() * 1e6);
        pace(began, i);
    }
    median(times)
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v.get(v.len() / 2).copied().unwrap_or(f64::NAN)
}
