//! Distributed clocks (EMULATOR-NOTES §7; Beckhoff ESC datasheet, Section I "Distributed
//! Clocks" and Section II registers 0x0900-0x09FF, see `data/README.md`): each device with
//! a DC unit has a local clock of its own ([`clock`]: start and drift seeded per bus), whose
//! time control loop ([`control`]) follows the system time a MainDevice distributes from the
//! reference clock, and a SYNC0 output ([`sync0`]) that fires on the local copy of the
//! system time. This file: where frames meet the devices in the line, which gives the
//! receive times a MainDevice measures propagation delays with.
//!
//! Frames take [`HOP_NS`] from one device to the next, so in a line of N devices a frame
//! sent at bus time `t` reaches device i at `t + i·HOP_NS` on port 0 and comes back to its
//! port 1 at `t + (2N − 2 − i)·HOP_NS`: a MainDevice then computes a delay of one hop per
//! device, as it does on hardware (capture \[A\]: 140 and 295 ns).

mod clock;
mod control;
mod sync0;

pub(crate) use clock::{Clock, seeded};
pub(crate) use control::{ControlLoop, Params};
pub use sync0::Sync0;
pub(crate) use sync0::SyncUnit;

/// Time a frame takes from one device's port 0 to the next one's (cable plus forwarding).
pub const HOP_NS: u64 = 140;

/// Where a device sits in the line.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Position {
    /// Index in ring order.
    pub(crate) index: usize,
    /// Devices on the bus.
    pub(crate) count: usize,
    /// The link to the next device is down, so port 1 has closed its loop.
    pub(crate) next_link_lost: bool,
}

impl Position {
    /// Whether port 1 leads to another device (every device but the last, in a line).
    pub(crate) fn port1_open(&self) -> bool {
        self.index + 1 < self.count && !self.next_link_lost
    }

    /// Bus time when a frame sent at bus time `t` reaches port 0.
    pub(crate) fn arrival(&self, t: u64) -> u64 {
        t.saturating_add(self.index as u64 * HOP_NS)
    }

    /// Bus time when that frame comes back on port 1.
    fn return_time(&self, t: u64) -> u64 {
        let hops = (2 * self.count as u64).saturating_sub(2 + self.index as u64);
        t.saturating_add(hops * HOP_NS)
    }
}

/// Receive times to latch for a frame sent at bus time `t`: port 0 to 3 (None keeps what the
/// register held) and the processing unit's 64-bit time, all in local time.
pub(crate) fn latch(pos: &Position, clock: &Clock, t: u64) -> ([Option<u32>; 4], u64) {
    let arrival = clock.local(pos.arrival(t));
    let port1 = pos
        .port1_open()
        .then(|| clock.local(pos.return_time(t)) as u32);
    ([Some(arrival as u32), port1, None, None], arrival)
}

/// A device's distributed-clock unit: its clock, time control loop and SYNC0 output.
#[derive(Clone, Debug, Default)]
pub(crate) struct DcUnit {
    /// The local clock.
    pub(crate) clock: Clock,
    /// The time control loop.
    pub(crate) control: ControlLoop,
    /// The SYNC out unit (SYNC0).
    pub(crate) sync: SyncUnit,
}

impl DcUnit {
    /// After a power cycle: the loop and the SYNC unit start afresh and the clock loses its
    /// corrections (its oscillator runs on: the simulator does not restart it from 0).
    pub(crate) fn power_on_reset(&mut self) {
        self.control.reset();
        self.sync = SyncUnit::default();
        self.clock.forget_corrections();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn loop_times_shrink_by_two_hops_per_device() {
        let clock = Clock::new(77, 0);
        let loop_time = |index| {
            let p = Position {
                index,
                count: 3,
                next_link_lost: false,
            };
            let (ports, _) = latch(&p, &clock, 1000);
            ports[1].map_or(0, |p1| p1 - ports[0].unwrap_or(0))
        };
        assert_eq!(
            (loop_time(0), loop_time(1), loop_time(2)),
            (4 * HOP_NS as u32, 2 * HOP_NS as u32, 0)
        );
    }
}
