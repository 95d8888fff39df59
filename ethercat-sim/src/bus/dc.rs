//! Distributed clocks as a test sees them: each device's SYNC0 output and system time, and
//! a clock's drift changed on purpose.

use super::SimBus;
use crate::dc::Sync0;

impl SimBus {
    /// What the SYNC0 output of the device at `pos` has done, up to the last frame the bus
    /// processed: pulses so far, the local system time of the last and of the next. A device
    /// model checks it to notice a lost SYNC0; nothing fires on a device without a DC
    /// system-time unit.
    pub fn sync0(&self, pos: usize) -> Sync0 {
        self.with(pos, |d| d.sync0())
    }

    /// Each device's local copy of the system time (ns) at the bus time of the last frame,
    /// in ring order: where the clocks stand against each other at one instant (`None` for
    /// a device without a DC system-time unit).
    pub fn system_times(&self) -> Vec<Option<u64>> {
        let ring = self.ring();
        ring.devices
            .iter()
            .map(|d| d.esc().dc_system_time.then(|| d.system_time_at(ring.now)))
            .collect()
    }

    /// From the last frame on, the local clock of the device at `pos` drifts by `drift_ppb`
    /// parts per billion (clamped to ±1 %) instead of its seeded drift; its time does not
    /// jump. For tests of the worst case (crystals of ±100 ppm pulling apart) or of a clock
    /// that goes wrong.
    pub fn set_clock_drift(&self, pos: usize, drift_ppb: i64) {
        let now = self.ring().now;
        self.with(pos, |d| d.dc.clock.set_drift(now, drift_ppb))
    }
}
