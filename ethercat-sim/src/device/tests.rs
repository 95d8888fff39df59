//! Tests of one simulated device: models, EEPROM interface, AL state machine, registers
//! and FMMUs.

use super::process_data::Fmmu;
use super::*;

#[test]
fn every_listed_model_is_found_by_its_name() {
    for name in Device::MODELS {
        assert_eq!(
            Device::model(name).map(|d| d.name().to_owned()).as_deref(),
            Some(name)
        );
    }
}

#[test]
fn models_have_the_real_names_and_identities() {
    let models = [
        (Device::ek1100(), "EK1100", 0x044C_2C52, 0x0012_0000),
        (Device::el1004(), "EL1004", 0x03EC_3052, 0x0013_0000),
        (Device::el2004(), "EL2004", 0x07D4_3052, 0x0010_0000),
        (Device::el2828(), "EL2828", 0x0B0C_3052, 0x0011_0000),
        (Device::el2889(), "EL2889", 0x0B49_3052, 0x0011_0000),
    ];
    for (d, name, product, revision) in models {
        assert_eq!(d.name(), name);
        assert_eq!(d.identity(), (2, product, revision), "{name}");
    }
}

#[test]
fn an_eeprom_read_goes_through_the_registers() {
    let mut d = Device::ek1100();
    d.write(0x0502, &[0x00, 0x01, 0x08, 0x00, 0x00, 0x00], 0);
    let mut status = [0u8; 2];
    d.read(0x0502, &mut status, 1);
    assert_eq!(status, [0x40, 0x81]); // [A] F106
    d.read(0x0502, &mut status, sii::READ_BUSY_NS);
    assert_eq!(status, [0x40, 0x00]);
    let mut out = [0u8; 8];
    d.read(0x0508, &mut out, sii::READ_BUSY_NS);
    assert_eq!(out, [0x02, 0, 0, 0, 0x52, 0x2c, 0x4c, 0x04]); // [A] F112
}

#[test]
fn al_status_follows_control_unless_refused() {
    let mut d = Device::el2004();
    d.write(0x0120, &[0x11, 0], 0);
    assert_eq!(d.al_status(), 0x0011);
    d.write(0x0120, &[0x02, 0], 0);
    assert_eq!(d.al_status(), 0x0002);
    d.faults
        .refuse(al::SAFE_OP, al::INVALID_OUTPUT_CONFIGURATION);
    d.write(0x0120, &[0x04, 0], 0);
    assert_eq!((d.al_status(), d.al_status_code()), (0x0012, 0x001D));
}

#[test]
fn the_alias_comes_from_eeprom_word_4_on_reload() {
    let mut d = Device::ek1100();
    assert_eq!(d.u16_at(reg::STATION_ALIAS), 0);
    d.eeprom.words[4] = 0xABCD;
    assert_eq!(
        d.u16_at(reg::STATION_ALIAS),
        0,
        "only loaded at power-up or reload"
    );
    d.write(0x0502, &[0x00, 0x04], 0);
    assert_eq!(d.u16_at(reg::STATION_ALIAS), 0xABCD);
}

#[test]
fn a_write_to_any_rx_error_counter_clears_them_all() {
    let mut d = Device::el2004();
    d.mem[reg::RX_ERROR_COUNTERS].copy_from_slice(&[1, 2, 3, 4, 5, 6, 7, 8]);
    d.write(0x0305, &[0x55], 0);
    let mut counters = [0xffu8; 8];
    d.read(0x0300, &mut counters, 0);
    assert_eq!(counters, [0; 8]);
}

#[test]
fn a_write_beside_the_rx_error_counters_keeps_them() {
    let mut d = Device::el2004();
    d.mem[reg::RX_ERROR_COUNTERS].copy_from_slice(&[1, 2, 3, 4, 5, 6, 7, 8]);
    d.write(0x0308, &[0], 0);
    d.write(0x02FE, &[0, 0], 0);
    assert_eq!(&d.mem[reg::RX_ERROR_COUNTERS], &[1, 2, 3, 4, 5, 6, 7, 8]);
}

#[test]
fn an_fmmu_reads_back_as_its_fields() {
    let mut d = Device::el2004();
    let mut fmmu = [0u8; 16];
    fmmu[0..4].copy_from_slice(&0x0001_0000u32.to_le_bytes());
    fmmu[4..6].copy_from_slice(&1u16.to_le_bytes());
    fmmu[8..10].copy_from_slice(&0x0f00u16.to_le_bytes());
    fmmu[11] = 2;
    fmmu[12] = 1;
    d.write(reg::FMMU0, &fmmu, 0);
    let expected = Fmmu {
        logical: 0x0001_0000,
        len: 1,
        physical: 0x0f00,
        reads: false,
        writes: true,
    };
    assert_eq!(d.fmmus(), [expected]);
}

/// Configures the EL3004's mailboxes as a MainDevice does (SM0 0x1000 128 bytes written by
/// the MainDevice, SM1 at 0x1080 of `in_len` bytes read by it), in PRE-OP.
fn el3004_with_mailboxes(in_len: u16) -> Device {
    let mut d = Device::el3004();
    let mut sm = |i: usize, start: u16, len: u16, control: u8| {
        let mut r = start.to_le_bytes().to_vec();
        r.extend_from_slice(&len.to_le_bytes());
        r.extend_from_slice(&[control, 0, 1, 0]);
        d.write(reg::SM0 + 8 * i, &r, 0);
    };
    sm(0, 0x1000, 128, 0x26);
    sm(1, 0x1080, in_len, 0x22);
    d
}

/// Writes an SDO information request (`opcode`, `data`) with mailbox counter 5.
fn info_request(d: &mut Device, opcode: u8, data: &[u8]) {
    let mut frame = vec![0u8; 128];
    frame[..2].copy_from_slice(&(6 + data.len() as u16).to_le_bytes());
    frame[5] = 0x53;
    frame[6..8].copy_from_slice(&0x8000u16.to_le_bytes());
    frame[8] = opcode;
    frame[12..12 + data.len()].copy_from_slice(data);
    d.write(0x1000, &frame, 0);
}

/// Reads the whole input mailbox if it is full.
fn take_reply(d: &mut Device, len: usize) -> Option<Vec<u8>> {
    let mut status = [0u8];
    d.read(reg::SM0 + 8 + 5, &mut status, 0);
    (status[0] & 0x08 != 0).then(|| {
        let mut out = vec![0u8; len];
        d.read(0x1080, &mut out, 0);
        out
    })
}

#[test]
fn an_sdo_information_answer_longer_than_the_mailbox_comes_in_fragments_one_per_read() {
    let mut d = el3004_with_mailboxes(16);
    info_request(&mut d, 0x01, &[1, 0]); // Get OD List, all objects
    let mut data = Vec::new();
    let mut lefts = Vec::new();
    while let Some(r) = take_reply(&mut d, 16) {
        let len = u16::from_le_bytes([r[0], r[1]]) as usize;
        assert!(len <= 10);
        assert_eq!(r[5], 0x53, "CoE, the request's counter");
        assert_eq!(r[8] & 0x7F, 0x02);
        let left = u16::from_le_bytes([r[10], r[11]]);
        assert_eq!(r[8] & 0x80 != 0, left > 0, "incomplete until the last");
        lefts.push(left);
        data.extend_from_slice(&r[12..6 + len]);
        assert!(lefts.len() < 100);
    }
    assert!(lefts.len() > 3);
    assert!(lefts.windows(2).all(|w| w[1] + 1 == w[0]) && lefts.last() == Some(&0));
    assert_eq!(data[..2], [1, 0], "the list type, then the indexes");
    let indexes: Vec<u16> = data[2..]
        .chunks(2)
        .map(|c| u16::from_le_bytes([c[0], c[1]]))
        .collect();
    assert_eq!(indexes[..2], [0x1008, 0x1018]);
    assert!(indexes.contains(&0x6030));
    // A new request drops what was left of the old answer.
    info_request(&mut d, 0x01, &[1, 0]);
    take_reply(&mut d, 16).unwrap();
    info_request(&mut d, 0x03, &[0x00, 0x60]); // Get Object Description 0x6000
    let r = take_reply(&mut d, 16).unwrap();
    assert_eq!((r[8], &r[12..16]), (0x84, &[0x00, 0x60, 0, 0][..]));
}

#[test]
fn a_refusing_device_answers_sdo_information_with_an_info_error_and_uploads_as_before() {
    let mut d = el3004_with_mailboxes(128);
    d.set_sdo_info_fault(Some(crate::SdoInfoFault::Refused));
    info_request(&mut d, 0x05, &[0x00, 0x60, 0x11, 0]);
    let r = take_reply(&mut d, 128).unwrap();
    assert_eq!(
        (r[8], &r[12..16]),
        (0x07, &0x0504_0001u32.to_le_bytes()[..])
    );
    assert_eq!(take_reply(&mut d, 128), None);
}
