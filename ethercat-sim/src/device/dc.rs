//! The distributed-clock registers of a device as datagrams see them: receive times latched
//! by a write of 0x0900, the system time (0x0910) and what a write of it does (the time
//! control loop), the loop's registers, and the SYNC0 unit's registers (see [`crate::dc`]).

use super::Device;
use crate::dc::{self, Params};
use crate::esc::reg;

impl Device {
    /// The local copy of the system time at bus time `at`: local time plus offset (0x0920).
    pub(crate) fn system_time_at(&self, at: u64) -> u64 {
        let offset = self.u64_at(reg::DC_SYSTEM_TIME_OFFSET);
        self.dc.clock.local(at).wrapping_add(offset)
    }

    /// Lets the SYNC0 unit fire the pulses due by the time a frame sent at bus time `now`
    /// reaches the device (before the frame's datagrams act on it).
    pub(crate) fn tick_dc(&mut self, now: u64) {
        if self.esc.dc_system_time {
            let system_time = self.system_time_at(self.position.arrival(now));
            let cycle = self.u32_at(reg::DC_SYNC0_CYCLE_TIME);
            self.dc.sync.advance(system_time, cycle);
        }
    }

    /// Brings the DC registers that change by themselves up to date before a datagram sent
    /// at bus time `now` reads `[ado, ado + len)`.
    pub(super) fn refresh_dc(&mut self, ado: usize, len: usize, now: u64) {
        let overlaps = |a: usize, n: usize| ado < a + n && a < ado + len;
        if !self.esc.dc_system_time || !overlaps(reg::DC_SYSTEM_TIME, 0xF0) {
            return;
        }
        // An ECAT read of the system time gives the local copy when the frame passed the
        // reference clock, i.e. minus the delay (datasheet, Section II, 0x0910).
        let delay = self.u32_at(reg::DC_SYSTEM_TIME_DELAY) as u64;
        let system_time = self.system_time_at(self.position.arrival(now));
        self.set_u64(reg::DC_SYSTEM_TIME, system_time.wrapping_sub(delay));
        self.mem[reg::DC_ACTIVATION_STATUS] = self.dc.sync.activation_status();
        self.mem[reg::DC_SYNC0_STATUS] = self.dc.sync.status();
        self.set_u64(reg::DC_SYNC0_START_TIME, self.dc.sync.start_time_register());
    }

    /// The ESC's reactions to a datagram sent at bus time `now` that wrote
    /// `[ado, ado + len)`; `old_system_time` is what 0x0910 held if the write touched it.
    pub(super) fn after_dc_write(
        &mut self,
        ado: usize,
        len: usize,
        now: u64,
        old_system_time: Option<u64>,
    ) {
        let touches = |a: usize| ado <= a && a < ado + len;
        if touches(reg::DC_RECEIVE_TIME) && self.esc.has_dc() {
            self.on_latch(now);
        }
        if !self.esc.dc_system_time {
            return;
        }
        let at = self.position.arrival(now);
        if let Some(old) = old_system_time {
            // System time is not set by a write: the ESC compares and corrects its clock.
            let written = self.u64_at(reg::DC_SYSTEM_TIME);
            self.set_u64(reg::DC_SYSTEM_TIME, old);
            self.on_system_time_write(written, at);
        }
        if touches(reg::DC_SPEED_COUNTER_START) || touches(reg::DC_SPEED_COUNTER_START + 1) {
            self.dc.control.reset();
            self.dc.clock.correct(at, 0, 0);
            self.show_control_registers();
        }
        let system_time = self.system_time_at(at);
        if (reg::DC_SYNC0_START_TIME..reg::DC_SYNC0_START_TIME + 8).any(touches) {
            let start = self.u64_at(reg::DC_SYNC0_START_TIME);
            let activation = self.mem[reg::DC_ACTIVATION];
            self.mem[reg::DC_ACTIVATION] =
                self.dc.sync.on_start_time(start, activation, system_time);
        }
        if touches(reg::DC_ACTIVATION) {
            let activation = self.mem[reg::DC_ACTIVATION];
            self.mem[reg::DC_ACTIVATION] = self.dc.sync.on_activation(activation, system_time);
        }
    }

    fn on_latch(&mut self, now: u64) {
        let (ports, unit) = dc::latch(&self.position, &self.dc.clock, now);
        for (i, time) in ports.iter().enumerate() {
            if let Some(t) = time {
                let a = reg::DC_RECEIVE_TIME + 4 * i;
                self.mem[a..a + 4].copy_from_slice(&t.to_le_bytes());
            }
        }
        if self.esc.dc_system_time {
            self.set_u64(reg::DC_RECEIVE_TIME_PU, unit);
        }
    }

    /// A system time `written` (the reference clock's, by FRMW) reached the device at bus
    /// time `at`: one step of the time control loop.
    fn on_system_time_write(&mut self, written: u64, at: u64) {
        let delay = self.u32_at(reg::DC_SYSTEM_TIME_DELAY) as u64;
        let own = self.system_time_at(at).wrapping_sub(delay);
        // The loop compares the lower 32 bits (datasheet, Section I, drift compensation).
        let diff = (own as u32).wrapping_sub(written as u32) as i32;
        let params = Params {
            speed_counter_start: self.u16_at(reg::DC_SPEED_COUNTER_START),
            difference_filter_depth: self.mem[reg::DC_TIME_FILTER_DEPTH],
        };
        let oscillator = self.dc.clock.oscillator(at);
        let c = self
            .dc
            .control
            .update(diff, oscillator, written as u32, params);
        self.dc.clock.correct(at, c.rate_ppt, c.slew_ps);
        self.show_control_registers();
    }

    /// Copies the loop's state into 0x092C and 0x0932.
    fn show_control_registers(&mut self) {
        let difference = self.dc.control.difference_register();
        let a = reg::DC_SYSTEM_TIME_DIFFERENCE;
        self.mem[a..a + 4].copy_from_slice(&difference.to_le_bytes());
        let speed = self.dc.control.speed_counter_diff();
        self.set_u16(reg::DC_SPEED_COUNTER_DIFF, speed);
    }
}
