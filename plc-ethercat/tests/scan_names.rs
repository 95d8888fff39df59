//! `plc_ethercat::scan::scan` on the simulated bus names the entries a CoE device's EEPROM
//! leaves unnamed from the device's object dictionary (the SDO information service, ETG.1000.6
//! §5.6.3), and keeps the `xIIII_SS` names when the device refuses the service or answers it
//! in a way that breaks the protocol.

use ethercat_sim::{Device, SdoInfoFault, SimBus};
use plc_ethercat::scan::{ScannedBus, scan};
use plc_ethercat::{Options, Transport};
use plc_rules::bus::{DeviceConfig, PdoDirection, devices};
use std::time::{Duration, Instant};

fn transport(bus: &SimBus) -> Transport {
    let bus = bus.clone();
    Transport::custom(move |tx, rx| Ok(Box::new(ethercat_sim::inproc::spawn(tx, rx, bus)?)))
}

fn scanned(models: Vec<Device>) -> ScannedBus {
    scan(transport(&SimBus::new(models)), &Options::simulated()).unwrap()
}

/// Each entry as (name, type, bits).
fn entries(d: &DeviceConfig) -> Vec<(&str, &str, u32)> {
    d.entries
        .iter()
        .map(|e| (e.name.as_str(), e.iec_type.as_str(), e.bits))
        .collect()
}

fn faulty(mut d: Device, fault: SdoInfoFault) -> Device {
    d.set_sdo_info_fault(Some(fault));
    d
}

#[test]
fn the_akd_scans_with_the_cia_402_names_and_types_of_its_ready_description() {
    let scan = scanned(vec![Device::ek1100(), Device::akd()]);
    let akd = &scan.bus.devices[1];
    assert_eq!(akd.entries, devices::akd("akd").entries);
    let got = entries(akd);
    assert_eq!(got[0], ("controlword", "UINT", 16));
    assert_eq!(got[1], ("modes_of_operation", "SINT", 8));
    assert_eq!(got[4], ("statusword", "UINT", 16));
    assert_eq!(got[6], ("position_actual_value", "DINT", 32));
    assert_eq!(got[8], ("following_error_actual_value", "DINT", 32));
    assert_eq!(got[9], ("error_code", "UINT", 16));
    // The scanned device keeps the dictionary's own names and data types.
    let e = &scan.devices[1].entries[1];
    assert_eq!(
        (e.name.as_deref(), e.data_type, e.index),
        (Some("Modes of operation"), Some(0x02), 0x6060)
    );
}

#[test]
fn the_el3004_values_are_named_value_and_typed_int() {
    let scan = scanned(vec![Device::ek1100(), Device::el3004(), Device::el1004()]);
    let ai = &scan.bus.devices[1];
    let values: Vec<_> = ai
        .entries
        .iter()
        .filter(|e| e.bits == 16)
        .map(|e| (e.name.as_str(), e.iec_type.as_str()))
        .collect();
    assert_eq!(
        values,
        [
            ("value_1", "INT"),
            ("value_2", "INT"),
            ("value_3", "INT"),
            ("value_4", "INT")
        ]
    );
    let first: Vec<_> = entries(ai).into_iter().take(10).collect();
    assert_eq!(
        first,
        [
            ("underrange_1", "BOOL", 1),
            ("overrange_1", "BOOL", 1),
            ("limit_1_1", "BYTE", 2),
            ("limit_2_1", "BYTE", 2),
            ("error_1", "BOOL", 1),
            ("gap_1", "BOOL", 1),
            ("gap_2", "BYTE", 6),
            ("txpdo_state_1", "BOOL", 1),
            ("txpdo_toggle_1", "BOOL", 1),
            ("value_1", "INT", 16),
        ]
    );
    let e = &scan.devices[1].entries[9];
    assert_eq!(
        (e.name.as_deref(), e.data_type, e.index, e.subindex),
        (Some("Value"), Some(0x03), 0x6000, 0x11)
    );
    // The EEPROM's names stay where the EEPROM has them.
    assert_eq!(scan.bus.devices[2].entries[3].name, "input_4");
    assert!(
        ai.entries
            .iter()
            .all(|e| e.direction == PdoDirection::Input)
    );
}

#[test]
fn a_device_that_refuses_the_service_keeps_object_index_names() {
    let scan = scanned(vec![
        Device::ek1100(),
        faulty(Device::el3004(), SdoInfoFault::Refused),
        Device::akd(),
    ]);
    let ai = entries(&scan.bus.devices[1]);
    assert_eq!(ai[0], ("x6000_01", "BOOL", 1));
    assert_eq!(ai[9], ("x6000_11", "WORD", 16));
    // The next device is asked all the same.
    assert_eq!(scan.bus.devices[2].entries, devices::akd("akd").entries);
    let drive = faulty(Device::akd(), SdoInfoFault::Refused);
    let scan = scanned(vec![Device::ek1100(), drive]);
    let got = entries(&scan.bus.devices[1]);
    // Its EEPROM names the objects of its fixed PDOs (controlword, target position ...), not
    // the modes or the error code.
    assert_eq!(got[0], ("controlword", "UINT", 16));
    assert_eq!(got[1], ("x6060_00", "BYTE", 8));
    assert_eq!(got[5], ("x6061_00", "BYTE", 8));
    assert_eq!(got[9], ("x603f_00", "WORD", 16));
    // The file says why, above the device's entries.
    let text = scan.to_toml();
    let at = text
        .find("# 3 entries have no name from its CoE object dictionary (the device answered")
        .expect(&text);
    assert!(text[at..].contains("named by object index"), "{text}");
    assert!(at > text.find("name = \"akd\"").expect(&text), "{text}");
    assert!(
        scan.devices[0].note.is_none(),
        "the coupler has nothing to say"
    );
}

#[test]
fn hostile_answers_cost_only_the_names_and_end_in_time() {
    for fault in [SdoInfoFault::Oversized, SdoInfoFault::EndlessFragments] {
        let start = Instant::now();
        let scan = scanned(vec![
            Device::ek1100(),
            faulty(Device::akd(), fault),
            Device::el3004(),
        ]);
        assert!(
            start.elapsed() < Duration::from_secs(20),
            "{fault:?}: {:?}",
            start.elapsed()
        );
        let got = entries(&scan.bus.devices[1]);
        // (The drive's EEPROM names the objects its fixed PDOs map, 0x6040 among them.)
        assert_eq!(got[0], ("controlword", "UINT", 16), "{fault:?}");
        assert_eq!(got[1], ("x6060_00", "BYTE", 8), "{fault:?}");
        assert_eq!(got[9], ("x603f_00", "WORD", 16), "{fault:?}");
        // The device behind it is named.
        assert_eq!(scan.bus.devices[2].entries[9].name, "value_1", "{fault:?}");
    }
}

#[test]
fn the_scanned_text_reads_back_with_the_dictionary_names() {
    let scan = scanned(vec![Device::ek1100(), Device::el3004(), Device::akd()]);
    let text = scan.to_toml();
    assert!(
        text.contains(
            r#"{ name = "value_1", direction = "input", bits = 16, type = "INT", sm = 3 }, # 0x6000:11"#
        ),
        "{text}"
    );
    assert!(
        text.contains(r#"{ name = "modes_of_operation", direction = "output", bits = 8, type = "SINT", sm = 2 }, # 0x6060:00"#),
        "{text}"
    );
    assert_eq!(
        plc_rules::bus::BusConfig::from_toml_str(&text).unwrap(),
        scan.bus
    );
}
