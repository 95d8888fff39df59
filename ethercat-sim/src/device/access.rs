//! What a datagram's read or write does to the ESC: registers that change by themselves
//! brought up to date before a read (EEPROM interface, DC registers), read-only bytes kept
//! on a write, and the ESC's reactions to written registers (AL control, EEPROM commands,
//! RX error counters, the output mailbox; DC registers in [`super::dc`]).

use super::Device;
use crate::al;
use crate::esc::{self, SPACE, reg};
use crate::sii::Completed;

/// Registers the EEPROM interface computes when read.
const SII_REGS: std::ops::Range<usize> = reg::SII_CONTROL..reg::SII_DATA + 8;

impl Device {
    /// Whether the device answers datagrams addressed to station address `adp`: its
    /// configured address, or its alias when DL control enables alias addressing.
    pub(crate) fn addressed_as(&self, adp: u16) -> bool {
        self.station_address() == adp
            || (self.mem[reg::DL_CONTROL_ALIAS] & 1 != 0 && self.u16_at(reg::STATION_ALIAS) == adp)
    }

    /// Whether a datagram over `[ado, ado + len)` finds registers here.
    pub(crate) fn has(&self, ado: usize, len: usize) -> bool {
        self.esc.has(ado, len)
    }

    /// Brings registers that change by themselves (EEPROM interface, system time) up to date
    /// before a datagram reads `[ado, ado + len)` at bus time `now`.
    fn refresh(&mut self, ado: usize, len: usize, now: u64) {
        let overlaps = |r: std::ops::Range<usize>| ado < r.end && r.start < ado + len;
        if overlaps(SII_REGS) {
            self.tick_eeprom(now);
        }
        self.refresh_dc(ado, len, now);
    }

    fn tick_eeprom(&mut self, now: u64) {
        if let Completed::Data(data) = self.eeprom.tick(now) {
            self.mem[reg::SII_DATA..reg::SII_DATA + 8].copy_from_slice(&data);
        }
        let status = self.eeprom.status();
        self.set_u16(reg::SII_CONTROL, status);
    }

    /// Reads `out.len()` bytes at `ado` into `out` (0 beyond the modelled space).
    pub(crate) fn read(&mut self, ado: usize, out: &mut [u8], now: u64) {
        self.refresh(ado, out.len(), now);
        self.register(ado, out);
        self.after_mailbox_read(ado, out.len());
    }

    /// ORs the bytes at `ado` into `out` (BRD).
    pub(crate) fn read_or(&mut self, ado: usize, out: &mut [u8], now: u64) {
        self.refresh(ado, out.len(), now);
        for (i, b) in out.iter_mut().enumerate() {
            *b |= self.mem.get(ado + i).copied().unwrap_or(0);
        }
    }

    /// Writes `data` at `ado` at bus time `now`, then lets the ESC react (AL control, EEPROM
    /// commands, DC latches). Read-only bytes keep their value.
    pub(crate) fn write(&mut self, ado: usize, data: &[u8], now: u64) {
        let touches = |a: usize| ado <= a && a < ado + data.len();
        if ado < SII_REGS.end && SII_REGS.start < ado + data.len() {
            // A command that finished in the background finishes before the new bytes land.
            self.tick_eeprom(now);
        }
        let old_system_time = touches(reg::DC_SYSTEM_TIME).then(|| {
            self.refresh(reg::DC_SYSTEM_TIME, 8, now);
            self.u64_at(reg::DC_SYSTEM_TIME)
        });
        for (i, &b) in data.iter().enumerate() {
            let a = ado + i;
            if a < SPACE && esc::writable(a) {
                self.mem[a] = b;
            }
        }
        if reg::RX_ERROR_COUNTERS.start < ado + data.len() && ado < reg::RX_ERROR_COUNTERS.end {
            // A write to any RX error counter clears them all, whatever is written.
            self.mem[reg::RX_ERROR_COUNTERS].fill(0);
        }
        if touches(reg::AL_CONTROL) {
            self.on_al_control();
        }
        self.after_mailbox_write(ado, data.len());
        if touches(reg::SII_CONTROL) || touches(reg::SII_CONTROL + 1) {
            self.on_sii_command(now);
        }
        self.after_dc_write(ado, data.len(), now, old_system_time);
    }

    fn on_al_control(&mut self) {
        let control = self.u16_at(reg::AL_CONTROL);
        let refused = self.faults.refusal((control & 0x0F) as u8);
        let (status, code) =
            al::on_control(self.al_status(), control, refused, self.faults.latched);
        self.faults.latched = (status & al::ERROR != 0 && code != 0).then_some(code);
        let status = if self.microcontroller && code == 0 {
            status & !al::ERROR
        } else {
            status
        };
        self.set_u16(reg::AL_STATUS, status);
        self.set_u16(reg::AL_STATUS_CODE, code);
    }

    fn on_sii_command(&mut self, now: u64) {
        let control = self.u16_at(reg::SII_CONTROL);
        let address = self.u32_at(reg::SII_ADDRESS);
        let data = self.u16_at(reg::SII_DATA);
        if self.eeprom.command(control, address, data, now) {
            self.load_from_eeprom();
        }
        let status = self.eeprom.status();
        self.set_u16(reg::SII_CONTROL, status);
    }
}
