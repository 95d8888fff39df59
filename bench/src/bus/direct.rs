//! The loop a user writes directly on ethercrab instead of using the framework: a MainDevice
//! on its own frame storage, the frames moved by ethercrab's `tx_rx_task` on a thread (or by
//! the in-process simulator), one group brought to OP, then each cycle the outputs written
//! into the process data by hand, `group.tx_rx`, the working counter checked, the inputs read
//! by hand, the same tensile-tester tick, and `std::thread::sleep` to the next deadline, the
//! way the Runtime schedules (a late cycle is followed at once, no catch-up burst). It runs
//! on the calling thread: the caller pins it and sets its scheduling, and the frame thread it
//! starts inherits both, as the Runtime's does.

use async_io::block_on;
use ethercat_sim::SimBus;
use ethercrab::std::{ethercat_now, tx_rx_task};
use ethercrab::{MainDevice, MainDeviceConfig, PduStorage, Timeouts};
#[cfg(doc)]
use examples::tensile::process_tick;
use examples::tensile::{Gm, TickInfo, position};
use plc_core::Time;
use plc_io::probe::CycleTimes;
use std::time::{Duration, Instant};

/// The same sizes as plc-io's backend, so both send the same frames.
const MAX_SUBDEVICES: usize = plc_io::ethercat::MAX_SUBDEVICES;
const MAX_PDI: usize = plc_io::ethercat::MAX_PDI;
const MAX_FRAMES: usize = 16;
const MAX_PDU_DATA: usize = PduStorage::element_size(1100);

/// Cycles in a row without a good answer after which a block gives up: the bus (or the
/// frame thread) stopped, and every further exchange would wait for its timeout.
pub const GIVE_UP: usize = 20;

/// The working counter of a good exchange: the EL1004's inputs read (1), the EL2889's and
/// the EL2004's outputs written (2 each), the AKD's inputs read and outputs written (3).
const EXPECTED_WKC: u16 = 8;

/// How the frames reach the simulated bus.
pub enum Wire {
    /// A raw socket on this interface (in the calling thread's network namespace).
    Interface(&'static str),
    /// ethercat-sim's in-process driver.
    InProcess(SimBus),
}

/// Runs `warmup + cycles` cycles at `period` with the program `tick` (the tensile tester's
/// [`process_tick`] in the benchmark); the timestamps of the last `cycles`, and how many of
/// them had a bad working counter or no answer.
pub fn run(
    wire: Wire,
    timeouts: Timeouts,
    period: Duration,
    warmup: usize,
    cycles: usize,
    tick: impl FnMut(&mut Gm, TickInfo),
) -> Result<(Vec<CycleTimes>, usize), String> {
    // ethercrab wants the storage `'static`; a benchmark run leaks one per block (about 20 KiB).
    let storage: &'static PduStorage<MAX_FRAMES, MAX_PDU_DATA> =
        Box::leak(Box::new(PduStorage::new()));
    let (tx, rx, pdu_loop) = storage
        .try_split()
        .map_err(|()| "ethercrab's frame storage split twice".to_string())?;
    let driver = match wire {
        Wire::Interface(name) => {
            let task =
                tx_rx_task(name, tx, rx).map_err(|e| format!("raw socket on {name}: {e}"))?;
            Driver::Thread(
                std::thread::Builder::new()
                    .name("direct-tx-rx".into())
                    .spawn(move || block_on(task).map(|_| ()))
                    .map_err(|e| format!("starting the frame thread: {e}"))?,
            )
        }
        Wire::InProcess(bus) => Driver::InProcess(
            ethercat_sim::inproc::spawn(tx, rx, bus)
                .map_err(|e| format!("starting the in-process simulator: {e}"))?,
        ),
    };
    let md = MainDevice::new(
        pdu_loop,
        timeouts,
        MainDeviceConfig {
            dc_static_sync_iterations: 100,
            ..MainDeviceConfig::default()
        },
    );
    let mut result = cycle_in_op(&md, period, warmup, cycles, tick);
    // SAFETY: every group made with `md` is gone (`cycle_in_op` owns and drops it) and every
    // ethercrab call was awaited to its end, so no frame is in flight; this tells the frame
    // thread to exit.
    let _ = unsafe { md.release_all() };
    match driver {
        Driver::Thread(t) => {
            let ended = match t.join() {
                Ok(Ok(())) => return result,
                Ok(Err(e)) => format!("ethercrab's tx_rx_task ended with: {e}"),
                Err(_) => "ethercrab's tx_rx_task panicked".into(),
            };
            result = Err(match result {
                Ok(_) => ended,
                Err(e) => format!("{e}; {ended}"),
            });
        }
        Driver::InProcess(d) => d.stop(),
    }
    result
}

/// What moves the frames, stopped after the MainDevice released them.
enum Driver {
    Thread(std::thread::JoinHandle<Result<(), ethercrab::error::Error>>),
    InProcess(ethercat_sim::inproc::Driver),
}

fn cycle_in_op(
    md: &MainDevice<'static>,
    period: Duration,
    warmup: usize,
    cycles: usize,
    mut tick: impl FnMut(&mut Gm, TickInfo),
) -> Result<(Vec<CycleTimes>, usize), String> {
    let crab = |what: &'static str| move |e: ethercrab::error::Error| format!("{what}: {e}");
    let group = block_on(md.init_single_group::<MAX_SUBDEVICES, MAX_PDI>(ethercat_now))
        .map_err(crab("scanning the bus"))?;
    let group = block_on(group.into_op(md)).map_err(crab("going to OP"))?;
    let inputs = group
        .subdevice(md, position::INPUTS)
        .map_err(crab("EL1004"))?;
    let outputs = group
        .subdevice(md, position::OUTPUTS)
        .map_err(crab("EL2889"))?;
    let lamps = group
        .subdevice(md, position::LAMPS)
        .map_err(crab("EL2004"))?;
    let crosshead = group
        .subdevice(md, position::CROSSHEAD)
        .map_err(crab("AKD"))?;

    let mut gm = Gm::default();
    let mut times = Vec::with_capacity(cycles);
    let (mut bad, mut in_a_row) = (0, 0);
    let epoch = Instant::now();
    let mut next = Instant::now();
    for k in 0..warmup + cycles {
        let start = Instant::now();
        // The outputs by hand: the four drive bits of the EL2889's word and the tower's lamps.
        let word = u16::from(gm.cr_lift_brake)
            | u16::from(gm.cr_centering_drive) << 1
            | u16::from(gm.cr_lift_up) << 2
            | u16::from(gm.cr_test_drive) << 3;
        outputs.outputs_raw_mut()[..2].copy_from_slice(&word.to_le_bytes());
        lamps.outputs_raw_mut()[0] = u8::from(gm.lamp_green)
            | u8::from(gm.lamp_yellow) << 1
            | u8::from(gm.lamp_red) << 2
            | u8::from(gm.horn) << 3;
        // The AKD's outputs (0x1600): controlword, mode, target position and velocity.
        let mut akd = crosshead.outputs_raw_mut();
        akd[0..2].copy_from_slice(&gm.crosshead_controlword.to_le_bytes());
        akd[2] = gm.crosshead_mode as u8;
        akd[3..7].copy_from_slice(&gm.crosshead_target_position.to_le_bytes());
        akd[7..11].copy_from_slice(&gm.crosshead_target_velocity.to_le_bytes());
        drop(akd);
        let bus_start = Instant::now();
        let answer = block_on(group.tx_rx(md));
        let bus_end = Instant::now();
        let valid = matches!(&answer, Ok(r) if r.working_counter == EXPECTED_WKC);
        // The inputs by hand, zero when the bus did not answer right (as the framework's
        // default does).
        let byte = if valid { inputs.inputs_raw()[0] } else { 0 };
        gm.ls_centering_neg = byte & 1 != 0;
        gm.ls_centering_pos = byte & 2 != 0;
        gm.ls_lift_neg = byte & 4 != 0;
        gm.specimen_broken = byte & 8 != 0;
        // The AKD's inputs (0x1A00): statusword, mode, position, velocity, following error,
        // error code.
        let mut akd = [0u8; 17];
        if valid {
            akd.copy_from_slice(&crosshead.inputs_raw()[..17]);
        }
        let i32_at =
            |at: usize| i32::from_le_bytes([akd[at], akd[at + 1], akd[at + 2], akd[at + 3]]);
        gm.crosshead_statusword = u16::from_le_bytes([akd[0], akd[1]]);
        gm.crosshead_mode_display = akd[2] as i8;
        gm.crosshead_position = i32_at(3);
        gm.crosshead_velocity = i32_at(7);
        gm.crosshead_following_error = i32_at(11);
        gm.crosshead_error_code = u16::from_le_bytes([akd[15], akd[16]]);
        let tick_start = Instant::now();
        tick(
            &mut gm,
            TickInfo {
                period,
                inputs_valid: valid,
                now: Time::try_from(start - epoch).unwrap_or(Time::MAX),
            },
        );
        let tick_end = Instant::now();
        let end = Instant::now();
        in_a_row = if valid { 0 } else { in_a_row + 1 };
        if in_a_row == GIVE_UP {
            return Err(format!(
                "the direct loop: the bus stopped answering ({GIVE_UP} cycles in a row without \
                 the right working counter, the last {})",
                match answer {
                    Ok(r) => format!("working counter {}", r.working_counter),
                    Err(e) => e.to_string(),
                }
            ));
        }
        if k >= warmup {
            bad += usize::from(!valid);
            times.push(CycleTimes {
                start,
                bus_start,
                bus_end,
                tick_start,
                tick_end,
                end,
            });
        }
        next += period;
        let now = Instant::now();
        if next > now {
            std::thread::sleep(next - now);
        } else {
            next = now;
        }
    }
    // Back to INIT, as the framework's stop does, so the next block finds the bus as it left it.
    let group = block_on(group.into_safe_op(md)).map_err(crab("going to SAFE-OP"))?;
    let group = block_on(group.into_pre_op(md)).map_err(crab("going to PRE-OP"))?;
    block_on(group.into_init(md)).map_err(crab("going to INIT"))?;
    Ok((times, bad))
}
