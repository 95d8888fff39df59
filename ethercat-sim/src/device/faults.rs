//! What injected faults do to a device: a power cycle (back to its power-on registers) and a
//! tripped SyncManager watchdog.

use super::Device;
use crate::al;
use crate::esc::reg;

impl Device {
    /// The device restarts, as after losing its power: every register and the process RAM
    /// back to their power-on values (INIT, station address 0, SyncManagers and FMMUs off,
    /// alias reloaded from the EEPROM, CoE objects back to their defaults, the DC loop and
    /// SYNC unit reset), the EEPROM contents kept. Injected faults stay.
    pub(crate) fn power_on_reset(&mut self) {
        let fresh = Device::from_sii(self.eeprom.words.clone(), self.esc);
        self.mem = fresh.mem;
        self.eeprom = fresh.eeprom;
        self.coe.clone_from(&self.coe_at_power_on);
        self.mailbox_queue.clear();
        self.endless_fragments = None;
        if let Some(drive) = self.servo.as_deref_mut() {
            *drive = super::servo::Drive::default();
        }
        self.faults.latched = None;
        self.dc.power_on_reset();
        self.set_dl_status();
    }

    /// The SyncManager watchdog expired (no process data for longer than its time, e.g. the
    /// MainDevice stopped cycling): a terminal with a microcontroller drops to SAFE-OP,
    /// switches its outputs off, and reports AL status code 0x001B until acknowledged.
    pub(crate) fn trip_watchdog(&mut self) {
        let state = self.al_state().min(al::SAFE_OP) as u16;
        self.set_u16(reg::AL_STATUS, state | al::ERROR);
        self.set_u16(reg::AL_STATUS_CODE, al::SYNC_MANAGER_WATCHDOG);
        self.faults.latched = Some(al::SYNC_MANAGER_WATCHDOG);
    }
}
