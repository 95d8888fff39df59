//! A CiA 402 servo drive (the Kollmorgen AKD's EtherCAT interface): its CoE objects
//! ([`objects`]), the PDO image they make ([`pdo`]), the drive state machine
//! ([`state_machine`]), the motor and load ([`motor`]) and the firmware's cycle ([`drive`]).
//!
//! The drive runs when a logical datagram reaches its FMMUs, before the datagram's bytes
//! move: it takes the outputs the previous exchange left (one cycle of latency, as a drive
//! that acts on SYNC0 between two frames), integrates the motor over the real time since
//! its last run, and leaves new inputs for this datagram to read.

mod drive;
mod motor;
pub(crate) mod objects;
mod pdo;
mod state_machine;

pub(crate) use drive::Drive;

use super::Device;
use crate::al;
use crate::esc::EscInfo;
use crate::sii;

/// SII SyncManager kinds of the process data.
const OUTPUTS: u8 = 3;
const INPUTS: u8 = 4;

impl Device {
    /// The Kollmorgen AKD servo drive (EtherCAT, CiA 402 over CoE), order name "AKD", with a
    /// simulated motor; [`Device::model`] also finds it as `"servo"`.
    ///
    /// Its process image, as ethercrab reads the PDO assignment (0x1C12 = 0x1600, 0x1C13 =
    /// 0x1A00) and mappings by SDO:
    /// - outputs (11 bytes): controlword (0x6040, u16), modes_of_operation (0x6060, i8),
    ///   target_position (0x607A, i32), target_velocity (0x60FF, i32);
    /// - inputs (17 bytes): statusword (0x6041, u16), modes_of_operation_display (0x6061,
    ///   i8), position_actual_value (0x6064, i32), velocity_actual_value (0x606C, i32),
    ///   following_error_actual_value (0x60F4, i32), error_code (0x603F, u16).
    ///
    /// Each exchange runs the CiA 402 state machine (fault reset on the rising edge of
    /// controlword bit 7), CSP (8), CSV (9) and homing (6, methods 37 and 35: the current
    /// position becomes the home offset 0x607C), the following error window 0x6065 (fault
    /// 0x8611) and, when SYNC0 drove a cyclic mode and stops, fault 0x8700. Positions are in
    /// increments (2^20 per revolution), velocities in increments/s.
    ///
    /// Sources (details in `data/README.md`): the SII image is ethercrab's complete dump of
    /// a real AKD (`dumps/eeprom/akd.hex`: vendor 0x6A, product 0x00414B44, revision 2); ESC
    /// registers from ethercrab's SOEM and TwinCAT captures of an AKD; the PDO objects
    /// 0x1601-0x1603 and 0x1A01-0x1A03 as the SOEM capture read them, the fixed PDOs from
    /// the EEPROM. Invented: the preset 0x1600/0x1A00 mappings (a real AKD powers up with
    /// 0x1600-0x1603 assigned; a program maps this image in PRE-OP), the motor, its limits
    /// and the loop gain.
    ///
    /// ```
    /// use ethercat_sim::Device;
    /// let d = Device::akd();
    /// assert_eq!((d.name(), d.identity()), ("AKD", (0x6A, 0x0041_4B44, 2)));
    /// assert_eq!(d.sdo(0x1C12, 1), Some(0x1600));
    /// assert_eq!(d.sdo(0x6041, 0), Some(0), "not ready to switch on until it runs");
    /// ```
    pub fn akd() -> Device {
        let words = sii::parse(include_str!("../../../data/sii-AKD-full.txt"));
        // The serial number, SII words 0x0E-0x0F (ethercrab's test of the dump: 2575499411).
        let word = |w: usize| words.get(w).copied().unwrap_or(0) as u32;
        let serial = word(0x0E) | word(0x0F) << 16;
        let mut d = Device::from_sii(words, Self::akd_esc());
        let (vendor, product, revision) = d.identity();
        d.coe = Some(objects::akd(vendor, product, revision, serial));
        d.coe_at_power_on = d.coe.clone();
        d.microcontroller = true;
        d.servo = Some(Box::default());
        d
    }

    /// The AKD's ESC as ethercrab's captures of one show it (`soem-sdinfo-akd.pcapng`,
    /// `twincat-akd-nc-mode.pcapng`): type 0x04, revision 2, build 0x0043, 3 FMMUs, 4
    /// SyncManagers, 4 KiB RAM, ports 0x0F, features 0x0184 (DC with 32-bit system time,
    /// enhanced DC sync), DL status 0x5613 and EEPROM status 0x0020 (4-byte reads, the
    /// firmware emulating the EEPROM). That its system-time unit exists is inferred from
    /// the DC features; no capture reads it.
    fn akd_esc() -> EscInfo {
        EscInfo {
            esc_type: 0x04,
            revision: 0x02,
            build: 0x0043,
            fmmus: 3,
            sync_managers: 4,
            ram_kib: 4,
            ports: 0x0F,
            features: 0x0184,
            dc_system_time: true,
            dl_status_pdi: 0x3,
            sii_idle: 0x0020,
        }
    }

    /// A logical datagram over `[logical, logical + len)` at bus time `now` is about to
    /// pass: if it reaches this device's FMMUs, a drive runs one cycle first (nothing
    /// happens on other devices, or below SAFE-OP, where no process data flows).
    pub(crate) fn before_process_data(&mut self, now: u64, logical: u32, len: usize) {
        if self.servo.is_none() {
            return;
        }
        let state = self.al_state();
        if state != al::SAFE_OP && state != al::OP {
            return;
        }
        let (start, end) = (logical as u64, logical as u64 + len as u64);
        let reached = self.fmmus().iter().any(|f| {
            let f_start = u64::from(f.logical);
            f_start < end && start < f_start + f.len as u64
        });
        if !reached {
            return;
        }
        let outputs = self.areas(OUTPUTS).first().cloned();
        let inputs = self.areas(INPUTS).first().cloned();
        let sync0 = self.esc.dc_system_time.then(|| self.sync0().active);
        let op = state == al::OP;
        let (Some(drive), Some(d)) = (self.servo.as_deref_mut(), self.coe.as_mut()) else {
            return;
        };
        if let (true, Some(area)) = (op, outputs) {
            pdo::receive(d, &pdo::layout(d, 0x1C12), &self.mem, area);
        }
        drive.cycle(d, now, op, sync0);
        if let Some(area) = inputs {
            pdo::transmit(d, &pdo::layout(d, 0x1C13), &mut self.mem, area);
        }
    }
}
