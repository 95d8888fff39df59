//! Distributed clocks: each device's local clock, the receive times latched per port when a
//! MainDevice writes 0x0900, and system time (0x0910) with offset and delay, enough for a
//! MainDevice to measure propagation delays and align clocks (EMULATOR-NOTES §7).
//!
//! Frames take [`HOP_NS`] from one device to the next, so in a line of N devices a frame
//! reaches device i at `t + i·HOP_NS` on port 0 and comes back to its port 1 at
//! `t + (2N − 2 − i)·HOP_NS`: a MainDevice then computes a delay of one hop per device, as it
//! does on hardware (capture \[A\]: 140 and 295 ns).

/// Time a frame takes from one device's port 0 to the next one's (cable plus forwarding).
pub const HOP_NS: u64 = 140;

/// Where a device sits in the line, and its clock.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Position {
    /// Index in ring order.
    pub(crate) index: usize,
    /// Devices on the bus.
    pub(crate) count: usize,
    /// Local clock minus bus time: real clocks start at power-on, not together.
    pub(crate) clock_offset: u64,
    /// The link to the next device is down, so port 1 has closed its loop.
    pub(crate) next_link_lost: bool,
}

impl Position {
    /// Whether port 1 leads to another device (every device but the last, in a line).
    pub(crate) fn port1_open(&self) -> bool {
        self.index + 1 < self.count && !self.next_link_lost
    }

    /// Local time when a frame sent at bus time `t` reaches port 0.
    pub(crate) fn arrival(&self, t: u64) -> u64 {
        t + self.index as u64 * HOP_NS + self.clock_offset
    }

    /// Local time when that frame comes back on port 1.
    pub(crate) fn return_time(&self, t: u64) -> u64 {
        t + (2 * self.count as u64 - 2 - self.index as u64) * HOP_NS + self.clock_offset
    }
}

/// Receive times to latch: port 0 to 3 (None keeps what the register held) and the
/// processing unit's 64-bit time.
pub(crate) fn latch(pos: &Position, t: u64) -> ([Option<u32>; 4], u64) {
    let arrival = pos.arrival(t);
    let port1 = pos.port1_open().then(|| pos.return_time(t) as u32);
    ([Some(arrival as u32), port1, None, None], arrival)
}

/// System time = local time + offset (0x0920).
pub(crate) fn system_time(local: u64, offset: u64) -> u64 {
    local.wrapping_add(offset)
}

/// A write of `written` to the system time (FRMW from the reference clock). The ESC compares
/// it, plus the propagation delay (0x0928), with its own system time and corrects its clock.
/// Simulated clocks do not drift, so the correction is applied at once. Returns the new offset
/// and the system time difference register (bit 31 set: the local copy was ahead).
pub(crate) fn on_system_time_write(
    local: u64,
    offset: u64,
    delay: u32,
    written: u64,
) -> (u64, u32) {
    let own = system_time(local, offset);
    let target = written.wrapping_add(delay as u64);
    let diff = target.wrapping_sub(own) as i64;
    let register = if diff < 0 {
        0x8000_0000 | (diff.unsigned_abs().min(0x7FFF_FFFF) as u32)
    } else {
        diff.unsigned_abs().min(0x7FFF_FFFF) as u32
    };
    (offset.wrapping_add(diff as u64), register)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn loop_times_shrink_by_two_hops_per_device() {
        let loop_time = |index| {
            let p = Position {
                index,
                count: 3,
                clock_offset: 77,
                next_link_lost: false,
            };
            let (ports, _) = latch(&p, 1000);
            ports[1].map_or(0, |p1| p1 - ports[0].unwrap_or(0))
        };
        assert_eq!(
            (loop_time(0), loop_time(1), loop_time(2)),
            (4 * HOP_NS as u32, 2 * HOP_NS as u32, 0)
        );
    }

    #[test]
    fn a_system_time_write_aligns_the_clock() {
        let (offset, diff) = on_system_time_write(1_000, 0, 100, 5_000);
        assert_eq!(system_time(1_000, offset), 5_100);
        assert_eq!(diff, 4_100);
        let (_, diff) = on_system_time_write(1_000, 0, 0, 400);
        assert_eq!(diff, 0x8000_0000 | 600);
    }
}
