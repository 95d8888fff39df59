//! Faults a test injects into the bus: a lost link (the device and the ring behind it stop
//! answering), a power cycle, a tripped SyncManager watchdog, a wrong identity, a refused
//! state change.

use super::SimBus;

impl SimBus {
    /// Makes the device at `pos` stop answering as a real one does: the link into its port 0
    /// goes down (the device lost power, or its cable was pulled), so the device before it
    /// closes its port 1 (DL status shows the lost link) and frames turn back there. Neither
    /// this device nor any device behind it sees a frame: they do not act on any datagram,
    /// do not count working counters and do not increment auto-increment addresses (APRD
    /// and FPRD to them get working counter 0, a BRD counts only the devices before). With
    /// `pos` 0 no device answers. `true` restores the link; the devices kept their registers,
    /// as after a pulled and re-plugged cable (add [`power_cycle`](Self::power_cycle) for a
    /// device that lost its power).
    pub fn set_responding(&self, pos: usize, responding: bool) {
        let mut ring = self.ring();
        let n = ring.devices.len();
        assert!(pos < n, "no SubDevice at position {pos}: the bus has {n}");
        ring.devices[pos].faults.link_lost = !responding;
        for i in 0..n {
            let lost = ring.devices.get(i + 1).is_some_and(|d| d.faults.link_lost);
            let d = &mut ring.devices[i];
            d.position.next_link_lost = lost;
            d.set_dl_status();
        }
    }

    /// Restarts the device at `pos` as after a loss of power: its registers and process
    /// RAM return to their power-on values (AL state INIT, station address 0, SyncManagers
    /// and FMMUs off, outputs off, station alias reloaded), its EEPROM keeps its contents.
    /// A MainDevice must address and configure it again. Call it while the device is off the
    /// ring ([`set_responding`](Self::set_responding) `false`) to model an outage, or on its
    /// own for a short power dip.
    pub fn power_cycle(&self, pos: usize) {
        self.with(pos, |d| d.power_on_reset())
    }

    /// The SyncManager watchdog of the device at `pos` expires, as when process data stopped
    /// arriving for longer than its watchdog time (100 ms by default on Beckhoff terminals):
    /// the device drops to SAFE-OP (or stays lower), switches its outputs off and reports AL
    /// status 0x0014 with AL status code 0x001B ([`al::SYNC_MANAGER_WATCHDOG`](crate::al::SYNC_MANAGER_WATCHDOG)). It ignores
    /// state requests until one carries the error-acknowledge bit (AL control bit 4). The
    /// simulator has no clock of its own to trip it: a test injects it.
    pub fn trip_watchdog(&self, pos: usize) {
        self.with(pos, |d| d.trip_watchdog())
    }

    /// Changes the identity the device at `pos` reports from its EEPROM (a different
    /// terminal in this slot).
    pub fn set_identity(&self, pos: usize, vendor: u32, product: u32, revision: u32) {
        self.with(pos, |d| d.set_identity(vendor, product, revision))
    }

    /// Makes the device at `pos` refuse requests for AL state `state` (see [`al`](crate::al)): it keeps
    /// its state, sets the error bit 4 of AL status and reports `code` in AL status code
    /// 0x0134, as a terminal with a microcontroller does.
    pub fn refuse_transition(&self, pos: usize, state: u8, code: u16) {
        self.with(pos, |d| d.faults.refuse(state, code))
    }

    /// Lets the device at `pos` accept requests for `state` again.
    pub fn accept_transition(&self, pos: usize, state: u8) {
        self.with(pos, |d| d.faults.accept(state))
    }
}
