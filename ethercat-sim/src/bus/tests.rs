//! Tests of the bus: reply frames, addressing modes, working counters and injected faults.

use super::*;
use crate::al;
use crate::datagram_frame as frame;

/// (data, wkc, adp) of the reply's datagram.
fn answer(reply: &[u8], len: usize) -> (Vec<u8>, u16, u16) {
    let wkc = u16::from_le_bytes([reply[26 + len], reply[27 + len]]);
    let adp = u16::from_le_bytes([reply[18], reply[19]]);
    (reply[26..26 + len].to_vec(), wkc, adp)
}

#[test]
fn replies_come_from_12_10_10_10_10_10_padded_to_60_bytes() {
    let bus = SimBus::new(vec![Device::ek1100(), Device::el2004()]);
    let reply = bus.process_frame(&frame(0x07, 0, 0, &[0])).unwrap();
    assert_eq!(reply[6..12], REPLY_SOURCE);
    assert_eq!(reply.len(), 60);
    assert_eq!(answer(&reply, 1), (vec![0x13], 2, 2)); // BRD: OR of types, one per device
}

#[test]
fn the_station_alias_addresses_a_device_once_dl_control_enables_it() {
    let mut ek1100 = Device::ek1100();
    ek1100.eeprom_words_mut()[4] = 0x0ABC;
    ek1100.write(0x0502, &[0x00, 0x04], 0); // reload: 0x0012 = word 4
    let bus = SimBus::new(vec![ek1100, Device::el2004()]);
    let fprd = frame(0x04, 0x0ABC, 0x0012, &[0, 0]);
    assert_eq!(
        answer(&bus.process_frame(&fprd).unwrap(), 2).1,
        0,
        "alias not enabled"
    );
    bus.process_frame(&frame(0x02, 0, 0x0103, &[0x01])).unwrap(); // APWR DL control byte 3
    let (data, wkc, _) = answer(&bus.process_frame(&fprd).unwrap(), 2);
    assert_eq!((data, wkc), (vec![0xBC, 0x0A], 1));
}

#[test]
fn a_device_that_stops_answering_takes_the_ring_behind_it_away_for_every_addressing_mode() {
    let bus = SimBus::new(vec![Device::ek1100(), Device::el2004(), Device::el2889()]);
    for i in 0..3u16 {
        let apwr = frame(
            0x02,
            0u16.wrapping_sub(i),
            0x0010,
            &(0x1000 + i).to_le_bytes(),
        );
        bus.process_frame(&apwr).unwrap();
    }
    bus.set_responding(1, false);
    // APRD of position 1 (the silent device) and position 2 (behind it): nobody answers,
    // in particular the EL2889 does not answer as position 1; only the EK1100 increments.
    for (adp, pos) in [(0xFFFF, 1), (0xFFFE, 2)] {
        let reply = bus
            .process_frame(&frame(0x01, adp, 0x0010, &[0, 0]))
            .unwrap();
        assert_eq!(
            answer(&reply, 2),
            (vec![0, 0], 0, adp.wrapping_add(1)),
            "APRD {pos}"
        );
    }
    let fprd = |station: u16| {
        answer(
            &bus.process_frame(&frame(0x04, station, 0x0010, &[0, 0]))
                .unwrap(),
            2,
        )
    };
    assert_eq!(fprd(0x1000), (vec![0x00, 0x10], 1, 0x1000));
    assert_eq!(fprd(0x1001).1, 0, "FPRD of the silent device");
    assert_eq!(fprd(0x1002).1, 0, "FPRD of the device behind it");
    let brd = bus.process_frame(&frame(0x07, 0, 0x0000, &[0])).unwrap();
    assert_eq!(
        answer(&brd, 1),
        (vec![0x11], 1, 1),
        "BRD counts the EK1100 only"
    );
    // The EK1100 sees the lost link on its port 1 (DL status bit 5 clear, loop closed).
    assert_eq!(fprd_u16(&bus, 0x1000, 0x0110) & 0x0020, 0);
    bus.set_responding(1, true);
    assert_eq!(fprd(0x1002).1, 1);
    assert_eq!(fprd_u16(&bus, 0x1000, 0x0110), 0x5A31);
}

fn fprd_u16(bus: &SimBus, station: u16, ado: u16) -> u16 {
    let (data, _, _) = answer(
        &bus.process_frame(&frame(0x04, station, ado, &[0, 0]))
            .unwrap(),
        2,
    );
    u16::from_le_bytes([data[0], data[1]])
}

#[test]
fn a_power_cycled_device_is_back_in_init_with_its_eeprom_but_no_address() {
    let mut el2004 = Device::el2004();
    el2004.eeprom_words_mut()[4] = 0x0042; // alias, reloaded at power-on
    let bus = SimBus::new(vec![Device::ek1100(), el2004]);
    bus.process_frame(&frame(0x02, 0xFFFF, 0x0010, &[0x01, 0x10]))
        .unwrap();
    bus.process_frame(&frame(
        0x05,
        0x1001,
        0x0800,
        &[0x00, 0x0F, 1, 0, 0x44, 0, 1, 0],
    ))
    .unwrap();
    bus.process_frame(&frame(0x05, 0x1001, 0x0120, &[0x08, 0]))
        .unwrap();
    bus.set_inputs(1, &[0]);
    assert_eq!(bus.al_state(1), al::OP);
    bus.power_cycle(1);
    let d = bus.device(1);
    assert_eq!((d.al_status(), d.station_address()), (0x0001, 0));
    let mut sm0 = [0xFFu8; 8];
    d.register(0x0800, &mut sm0);
    assert_eq!(sm0, [0; 8]);
    assert_eq!(d.sii()[4], 0x0042);
    let mut alias = [0u8; 2];
    d.register(0x0012, &mut alias);
    assert_eq!(alias, [0x42, 0]);
    assert_eq!(fprd_u16(&bus, 0x1001, 0x0130), 0, "the old address is gone");
}

#[test]
fn a_tripped_watchdog_holds_safe_op_with_code_0x001b_until_acknowledged() {
    let bus = SimBus::new(vec![Device::el2004()]);
    bus.process_frame(&frame(0x02, 0, 0x0010, &[0x00, 0x10]))
        .unwrap();
    bus.process_frame(&frame(0x05, 0x1000, 0x0120, &[0x08, 0]))
        .unwrap();
    bus.trip_watchdog(0);
    assert_eq!(
        (bus.device(0).al_status(), bus.al_status_code(0)),
        (0x0014, 0x001B)
    );
    bus.process_frame(&frame(0x05, 0x1000, 0x0120, &[0x08, 0]))
        .unwrap();
    assert_eq!(
        bus.device(0).al_status(),
        0x0014,
        "OP without acknowledge is ignored"
    );
    bus.process_frame(&frame(0x05, 0x1000, 0x0120, &[0x14, 0]))
        .unwrap();
    bus.process_frame(&frame(0x05, 0x1000, 0x0120, &[0x08, 0]))
        .unwrap();
    assert_eq!(
        (bus.device(0).al_status(), bus.al_status_code(0)),
        (0x0008, 0)
    );
}

#[test]
fn auto_increment_addresses_count_up_through_the_ring() {
    let bus = SimBus::new(vec![Device::ek1100(), Device::el2004(), Device::el2889()]);
    let reply = bus
        .process_frame(&frame(0x02, 0xFFFF, 0x0010, &[0x01, 0x10]))
        .unwrap();
    let (_, wkc, adp) = answer(&reply, 2);
    assert_eq!((wkc, adp), (1, 2)); // position -1 + 3 devices
    assert_eq!(bus.device(1).station_address(), 0x1001);
}
