//! The modelled Beckhoff terminals: each built from the SII EEPROM image of a real one
//! (`data/`) and its ESC's facts, and looked up by order number.

use super::Device;
use crate::coe;
use crate::esc::EscInfo;
use crate::sii;

impl Device {
    /// The EK1100 EtherCAT coupler (no process data). ESC registers from capture \[A\] and a
    /// TwinCAT scan (\[R2\]).
    pub fn ek1100() -> Device {
        let words = sii::parse(include_str!("../../data/sii-EK1100-full.txt"));
        Device::from_sii(
            words,
            EscInfo {
                esc_type: 0x11,
                revision: 0x00,
                build: 0x0003,
                fmmus: 8,
                sync_managers: 8,
                ram_kib: 8,
                ports: 0x3B,
                features: 0x00FC,
                dc_system_time: true,
                dl_status_pdi: 0x1,
                sii_idle: 0x0040,
            },
        )
    }

    /// The EL1004, 4 digital inputs (one byte at 0x1000). SII from \[R3\], its strings and
    /// PDO entries completed (TxPDOs 0x1A00-0x1A03, entries 0x60n0:01 "Input"; see
    /// `data/README.md`). ESC registers from \[R2\]; the EEPROM idle status and the missing
    /// system-time unit are taken from the EL2828, which reports the same features (0x01FC).
    pub fn el1004() -> Device {
        let words = sii::parse(include_str!("../../data/sii-EL1004.txt"));
        Device::from_sii(words, Self::terminal_esc(0x0050, 0x01FC, false))
    }

    /// The EL2004, 4 digital outputs (0x0F00). Its ESC registers were never captured
    /// except the EEPROM idle status (0x0040, \[D\]); the rest are the EL2889's.
    pub fn el2004() -> Device {
        let words = sii::parse(include_str!("../../data/sii-EL2004-full.txt"));
        Device::from_sii(words, Self::terminal_esc(0x0040, 0x00FC, true))
    }

    /// The EL2828, 8 digital outputs (0x0F00). Features, DL status and EEPROM status from
    /// capture \[A\]; it does not count the DC system-time registers there.
    pub fn el2828() -> Device {
        let words = sii::parse(include_str!("../../data/sii-EL2828-full.txt"));
        Device::from_sii(words, Self::terminal_esc(0x0050, 0x01FC, false))
    }

    /// The EL2889, 16 digital outputs (0x0F00, 0x0F01). Registers from capture \[A\].
    pub fn el2889() -> Device {
        let words = sii::parse(include_str!("../../data/sii-EL2889-full.txt"));
        Device::from_sii(words, Self::terminal_esc(0x0040, 0x00FC, true))
    }

    /// The EL3004, 4 analog inputs ±10 V, with a microcontroller and a CoE mailbox
    /// (EMULATOR-NOTES §8, §10): ethercrab reads its PDO assignment by SDO uploads (1C12 empty,
    /// 1C13 = 1A00/1A02/1A04/1A06) and gets 16 input bytes at 0x1180, per channel a status
    /// word and a 16-bit value. SII from capture \[C\] (words ethercrab never read are 0, or
    /// erased after the SyncManager category: no PDO categories; strings 2-4 completed, see
    /// `data/README.md`); ESC registers as the EL1004's, which reports
    /// the same features (0x01FC) and DL status (0x5613).
    pub fn el3004() -> Device {
        let words = sii::parse(include_str!("../../data/sii-EL3004.txt"));
        let mut d = Device::from_sii(words, Self::terminal_esc(0x0050, 0x01FC, false));
        let (vendor, product, revision) = d.identity();
        d.coe = Some(coe::el3004(vendor, product, revision));
        d.coe_at_power_on = d.coe.clone();
        d.microcontroller = true;
        d
    }

    /// The order numbers of the modelled terminals, as [`Device::model`] takes them.
    pub const MODELS: [&'static str; 7] = [
        "EK1100", "EL1004", "EL2004", "EL2828", "EL2889", "EL3004", "AKD",
    ];

    /// The model of order number `name` (case-insensitive: `"el1004"` is the EL1004), or
    /// `None` for a terminal that is not modelled (see [`Device::MODELS`]). `"servo"` is
    /// another name of the AKD servo drive ([`Device::akd`]).
    ///
    /// ```
    /// use ethercat_sim::Device;
    /// assert_eq!(Device::model("el3004").unwrap().name(), "EL3004");
    /// assert!(Device::model("EL9999").is_none());
    /// ```
    pub fn model(name: &str) -> Option<Device> {
        let make: fn() -> Device = match name.to_ascii_uppercase().as_str() {
            "EK1100" => Device::ek1100,
            "EL1004" => Device::el1004,
            "EL2004" => Device::el2004,
            "EL2828" => Device::el2828,
            "EL2889" => Device::el2889,
            "EL3004" => Device::el3004,
            "AKD" | "SERVO" => Device::akd,
            _ => return None,
        };
        Some(make())
    }

    /// The small ESC of the terminals: 3 FMMUs and 4 SyncManagers (inferred from the reset
    /// working counters of capture \[A\]); type, revision, build, RAM and ports as the EL1004
    /// reported them in \[R2\].
    fn terminal_esc(sii_idle: u16, features: u16, dc_system_time: bool) -> EscInfo {
        EscInfo {
            esc_type: 0x12,
            revision: 0x01,
            build: 0x0001,
            fmmus: 3,
            sync_managers: 4,
            ram_kib: 1,
            ports: 0x4A,
            features,
            dc_system_time,
            dl_status_pdi: 0x3,
            sii_idle,
        }
    }
}
