//! Distributed clocks with real ethercrab 0.7: local clocks that drift up to ±100 ppm apart,
//! brought together by ethercrab's static drift compensation and its cyclic FRMW through
//! each device's time control loop (system time difference 0x092C below 100 ns), and SYNC0
//! configured through ethercrab's group API firing at its cycle on the synchronised clocks.

#[macro_use]
mod common;

use common::timeouts;
use ethercat_sim::{Device, SimBus, datagram_frame as frame, inproc};
use ethercrab::error::Error;
use ethercrab::subdevice_group::DcConfiguration;
use ethercrab::{Command, DcSync, MainDevice, MainDeviceConfig, PduLoop, RegisterAddress};
use futures_lite::future::block_on;
use std::time::{Duration, Instant};

/// Static drift compensation frames: ethercrab's default is 10 000 (an ET1100's loop needs
/// thousands); the simulated loop settles in about a hundred, 2 000 leave ample margin.
const STATIC_SYNC: u32 = 2_000;

/// The difference every clock must end below (Beckhoff specifies < 100 ns for its
/// terminals).
const LIMIT_NS: i64 = 100;

fn maindevice(pdu_loop: PduLoop<'static>) -> MainDevice<'static> {
    MainDevice::new(
        pdu_loop,
        timeouts(),
        MainDeviceConfig {
            dc_static_sync_iterations: STATIC_SYNC,
            ..MainDeviceConfig::default()
        },
    )
}

/// The system time difference register 0x092C of the device at station `address`, as a
/// MainDevice reads it: sign and magnitude, bit 31 set when the local copy is behind.
/// `None` for a device without a system-time unit (working counter 0).
fn difference(md: &MainDevice<'_>, address: u16) -> Option<i64> {
    let read = Command::fprd(address, RegisterAddress::DcSystemTimeDifference.into());
    match block_on(read.receive::<u32>(md)) {
        Ok(raw) if raw & 0x8000_0000 != 0 => Some(-((raw & 0x7FFF_FFFF) as i64)),
        Ok(raw) => Some(raw as i64),
        Err(Error::WorkingCounter { received: 0, .. }) => None,
        Err(e) => panic!("reading 0x092C of {address:#06x}: {e:?}"),
    }
}

/// Every device's 0x092C (None where there is no system-time unit).
fn differences(md: &MainDevice<'_>, devices: usize) -> Vec<Option<i64>> {
    (0..devices as u16)
        .map(|i| difference(md, 0x1000 + i))
        .collect()
}

/// The largest distance of any device's system time from the reference's (position 0) at
/// the bus's last frame.
fn spread(bus: &SimBus) -> i64 {
    let times = bus.system_times();
    let reference = times[0].expect("the EK1100 is the reference clock");
    times
        .iter()
        .flatten()
        .map(|t| (t.wrapping_sub(reference) as i64).abs())
        .max()
        .unwrap_or(0)
}

#[test]
fn static_drift_compensation_brings_clocks_200_ppm_apart_within_100_ns() {
    let (tx, rx, pdu_loop) = storage!();
    let bus = SimBus::with_clock_seed(
        vec![
            Device::ek1100(),
            Device::el1004(),
            Device::el2004(),
            Device::el2889(),
            Device::el2004(),
        ],
        1,
    );
    // The worst crystals: the reference 100 ppm slow, the others up to 100 ppm fast.
    let drifts = [-100_000, 30_000, 100_000, 60_000, -20_000];
    for (pos, drift) in drifts.into_iter().enumerate() {
        bus.set_clock_drift(pos, drift);
    }
    let _driver = inproc::spawn(tx, rx, bus.clone()).unwrap();
    let md = maindevice(pdu_loop);
    let started = Instant::now();
    let group = block_on(md.init_single_group::<8, 64>(ethercrab::std::ethercat_now)).unwrap();
    let diffs = differences(&md, 5);
    println!(
        "init with {STATIC_SYNC} static sync frames took {:?}; 0x092C: {diffs:?}; spread {} ns",
        started.elapsed(),
        spread(&bus)
    );

    // The EL1004 has no system-time unit; the reference never receives a system time.
    assert_eq!(diffs[1], None);
    assert_eq!(diffs[0], Some(0));
    for (pos, diff) in diffs.iter().enumerate() {
        let diff = diff.unwrap_or(0);
        assert!(diff.abs() < LIMIT_NS, "device {pos}: 0x092C {diff} ns");
    }
    assert!(
        spread(&bus) < LIMIT_NS,
        "system times {:?}",
        bus.system_times()
    );

    // The loop measured the drift against the reference: the EL2004 at position 2 runs
    // 200 ppm fast, so its speed counter diff (0x0932, units of 0.25 ppm) is about -800.
    let speed: u16 = block_on(Command::fprd(0x1002, 0x0932).receive(&md)).unwrap();
    assert!(
        (-840..=-760).contains(&(speed as i16)),
        "speed counter diff {}",
        speed as i16
    );
    drop(group);
}

#[test]
fn sync0_configured_through_ethercrab_fires_every_cycle_on_the_synchronised_clocks() {
    let (tx, rx, pdu_loop) = storage!();
    let bus = SimBus::with_clock_seed(
        vec![
            Device::ek1100(),
            Device::el1004(),
            Device::el2004(),
            Device::el2889(),
        ],
        2024,
    );
    let drifts: Vec<i64> = (0..4).map(|i| bus.device(i).dc_drift_ppb()).collect();
    println!("seeded drifts (ppb): {drifts:?}");
    let _driver = inproc::spawn(tx, rx, bus.clone()).unwrap();
    let md = maindevice(pdu_loop);
    let mut group = block_on(md.init_single_group::<8, 64>(ethercrab::std::ethercat_now)).unwrap();
    for mut sd in group.iter_mut(&md) {
        if matches!(sd.name(), "EL2004" | "EL2889") {
            sd.set_dc_sync(DcSync::Sync0);
        }
    }
    let cycle = Duration::from_millis(1);
    let group = block_on(group.into_pre_op_pdi(&md)).unwrap();
    let group = block_on(group.configure_dc_sync(
        &md,
        DcConfiguration {
            start_delay: Duration::from_millis(20),
            sync0_period: cycle,
            sync0_shift: cycle / 4,
        },
    ))
    .unwrap();
    let group = block_on(group.into_op(&md)).unwrap();
    assert_eq!(
        bus.sync0(2).pulses,
        0,
        "SYNC0 starts 20 ms after configuration"
    );

    // The process data cycle, timed on the DC system time as ethercrab's example does.
    for _ in 0..300 {
        let now = Instant::now();
        let response = block_on(group.tx_rx_dc(&md)).unwrap();
        assert_eq!(response.working_counter, 5);
        std::thread::sleep(
            (now + response.extra.next_cycle_wait).saturating_duration_since(Instant::now()),
        );
    }

    let diffs = differences(&md, 4);
    let times = bus.system_times();
    let cycle_ns = cycle.as_nanos() as u64;
    println!(
        "0x092C after 300 cycles: {diffs:?}; spread {} ns; SYNC0 {:?} {:?}",
        spread(&bus),
        bus.sync0(2),
        bus.sync0(3)
    );
    for (pos, diff) in diffs.iter().enumerate() {
        let diff = diff.unwrap_or(0);
        assert!(diff.abs() < LIMIT_NS, "device {pos}: 0x092C {diff} ns");
    }
    assert!(spread(&bus) < LIMIT_NS, "system times {times:?}");

    for pos in [2, 3] {
        let s = bus.sync0(pos);
        let now = times[pos].unwrap();
        let last = s.last_pulse.expect("SYNC0 fired");
        // Pulses on whole cycles of system time (ethercrab rounds the start to one), one per
        // cycle from the first: none lost, none extra.
        assert!(s.active);
        assert_eq!(last % cycle_ns, 0, "device {pos}: last pulse {last}");
        assert_eq!(s.next_pulse, Some(last + cycle_ns));
        assert!(
            last <= now && now < last + cycle_ns,
            "device {pos}: {s:?} at {now}"
        );
        let first = last - (s.pulses - 1) * cycle_ns;
        assert!(s.pulses > 200, "device {pos}: only {} pulses", s.pulses);
        // The first pulse came at the configured start: after the configuration, within
        // the start delay rounded to the cycle.
        assert_eq!(s.pulses, (now - first) / cycle_ns + 1);
    }
    let (a, b) = (bus.sync0(2), bus.sync0(3));
    assert_eq!(
        a.last_pulse.unwrap() - (a.pulses - 1) * cycle_ns,
        b.last_pulse.unwrap() - (b.pulses - 1) * cycle_ns,
        "both started on the same system time"
    );
    assert!(a.pulses.abs_diff(b.pulses) <= 1, "{a:?} {b:?}");
    // Devices ethercrab did not configure for SYNC0 never fire.
    assert_eq!((bus.sync0(0).pulses, bus.sync0(1).pulses), (0, 0));

    // As a MainDevice sees it: SYNC0 status latched (acknowledge mode: only the device's
    // own PDI clears it), first pulse no longer pending.
    let status: u8 = block_on(Command::fprd(0x1002, 0x098E).receive(&md)).unwrap();
    let activation: u8 = block_on(Command::fprd(0x1002, 0x0984).receive(&md)).unwrap();
    assert_eq!((status, activation & 1), (1, 0));
}

#[test]
fn sync0_with_a_start_time_in_the_past_never_fires() {
    let (tx, rx, pdu_loop) = storage!();
    let bus = SimBus::new(vec![Device::ek1100(), Device::el2004()]);
    let _driver = inproc::spawn(tx, rx, bus.clone()).unwrap();
    let md = maindevice(pdu_loop);
    let _group = block_on(md.init_single_group::<4, 16>(ethercrab::std::ethercat_now)).unwrap();
    let write = |register: u16, value: u64, len: usize| {
        let bytes = value.to_le_bytes();
        block_on(Command::fpwr(0x1001, register).send(&md, &bytes[..len])).unwrap();
    };
    let now: u64 = block_on(Command::fprd(0x1001, 0x0910).receive(&md)).unwrap();
    // What a MainDevice that forgot the start delay does: SYNC0 from a moment ago.
    write(0x0981, 0, 1);
    write(0x0990, now - 1_000_000, 8);
    write(0x09A0, 500_000, 4);
    write(0x0981, 0x03, 1);
    for _ in 0..20 {
        block_on(Command::fprd(0x1001, 0x0130).receive::<u16>(&md)).unwrap();
        std::thread::sleep(Duration::from_micros(500));
    }
    assert_eq!(bus.sync0(1).pulses, 0);
    assert_eq!(bus.sync0(1).next_pulse, None);
    let activation: u8 = block_on(Command::fprd(0x1001, 0x0984).receive(&md)).unwrap();
    assert_eq!(
        activation, 0b101,
        "first pulse pending, start out of the near future"
    );

    // Started again 20 ms ahead (time enough for the writes on a busy machine), it fires.
    let now: u64 = block_on(Command::fprd(0x1001, 0x0910).receive(&md)).unwrap();
    write(0x0981, 0, 1);
    write(0x0990, now + 20_000_000, 8);
    write(0x0981, 0x03, 1);
    let deadline = Instant::now() + Duration::from_secs(2);
    while bus.sync0(1).pulses < 3 && Instant::now() < deadline {
        block_on(Command::fprd(0x1001, 0x0130).receive::<u16>(&md)).unwrap();
        std::thread::sleep(Duration::from_micros(500));
    }
    let s = bus.sync0(1);
    assert!(s.pulses >= 3, "{s:?}");
    assert_eq!(
        s.last_pulse.unwrap() % 500_000,
        (now + 20_000_000) % 500_000
    );
}

/// The data of a reply's only datagram.
fn data(reply: &[u8], len: usize) -> &[u8] {
    &reply[26..26 + len]
}

/// Runs a MainDevice's DC set-up by hand at fixed bus times (every 50 µs): station
/// addresses, latch, offsets from the processing-unit receive times, delays of one hop per
/// device, 400 FRMWs of the reference's system time. Returns 0x092C of each device after
/// every FRMW.
fn scripted_setup(bus: &SimBus) -> Vec<Vec<u32>> {
    let mut t = 1_000_000u64;
    let mut send = |f: Vec<u8>| {
        t += 50_000;
        bus.process_frame_at(&f, t).expect("valid frame")
    };
    let n = bus.len() as u16;
    for i in 0..n {
        send(frame(
            0x02,
            0u16.wrapping_sub(i),
            0x0010,
            &(0x1000 + i).to_le_bytes(),
        ));
    }
    send(frame(0x08, 0, 0x0930, &0x1000u16.to_le_bytes())); // reset the loops
    send(frame(0x08, 0, 0x0934, &[0]));
    send(frame(0x08, 0, 0x0900, &[0; 4])); // latch
    let received: Vec<u64> = (0..n)
        .map(|i| {
            let r = send(frame(0x04, 0x1000 + i, 0x0918, &[0; 8]));
            u64::from_le_bytes(data(&r, 8).try_into().unwrap())
        })
        .collect();
    let epoch = 0x0700_0000_0000_0000u64;
    for i in 0..n {
        let offset = epoch.wrapping_sub(received[i as usize]);
        send(frame(0x05, 0x1000 + i, 0x0920, &offset.to_le_bytes()));
        let delay = i as u32 * ethercat_sim::HOP_NS as u32;
        send(frame(0x05, 0x1000 + i, 0x0928, &delay.to_le_bytes()));
    }
    (0..400)
        .map(|_| {
            send(frame(0x0E, 0x1000, 0x0910, &[0; 8]));
            (0..n)
                .map(|i| {
                    let r = send(frame(0x04, 0x1000 + i, 0x092C, &[0; 4]));
                    u32::from_le_bytes(data(&r, 4).try_into().unwrap())
                })
                .collect()
        })
        .collect()
}

fn line() -> Vec<Device> {
    vec![Device::ek1100(), Device::el2889(), Device::el2004()]
}

#[test]
fn the_same_seed_and_frame_times_give_the_same_clocks_and_the_loop_converges() {
    let first = scripted_setup(&SimBus::with_clock_seed(line(), 99));
    let again = scripted_setup(&SimBus::with_clock_seed(line(), 99));
    let other = scripted_setup(&SimBus::with_clock_seed(line(), 100));
    assert_eq!(first, again, "deterministic");
    assert_ne!(first, other, "the seed matters");
    let magnitude = |raw: u32| (raw & 0x7FFF_FFFF) as i64;
    for run in [&first, &other] {
        // The first FRMW finds the hop delays and the drift since the latch ...
        assert!(run[0].iter().any(|&d| magnitude(d) > 100), "{:?}", run[0]);
        // ... the last ones find the clocks together.
        for sample in &run[300..] {
            assert!(
                sample.iter().all(|&d| magnitude(d) < LIMIT_NS),
                "{sample:?}"
            );
        }
    }
}

#[test]
fn any_value_written_to_the_dc_registers_is_taken_without_a_panic() {
    let bus = SimBus::new(line());
    let mut state = 0x1234_5678_9ABC_DEF0u64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    };
    for _ in 0..5_000 {
        let r = next();
        let ado = 0x0900 + (r % 0x100) as u16;
        let len = 1 + (r >> 8) as usize % 16;
        let bytes: Vec<u8> = (0..len).map(|_| next() as u8).collect();
        // Bus times from anywhere, backwards included.
        let t = match r >> 60 {
            0 => u64::MAX - (r >> 20),
            1 => 0,
            _ => next() >> (r >> 58),
        };
        let cmd = [0x08, 0x05, 0x0E, 0x07, 0x04][(r >> 32) as usize % 5];
        let f = frame(cmd, 0x1000 + (r >> 40) as u16 % 3, ado, &bytes);
        assert!(bus.process_frame_at(&f, t).is_some());
    }
    let _ = (bus.sync0(1), bus.system_times());
    bus.set_clock_drift(2, i64::MAX);
    assert_eq!(bus.device(2).dc_drift_ppb(), 10_000_000);
}
