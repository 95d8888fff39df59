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
