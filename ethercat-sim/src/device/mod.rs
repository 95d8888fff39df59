//! One simulated SubDevice: the ESC's address space (registers and process RAM) and what
//! happens when a datagram reads or writes it, and the models of real Beckhoff terminals.
//!
//! This file holds the device's state, its power-on values and what can be read of it
//! directly; beside it: [`access`] (datagram reads and writes of the ESC and its reactions),
//! [`dc`] (the distributed-clock registers),
//! [`mailbox`] (the CoE mailbox), [`process_data`] (FMMUs and SyncManager areas),
//! [`faults`] (a power cycle, a tripped watchdog) and [`models`] (the modelled terminals).

mod access;
mod dc;
mod faults;
mod mailbox;
mod models;
mod process_data;
mod servo;
#[cfg(test)]
mod tests;

use crate::al;
use crate::coe::Dictionary;
use crate::dc::{DcUnit, Position, Sync0};
use crate::esc::{EscInfo, SPACE, reg};
use crate::fault::Faults;
use crate::sii::{self, Eeprom, SiiSyncManager};

/// A simulated EtherCAT SubDevice.
///
/// ```
/// use ethercat_sim::Device;
/// let d = Device::el2889();
/// assert_eq!(d.name(), "EL2889");
/// assert_eq!(d.identity(), (2, 0x0B49_3052, 0x0011_0000));
/// ```
#[derive(Clone, Debug)]
pub struct Device {
    name: String,
    esc: EscInfo,
    pub(crate) mem: Vec<u8>,
    eeprom: Eeprom,
    sync_managers: Vec<SiiSyncManager>,
    pub(crate) faults: Faults,
    pub(crate) position: Position,
    /// The distributed-clock unit: local clock, time control loop, SYNC0.
    pub(crate) dc: DcUnit,
    /// The CoE object dictionary of a device with a mailbox.
    coe: Option<Dictionary>,
    /// Its contents at power-on (the firmware keeps SDO writes in RAM only).
    coe_at_power_on: Option<Dictionary>,
    /// A terminal with a microcontroller runs the AL state machine in firmware: AL status
    /// does not mirror the acknowledge bit of AL control (EMULATOR-NOTES §5: 0x0001 after
    /// `BWR 0x0120 = 0x0011`).
    microcontroller: bool,
    /// The firmware of a CiA 402 drive, run on each process-data exchange (see [`servo`]).
    servo: Option<Box<servo::Drive>>,
    /// The fragments of an SDO information reply still to go into the input mailbox, each as
    /// soon as the MainDevice has read the one before.
    mailbox_queue: std::collections::VecDeque<Vec<u8>>,
    /// How the SDO information service is misanswered, for tests.
    sdo_info_fault: Option<crate::fault::SdoInfoFault>,
    /// While an endless reply runs (`SdoInfoFault::EndlessFragments`): the count of
    /// fragments its next fragment claims are left.
    endless_fragments: Option<u16>,
}

impl Device {
    /// A device from its SII EEPROM words and its ESC's facts. The name is the SII's
    /// order-number string (as ethercrab shows it), or "unknown" if the image has none.
    pub fn from_sii(words: Vec<u16>, esc: EscInfo) -> Device {
        let name = sii::name(&words).unwrap_or_else(|| "unknown".into());
        let mut mem = vec![0; SPACE];
        mem[0x0000] = esc.esc_type;
        mem[0x0001] = esc.revision;
        mem[0x0002..0x0004].copy_from_slice(&esc.build.to_le_bytes());
        mem[0x0004] = esc.fmmus;
        mem[0x0005] = esc.sync_managers;
        mem[0x0006] = esc.ram_kib;
        mem[0x0007] = esc.ports;
        mem[0x0008..0x000A].copy_from_slice(&esc.features.to_le_bytes());
        // Receive-time registers of ports that never latch hold what the real terminals
        // showed in capture [A] (EMULATOR-NOTES §7): "hoff" on port 1, "Verl" on port 3.
        mem[0x0904..0x0908].copy_from_slice(b"hoff");
        mem[0x090C..0x0910].copy_from_slice(b"Verl");
        let mut d = Device {
            name,
            esc,
            mem,
            sync_managers: sii::sync_managers(&words),
            eeprom: Eeprom::new(words, esc.sii_idle),
            faults: Faults::default(),
            position: Position::default(),
            dc: DcUnit::default(),
            coe: None,
            coe_at_power_on: None,
            microcontroller: false,
            servo: None,
            mailbox_queue: Default::default(),
            sdo_info_fault: None,
            endless_fragments: None,
        };
        d.load_from_eeprom();
        d.set_u16(reg::AL_CONTROL, al::INIT as u16);
        d.set_u16(reg::AL_STATUS, al::INIT as u16);
        d.set_u16(reg::SII_CONTROL, esc.sii_idle);
        d.set_dl_status();
        if esc.dc_system_time {
            d.set_dc_power_on_values();
        }
        d
    }

    /// Power-on values of the time control loop and the SYNC unit (datasheet, Section II):
    /// speed counter start 0x1000, filter depths 4 and 12, and the pulse length of the SYNC
    /// signals from SII word 2 (0 on the modelled terminals: acknowledge mode).
    fn set_dc_power_on_values(&mut self) {
        self.set_u16(reg::DC_SPEED_COUNTER_START, 0x1000);
        self.mem[reg::DC_TIME_FILTER_DEPTH] = 0x04;
        self.mem[reg::DC_SPEED_FILTER_DEPTH] = 0x0C;
        let pulse_length = self.eeprom.words.get(2).copied().unwrap_or(0);
        self.set_u16(reg::DC_PULSE_LENGTH, pulse_length);
    }

    /// The model name (the SII's order number, e.g. "EK1100").
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The ESC's facts.
    pub fn esc(&self) -> &EscInfo {
        &self.esc
    }

    /// Vendor, product and revision from the EEPROM.
    pub fn identity(&self) -> (u32, u32, u32) {
        sii::identity(&self.eeprom.words)
    }

    /// The SII EEPROM words (writes by the MainDevice included).
    pub fn sii(&self) -> &[u16] {
        &self.eeprom.words
    }

    /// The SII EEPROM words, to change the image before the device goes on a bus (the ESC
    /// loads the station alias from word 4 at power-up, i.e. in [`Device::from_sii`], and on
    /// a reload command).
    pub fn eeprom_words_mut(&mut self) -> &mut [u16] {
        &mut self.eeprom.words
    }

    /// The SyncManagers the SII describes.
    pub fn sii_sync_managers(&self) -> &[SiiSyncManager] {
        &self.sync_managers
    }

    /// Changes the identity in the EEPROM (a different terminal in this slot).
    pub fn set_identity(&mut self, vendor: u32, product: u32, revision: u32) {
        sii::set_identity(&mut self.eeprom.words, vendor, product, revision);
    }

    /// The configured station address (0x0010).
    pub fn station_address(&self) -> u16 {
        self.u16_at(reg::STATION_ADDRESS)
    }

    /// The AL status register (0x0130): state in bits 0-3, error in bit 4.
    pub fn al_status(&self) -> u16 {
        self.u16_at(reg::AL_STATUS)
    }

    /// The AL state (low nibble of 0x0130).
    pub fn al_state(&self) -> u8 {
        self.mem[reg::AL_STATUS] & 0x0F
    }

    /// The AL status code (0x0134).
    pub fn al_status_code(&self) -> u16 {
        self.u16_at(reg::AL_STATUS_CODE)
    }

    /// The drift of the device's local clock in parts per billion (its oscillator runs
    /// `1 + drift` ns per ns of bus time); 0 for a device that is on no bus.
    pub fn dc_drift_ppb(&self) -> i64 {
        self.dc.clock.drift_ppb()
    }

    /// What the device's SYNC0 output has done, up to the last frame it saw (nothing on a
    /// device without a DC system-time unit).
    pub fn sync0(&self) -> Sync0 {
        self.dc.sync.snapshot()
    }

    /// Reads registers or process RAM directly, as the device's own PDI would (not a
    /// datagram: no working counter, no side effects; 0 beyond the modelled space).
    pub fn register(&self, address: usize, out: &mut [u8]) {
        for (i, b) in out.iter_mut().enumerate() {
            *b = self.mem.get(address + i).copied().unwrap_or(0);
        }
    }

    pub(crate) fn u16_at(&self, a: usize) -> u16 {
        u16::from_le_bytes([self.mem[a], self.mem[a + 1]])
    }

    pub(crate) fn set_u16(&mut self, a: usize, v: u16) {
        self.mem[a..a + 2].copy_from_slice(&v.to_le_bytes());
    }

    pub(crate) fn u32_at(&self, a: usize) -> u32 {
        u32::from_le_bytes([
            self.mem[a],
            self.mem[a + 1],
            self.mem[a + 2],
            self.mem[a + 3],
        ])
    }

    fn u64_at(&self, a: usize) -> u64 {
        self.u32_at(a) as u64 | (self.u32_at(a + 4) as u64) << 32
    }

    fn set_u64(&mut self, a: usize, v: u64) {
        self.mem[a..a + 8].copy_from_slice(&v.to_le_bytes());
    }

    /// Registers the ESC loads from the EEPROM at power-up and on a reload command.
    fn load_from_eeprom(&mut self) {
        let alias = self.eeprom.words.get(4).copied().unwrap_or(0);
        self.set_u16(reg::STATION_ALIAS, alias);
    }

    /// DL status (0x0110) from the position in the line (EMULATOR-NOTES §6): link and
    /// communication on port 0, and on port 1 unless this is the last device or the link to
    /// the next one is lost (port 1 loop closed); ports 2 and 3 closed. 0x5A31 on a passing EK1100, 0x5613 at the end.
    pub(crate) fn set_dl_status(&mut self) {
        let port1 = self.position.port1_open();
        let low = self.esc.dl_status_pdi as u16 | 0x10 | if port1 { 0x20 } else { 0 };
        let high: u16 = 0x02 | 0x50 | if port1 { 0x08 } else { 0x04 };
        self.set_u16(reg::DL_STATUS, high << 8 | low);
    }
}
