//! Helpers shared by the integration tests (a module, not a test target of its own).
#![allow(dead_code)]

pub mod pcapng;

use ethercat_sim::{Device, SimBus};
use ethercrab::{MainDevice, MainDeviceConfig, PduLoop, Timeouts};
use std::time::Duration;

/// Frames and bytes per frame of each test's `PduStorage`.
pub const FRAMES: usize = 16;
/// Bytes of EtherCAT data per frame.
pub const PDU: usize = 1100;

/// A fresh `PduStorage` for the calling test: ethercrab's frame queues are `'static` and can
/// be split once, so each test has its own.
#[allow(unused_macros)]
macro_rules! storage {
    () => {{
        static STORAGE: ethercrab::PduStorage<{ common::FRAMES }, { common::PDU }> =
            ethercrab::PduStorage::new();
        STORAGE.try_split().expect("storage used once")
    }};
}

/// EK1100 + EL1004 + EL2004 + EL2889, the tensile tester's bench.
pub fn bench() -> SimBus {
    SimBus::new(vec![
        Device::ek1100(),
        Device::el1004(),
        Device::el2004(),
        Device::el2889(),
    ])
}

/// Timeouts with room for a busy machine: the simulated devices answer from a thread that
/// may wait for a core, where ethercrab's 30 ms PDU and 10 ms EEPROM defaults assume hardware.
pub fn timeouts() -> Timeouts {
    Timeouts {
        pdu: Duration::from_millis(500),
        eeprom: Duration::from_millis(500),
        state_transition: Duration::from_millis(1500),
        ..Timeouts::default()
    }
}

/// A MainDevice with 100 static DC sync frames (the default 10 000 takes seconds).
pub fn maindevice(pdu_loop: PduLoop<'static>, timeouts: Timeouts) -> MainDevice<'static> {
    MainDevice::new(
        pdu_loop,
        timeouts,
        MainDeviceConfig {
            dc_static_sync_iterations: 100,
            ..MainDeviceConfig::default()
        },
    )
}
