//! Real ethercrab 0.7 against the simulated terminals: init to OP, the real devices' names,
//! identities and process data sizes, cyclic data both ways with the working counters real
//! ESCs give, and the faults a test bench needs.

use ethercat_sim::{Device, SimBus, al, inproc};
use ethercrab::error::Error;
use ethercrab::{MainDevice, MainDeviceConfig, PduStorage, Timeouts};
use futures_lite::future::block_on;
use std::time::Duration;

const FRAMES: usize = 16;
const PDU: usize = 1100;

/// Each test its own storage: ethercrab's frame queues are `'static` and single-use.
macro_rules! storage {
    () => {{
        static STORAGE: PduStorage<FRAMES, PDU> = PduStorage::new();
        STORAGE.try_split().expect("storage used once")
    }};
}

fn bench() -> SimBus {
    SimBus::new(vec![
        Device::ek1100(),
        Device::el1004(),
        Device::el2004(),
        Device::el2889(),
    ])
}

fn maindevice(pdu_loop: ethercrab::PduLoop<'static>) -> MainDevice<'static> {
    // Room for a busy machine: the simulated devices answer from a thread that may have to
    // wait for a core (ethercrab's 10 ms EEPROM default assumes hardware).
    let timeouts = Timeouts {
        pdu: Duration::from_millis(200),
        eeprom: Duration::from_millis(500),
        ..Timeouts::default()
    };
    MainDevice::new(
        pdu_loop,
        timeouts,
        MainDeviceConfig {
            dc_static_sync_iterations: 100,
            ..MainDeviceConfig::default()
        },
    )
}

#[test]
fn ethercrab_brings_ek1100_el1004_el2004_el2889_to_op_and_exchanges_data() {
    let (tx, rx, pdu_loop) = storage!();
    let bus = bench();
    let _driver = inproc::spawn(tx, rx, bus.clone()).unwrap();
    let md = maindevice(pdu_loop);
    let group = block_on(md.init_single_group::<8, 64>(ethercrab::std::ethercat_now)).unwrap();
    let expected = [
        ("EK1100", 0x044C_2C52, 0x0012_0000, 0, 0),
        ("EL1004", 0x03EC_3052, 0x0013_0000, 1, 0),
        ("EL2004", 0x07D4_3052, 0x0010_0000, 0, 1),
        ("EL2889", 0x0B49_3052, 0x0011_0000, 0, 2),
    ];
    let group = block_on(group.into_op(&md)).unwrap();
    for (i, (name, product, revision, inputs, outputs)) in expected.into_iter().enumerate() {
        let sd = group.subdevice(&md, i).unwrap();
        assert_eq!(sd.name(), name);
        let id = sd.identity();
        assert_eq!(
            (id.vendor_id, id.product_id, id.revision),
            (2, product, revision)
        );
        assert_eq!(sd.inputs_raw().len(), inputs, "{name} input bytes");
        assert_eq!(sd.outputs_raw().len(), outputs, "{name} output bytes");
        assert_eq!(bus.al_state(i), al::OP);
    }

    bus.set_input_bit(1, 0, true);
    bus.set_input_bit(1, 3, true);
    {
        let dq4 = group.subdevice(&md, 2).unwrap();
        dq4.outputs_raw_mut()[0] = 0b0101;
        let dq16 = group.subdevice(&md, 3).unwrap();
        dq16.outputs_raw_mut().copy_from_slice(&[0x80, 0x01]);
    }
    let response = block_on(group.tx_rx(&md)).unwrap();
    // EL1004: +1 (read FMMU); EL2004 and EL2889: +2 each (write FMMU); EK1100: nothing.
    assert_eq!(response.working_counter, 5);
    assert_eq!(group.subdevice(&md, 1).unwrap().inputs_raw()[0], 0b1001);
    assert_eq!(bus.outputs(2), [0b0101]);
    assert_eq!(bus.outputs(3), [0x80, 0x01]);
    assert!(bus.output_bit(3, 7) && bus.output_bit(3, 8) && !bus.output_bit(3, 0));
}

#[test]
fn a_subdevice_that_stops_answering_gives_a_wrong_working_counter() {
    let (tx, rx, pdu_loop) = storage!();
    let bus = bench();
    let _driver = inproc::spawn(tx, rx, bus.clone()).unwrap();
    let md = maindevice(pdu_loop);
    let group = block_on(md.init_single_group::<8, 64>(ethercrab::std::ethercat_now)).unwrap();
    let group = block_on(group.into_op(&md)).unwrap();
    assert_eq!(block_on(group.tx_rx(&md)).unwrap().working_counter, 5);
    bus.set_responding(3, false);
    let r = block_on(group.tx_rx(&md));
    assert!(
        matches!(&r, Ok(resp) if resp.working_counter == 3) || r.is_err(),
        "the EL2889's +2 is missing: {r:?}"
    );
    bus.set_responding(3, true);
    assert_eq!(block_on(group.tx_rx(&md)).unwrap().working_counter, 5);
}

#[test]
fn a_wrong_terminal_shows_its_own_identity_to_ethercrab() {
    let (tx, rx, pdu_loop) = storage!();
    let bus = bench();
    bus.set_identity(2, 2, 0x0B0C_3052, 0x0011_0000); // an EL2828 where an EL2004 belongs
    let _driver = inproc::spawn(tx, rx, bus.clone()).unwrap();
    let md = maindevice(pdu_loop);
    let group = block_on(md.init_single_group::<8, 64>(ethercrab::std::ethercat_now)).unwrap();
    let sd = group.subdevice(&md, 2).unwrap();
    assert_eq!(sd.identity().product_id, 0x0B0C_3052);
}

#[test]
fn a_refused_state_change_fails_into_op() {
    let (tx, rx, pdu_loop) = storage!();
    let bus = bench();
    bus.refuse_transition(3, al::SAFE_OP, 0x001D); // "invalid output configuration"
    let _driver = inproc::spawn(tx, rx, bus.clone()).unwrap();
    let md = maindevice(pdu_loop);
    let group = block_on(md.init_single_group::<8, 64>(ethercrab::std::ethercat_now)).unwrap();
    let err = block_on(group.into_op(&md))
        .err()
        .expect("into_op must fail");
    assert!(
        matches!(
            err,
            Error::StateTransition | Error::SubDevice(_) | Error::Timeout(_)
        ),
        "{err:?}"
    );
    assert_ne!(bus.al_state(3), al::OP);
}

#[test]
fn malformed_frames_are_ignored_not_a_panic() {
    let bus = bench();
    assert_eq!(bus.process_frame(&[]), None);
    assert_eq!(bus.process_frame(&[0u8; 20]), None);
    let mut frame = vec![0xFF; 14];
    frame[12] = 0x88;
    frame[13] = 0xA4;
    frame.extend_from_slice(&[0xFF, 0x17]); // header says more than there is
    assert_eq!(bus.process_frame(&frame), None);
}
