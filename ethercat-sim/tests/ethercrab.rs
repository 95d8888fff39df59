//! Real ethercrab 0.7 against the simulated terminals through the in-process transport: init
//! to OP, the real devices' names, identities and process data sizes, distributed clocks,
//! cyclic data both ways with the working counters real ESCs give, and the faults a test
//! bench needs.

#[macro_use]
mod common;

use common::{bench, maindevice, timeouts};
use ethercat_sim::{Device, SimBus, al, inproc};
use ethercrab::error::{Error, TimeoutError};
use ethercrab::{Command, DcSupport, SubDeviceState};
use futures_lite::future::block_on;
use std::time::Duration;

#[test]
fn ethercrab_brings_ek1100_el1004_el2004_el2889_to_op_and_exchanges_data() {
    let (tx, rx, pdu_loop) = storage!();
    let bus = bench();
    let driver = inproc::spawn(tx, rx, bus.clone()).unwrap();
    let md = maindevice(pdu_loop, timeouts());
    let group = block_on(md.init_single_group::<8, 64>(ethercrab::std::ethercat_now)).unwrap();
    let group = block_on(group.into_op(&md)).unwrap();
    let expected = [
        ("EK1100", 0x044C_2C52, 0x0012_0000, 0, 0),
        ("EL1004", 0x03EC_3052, 0x0013_0000, 1, 0),
        ("EL2004", 0x07D4_3052, 0x0010_0000, 0, 1),
        ("EL2889", 0x0B49_3052, 0x0011_0000, 0, 2),
    ];
    for (i, (name, product, revision, inputs, outputs)) in expected.into_iter().enumerate() {
        let sd = group.subdevice(&md, i).unwrap();
        assert_eq!(sd.name(), name);
        let id = sd.identity();
        assert_eq!(
            (id.vendor_id, id.product_id, id.revision),
            (2, product, revision)
        );
        assert_eq!(sd.configured_address(), 0x1000 + i as u16);
        assert_eq!(sd.inputs_raw().len(), inputs, "{name} input bytes");
        assert_eq!(sd.outputs_raw().len(), outputs, "{name} output bytes");
        assert_eq!(bus.al_state(i), al::OP);
    }

    bus.set_input_bit(1, 0, true);
    bus.set_input_bit(1, 3, true);
    group.subdevice(&md, 2).unwrap().outputs_raw_mut()[0] = 0b0101;
    group
        .subdevice(&md, 3)
        .unwrap()
        .outputs_raw_mut()
        .copy_from_slice(&[0x80, 0x01]);
    let response = block_on(group.tx_rx(&md)).unwrap();
    // EL1004: +1 (read FMMU); EL2004 and EL2889: +2 each (write FMMU); EK1100: nothing.
    assert_eq!(response.working_counter, 5);
    assert!(
        response
            .subdevice_states
            .iter()
            .all(|s| *s == SubDeviceState::Op)
    );
    assert_eq!(group.subdevice(&md, 1).unwrap().inputs_raw()[0], 0b1001);
    assert_eq!(bus.outputs(2), [0b0101]);
    assert_eq!(bus.outputs(3), [0x80, 0x01]);
    assert!(bus.output_bit(3, 7) && bus.output_bit(3, 8) && !bus.output_bit(3, 0));

    bus.set_input_bit(1, 0, false);
    assert_eq!(block_on(group.tx_rx(&md)).unwrap().working_counter, 5);
    assert_eq!(group.subdevice(&md, 1).unwrap().inputs_raw()[0], 0b1000);

    drop(group);
    // SAFETY: the group is gone and no frame is in flight.
    let _ = unsafe { md.release_all() };
    driver.stop();
}

#[test]
fn cycles_of_the_captured_terminals_give_the_captured_working_counters() {
    // The terminals of capture [A] in one group, as in ethercrab's [R4]: each output terminal
    // adds 2 to the LRW's working counter, the EK1100 nothing (EMULATOR-NOTES §9).
    let (tx, rx, pdu_loop) = storage!();
    let bus = SimBus::new(vec![Device::ek1100(), Device::el2828(), Device::el2889()]);
    let _driver = inproc::spawn(tx, rx, bus.clone()).unwrap();
    let md = maindevice(pdu_loop, timeouts());
    let group = block_on(md.init_single_group::<4, 16>(ethercrab::std::ethercat_now)).unwrap();
    let group = block_on(group.into_op(&md)).unwrap();
    for cycle in 0..8u8 {
        group.subdevice(&md, 1).unwrap().outputs_raw_mut()[0] = cycle;
        group
            .subdevice(&md, 2)
            .unwrap()
            .outputs_raw_mut()
            .copy_from_slice(&[1 << cycle, 0x80 >> cycle]);
        assert_eq!(block_on(group.tx_rx(&md)).unwrap().working_counter, 4);
        assert_eq!(bus.outputs(1), [cycle]);
        assert_eq!(bus.outputs(2), [1 << cycle, 0x80 >> cycle]);
    }
}

#[test]
fn distributed_clocks_are_found_and_delays_grow_along_the_line() {
    let (tx, rx, pdu_loop) = storage!();
    let bus = bench();
    let _driver = inproc::spawn(tx, rx, bus.clone()).unwrap();
    let md = maindevice(pdu_loop, timeouts());
    let group = block_on(md.init_single_group::<8, 64>(ethercrab::std::ethercat_now)).unwrap();
    let sd = |i| group.subdevice(&md, i).unwrap();
    // 0x00FC: DC without enhanced sync ("RefOnly" to ethercrab); 0x01FC: 64-bit DC.
    assert_eq!(sd(0).dc_support(), DcSupport::RefOnly);
    assert_eq!(sd(1).dc_support(), DcSupport::Bits64);
    let delays: Vec<u32> = (0..4).map(|i| sd(i).propagation_delay()).collect();
    assert_eq!(delays[0], 0);
    assert!(
        delays.windows(2).all(|w| w[1] > w[0]),
        "delays grow down the line: {delays:?}"
    );
}

#[test]
fn a_subdevice_that_stops_answering_gives_working_counter_errors() {
    let (tx, rx, pdu_loop) = storage!();
    let bus = bench();
    let _driver = inproc::spawn(tx, rx, bus.clone()).unwrap();
    let md = maindevice(pdu_loop, timeouts());
    let group = block_on(md.init_single_group::<8, 64>(ethercrab::std::ethercat_now)).unwrap();
    let group = block_on(group.into_op(&md)).unwrap();
    assert_eq!(block_on(group.tx_rx(&md)).unwrap().working_counter, 5);

    bus.set_responding(3, false);
    // The cyclic LRW misses the EL2889's +2; ethercrab reports the sum, the program compares.
    assert_eq!(block_on(group.tx_rx(&md)).unwrap().working_counter, 3);
    // A checked read of the silent device fails with a working-counter error.
    let err = block_on(group.subdevice(&md, 3).unwrap().status()).unwrap_err();
    assert!(
        matches!(
            err,
            Error::WorkingCounter {
                expected: 1,
                received: 0
            }
        ),
        "{err:?}"
    );

    bus.set_responding(3, true);
    assert_eq!(block_on(group.tx_rx(&md)).unwrap().working_counter, 5);
}

#[test]
fn a_wrong_terminal_shows_its_own_identity_to_ethercrab() {
    let (tx, rx, pdu_loop) = storage!();
    let bus = bench();
    bus.set_identity(2, 2, 0x0B0C_3052, 0x0011_0000); // an EL2828's identity in the EL2004 slot
    let _driver = inproc::spawn(tx, rx, bus.clone()).unwrap();
    let md = maindevice(pdu_loop, timeouts());
    let group = block_on(md.init_single_group::<8, 64>(ethercrab::std::ethercat_now)).unwrap();
    let id = group.subdevice(&md, 2).unwrap().identity();
    assert_eq!(
        (id.vendor_id, id.product_id, id.revision),
        (2, 0x0B0C_3052, 0x0011_0000)
    );
}

#[test]
fn a_refused_state_change_fails_into_op_and_shows_the_al_status_code() {
    let (tx, rx, pdu_loop) = storage!();
    let bus = bench();
    bus.refuse_transition(3, al::SAFE_OP, al::INVALID_OUTPUT_CONFIGURATION);
    let _driver = inproc::spawn(tx, rx, bus.clone()).unwrap();
    let md = maindevice(
        pdu_loop,
        ethercrab::Timeouts {
            state_transition: Duration::from_millis(300),
            ..timeouts()
        },
    );
    let group = block_on(md.init_single_group::<8, 64>(ethercrab::std::ethercat_now)).unwrap();
    // ethercrab waits for SAFE-OP, which the EL2889 never reaches, as with hardware.
    let err = block_on(group.into_op(&md))
        .err()
        .expect("into_op must fail");
    assert!(
        matches!(err, Error::Timeout(TimeoutError::StateTransition)),
        "{err:?}"
    );
    // What a diagnosing program reads from the terminal: PRE-OP with the error bit, and the code.
    let status: u16 = block_on(Command::fprd(0x1003, 0x0130).receive(&md)).unwrap();
    let code: u16 = block_on(Command::fprd(0x1003, 0x0134).receive(&md)).unwrap();
    assert_eq!((status, code), (0x0012, 0x001D));
    assert_eq!(bus.al_state(3), al::PRE_OP);
    assert_eq!(bus.al_status_code(3), al::INVALID_OUTPUT_CONFIGURATION);
    assert_eq!(bus.al_state(2), al::SAFE_OP, "the others went on");
}

#[test]
fn malformed_frames_are_counted_and_ignored() {
    let bus = bench();
    assert_eq!(bus.process_frame(&[]), None);
    assert_eq!(bus.process_frame(&[0u8; 20]), None); // ethertype 0
    let mut frame = vec![0xFF; 12];
    frame.extend_from_slice(&[0x88, 0xA4, 0xFF, 0x17]); // header claims 0x7FF bytes
    assert_eq!(bus.process_frame(&frame), None);
    let c = bus.counters();
    assert_eq!((c.processed, c.not_ethercat, c.malformed), (0, 1, 2));
}

#[test]
fn an_el3004_reaches_op_through_its_coe_mailbox_and_delivers_16_input_bytes() {
    let (tx, rx, pdu_loop) = storage!();
    let bus = SimBus::new(vec![Device::ek1100(), Device::el3004(), Device::el2004()]);
    let _driver = inproc::spawn(tx, rx, bus.clone()).unwrap();
    let md = maindevice(pdu_loop, timeouts());
    let group = block_on(md.init_single_group::<8, 64>(ethercrab::std::ethercat_now)).unwrap();
    let ai = group.subdevice(&md, 1).unwrap();
    assert_eq!(ai.name(), "EL3004");
    let id = ai.identity();
    assert_eq!(
        (id.vendor_id, id.product_id, id.revision),
        (2, 0x0BBC_3052, 0x0015_0000)
    );
    // An SDO upload through the mailbox, as a program reads an object.
    let product: u32 = block_on(ai.sdo_read(0x1018, 2)).unwrap();
    assert_eq!(product, 0x0BBC_3052);
    // A string longer than 4 bytes comes in one normal (not expedited) upload.
    let name: [u8; 6] = block_on(ai.sdo_read(0x1008, 0)).unwrap();
    assert_eq!(&name, b"EL3004");
    let group = block_on(group.into_op(&md)).unwrap();
    assert_eq!(bus.al_state(1), al::OP);
    let ai = group.subdevice(&md, 1).unwrap();
    // 1C13 assigns four TxPDOs of 32 bits: 16 bytes, no outputs (1C12 is empty).
    assert_eq!((ai.inputs_raw().len(), ai.outputs_raw().len()), (16, 0));

    // Channel 2: status 0x0001 (underrange bit), value -1234.
    let mut inputs = [0u8; 16];
    inputs[4..6].copy_from_slice(&1u16.to_le_bytes());
    inputs[6..8].copy_from_slice(&(-1234i16).to_le_bytes());
    bus.set_inputs(1, &inputs);
    group.subdevice(&md, 2).unwrap().outputs_raw_mut()[0] = 0b1001;
    let response = block_on(group.tx_rx(&md)).unwrap();
    assert_eq!(response.working_counter, 3); // EL3004 reads (+1), EL2004 writes (+2)
    let ai = group.subdevice(&md, 1).unwrap();
    let raw = ai.inputs_raw();
    assert_eq!(i16::from_le_bytes([raw[6], raw[7]]), -1234);
    assert_eq!(u16::from_le_bytes([raw[4], raw[5]]), 1);
    assert_eq!(bus.outputs(2), [0b1001]);
}

#[test]
fn an_sdo_write_to_the_el3004_changes_its_pdo_assignment() {
    let (tx, rx, pdu_loop) = storage!();
    let bus = SimBus::new(vec![Device::ek1100(), Device::el3004()]);
    let _driver = inproc::spawn(tx, rx, bus.clone()).unwrap();
    let md = maindevice(pdu_loop, timeouts());
    let group = block_on(md.init_single_group::<8, 64>(ethercrab::std::ethercat_now)).unwrap();
    let ai = group.subdevice(&md, 1).unwrap();
    // Only channels 1 and 2, as a program does in PRE-OP before going to OP.
    block_on(ai.sdo_write_array(0x1C13, [0x1A00u16, 0x1A02])).unwrap();
    assert_eq!(bus.device(1).sdo(0x1C13, 0), Some(2));
    let err = block_on(ai.sdo_write(0x1A00, 0, 0u8)).unwrap_err();
    assert!(matches!(err, Error::Mailbox(_)), "{err:?}");
    let group = block_on(group.into_op(&md)).unwrap();
    assert_eq!(group.subdevice(&md, 1).unwrap().inputs_raw().len(), 8);
}

#[test]
fn ethercrab_lists_the_object_dictionaries_through_the_sdo_information_service() {
    // ethercrab gathers an object list in a 128 KiB buffer and returns it in another, on the
    // stack: more than a test thread has in a debug build.
    std::thread::Builder::new()
        .stack_size(16 << 20)
        .spawn(list_the_object_dictionaries)
        .unwrap()
        .join()
        .unwrap();
}

fn list_the_object_dictionaries() {
    use ethercrab::ObjectDescriptionListQuery as List;
    let (tx, rx, pdu_loop) = storage!();
    let bus = SimBus::new(vec![Device::ek1100(), Device::el3004(), Device::akd()]);
    let _driver = inproc::spawn(tx, rx, bus.clone()).unwrap();
    let md = maindevice(pdu_loop, timeouts());
    let group = block_on(md.init_single_group::<8, 64>(ethercrab::std::ethercat_now)).unwrap();
    let ai = group.subdevice(&md, 1).unwrap();
    let all = block_on(ai.sdo_info_object_description_list(List::All))
        .unwrap()
        .unwrap();
    for index in [0x1008, 0x1018, 0x1C13, 0x1A06, 0x6000, 0x6030, 0x8030] {
        assert!(all.contains(&index), "{index:#06x} in {all:x?}");
    }
    assert!(all.windows(2).all(|w| w[0] < w[1]), "ascending, once each");
    let inputs = block_on(ai.sdo_info_object_description_list(List::TxPdoMappable))
        .unwrap()
        .unwrap();
    assert_eq!(inputs.as_slice(), [0x6000, 0x6010, 0x6020, 0x6030]);
    let counts = block_on(ai.sdo_info_object_quantities()).unwrap().unwrap();
    assert_eq!(
        (
            counts.all as usize,
            counts.tx_pdo_mappable,
            counts.rx_pdo_mappable
        ),
        (all.len(), 4, 0)
    );
    // The drive: its CiA 402 process data objects are mappable each way.
    let drive = group.subdevice(&md, 2).unwrap();
    let outputs = block_on(drive.sdo_info_object_description_list(List::RxPdoMappable))
        .unwrap()
        .unwrap();
    assert_eq!(outputs.as_slice(), [0x6040, 0x6060, 0x607A, 0x60FF]);
    let inputs = block_on(drive.sdo_info_object_description_list(List::TxPdoMappable))
        .unwrap()
        .unwrap();
    assert!(
        inputs.contains(&0x6041) && inputs.contains(&0x60F4),
        "{inputs:x?}"
    );
    // SDO uploads still work after it.
    let product: u32 = block_on(drive.sdo_read(0x1018, 2)).unwrap();
    assert_eq!(product, 0x0041_4B44);
}
