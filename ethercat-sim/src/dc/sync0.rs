//! The SYNC0 signal of an ESC's SYNC out unit (ET1100 datasheet, Section I "SyncSignal
//! generation", Section II registers 0x0980-0x09A7): pulses at the start time and then every
//! cycle time, on the device's local copy of the system time, so a drifting clock that the
//! loop does not hold moves its pulses with it.
//!
//! Activation 0x0981: bit 0 activates the unit, bit 1 SYNC0 (both needed for pulses), bit 3
//! activates it when the start time is written, bit 5 fires at once when the start time is
//! out of the near future, bit 6 makes the near future 2^31 ns instead of 2^63, bit 7 fires
//! one debug pulse. A start time in the past without bit 5 is never reached (a 64-bit DC
//! waits for its counter to wrap): the unit stays armed and never fires, as a terminal whose
//! MainDevice started SYNC0 too late. SYNC1 (bit 2, 0x09A4) is kept but not generated;
//! assigning the unit to the PDI (0x0980) is not modelled.

/// What a SYNC0 output has done, as a test or a device model sees it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Sync0 {
    /// Pulses since power-on.
    pub pulses: u64,
    /// Local system time (ns) of the last pulse.
    pub last_pulse: Option<u64>,
    /// Local system time (ns) of the next pulse, if one will come.
    pub next_pulse: Option<u64>,
    /// The unit is activated with SYNC0 on (0x0981 bits 0 and 1).
    pub active: bool,
}

/// Activation bits (0x0981).
const ACTIVATE: u8 = 0x01;
const SYNC0: u8 = 0x02;
const AUTO_ACTIVATE: u8 = 0x08;
const IMMEDIATE_IF_OUT_OF_NEAR_FUTURE: u8 = 0x20;
const SHORT_NEAR_FUTURE: u8 = 0x40;
const DEBUG_PULSE: u8 = 0x80;

/// The SYNC out unit's SYNC0 state.
#[derive(Clone, Debug, Default)]
pub(crate) struct SyncUnit {
    /// Start time as written (0x0990).
    start: u64,
    /// Activated with SYNC0 on.
    active: bool,
    /// The next pulse, while one will come.
    next: Option<u64>,
    /// Pulses since activation (0x0984 bit 0 is "first pulse pending").
    since_activation: u64,
    /// The start time was out of the near future at activation (0x0984 bit 2).
    out_of_near_future: bool,
    pulses: u64,
    last: Option<u64>,
    /// SYNC0 status 0x098E bit 0: set by a pulse; only the PDI clears it.
    status: bool,
}

impl SyncUnit {
    /// Pulses due up to system time `now`, every `cycle` ns (0: a single shot).
    pub(crate) fn advance(&mut self, now: u64, cycle: u32) {
        let Some(next) = self.next else { return };
        let late = now.wrapping_sub(next) as i64;
        if late < 0 {
            return;
        }
        let (count, last) = if cycle == 0 {
            self.next = None;
            (1, next)
        } else {
            let k = late as u64 / cycle as u64;
            let last = next.wrapping_add(k.wrapping_mul(cycle as u64));
            self.next = Some(last.wrapping_add(cycle as u64));
            (k + 1, last)
        };
        self.fire(count, last);
    }

    fn fire(&mut self, count: u64, last: u64) {
        self.pulses = self.pulses.saturating_add(count);
        self.since_activation = self.since_activation.saturating_add(count);
        self.last = Some(last);
        self.status = true;
    }

    /// The start time 0x0990 was written with `start` at system time `now`; `activation`
    /// is 0x0981. Returns the new activation register (auto-activation sets bit 0).
    pub(crate) fn on_start_time(&mut self, start: u64, activation: u8, now: u64) -> u8 {
        self.start = start;
        if activation & AUTO_ACTIVATE != 0 {
            let activation = activation | ACTIVATE;
            self.on_activation(activation, now);
            activation
        } else {
            activation
        }
    }

    /// Activation 0x0981 was written with `activation` at system time `now`. Returns the
    /// register as it reads afterwards (the debug pulse bit clears itself).
    pub(crate) fn on_activation(&mut self, activation: u8, now: u64) -> u8 {
        let on = activation & (ACTIVATE | SYNC0) == ACTIVATE | SYNC0;
        if on && !self.active {
            self.arm(activation, now);
        } else if !on {
            self.next = None;
        }
        self.active = on;
        if activation & DEBUG_PULSE != 0 && activation & SYNC0 != 0 {
            self.fire(1, now);
        }
        activation & !DEBUG_PULSE
    }

    fn arm(&mut self, activation: u8, now: u64) {
        self.since_activation = 0;
        let ahead = self.start.wrapping_sub(now);
        let near = if activation & SHORT_NEAR_FUTURE != 0 {
            1 << 31
        } else {
            1 << 63
        };
        self.out_of_near_future = ahead >= near;
        self.next = if !self.out_of_near_future {
            Some(self.start)
        } else if activation & IMMEDIATE_IF_OUT_OF_NEAR_FUTURE != 0 {
            Some(now)
        } else if (ahead as i64) > 0 {
            // Far future (beyond a short near future): it is reached eventually.
            Some(self.start)
        } else {
            // In the past: a 64-bit system time never comes back to it.
            None
        };
    }

    /// The activation status register 0x0984: bit 0 first SYNC0 pulse pending, bit 2 start
    /// time out of the near future.
    pub(crate) fn activation_status(&self) -> u8 {
        let pending = self.active && self.since_activation == 0;
        pending as u8 | (self.out_of_near_future as u8) << 2
    }

    /// The SYNC0 status register 0x098E.
    pub(crate) fn status(&self) -> u8 {
        self.status as u8
    }

    /// What 0x0990 reads: the next pulse while generating, otherwise the start time.
    pub(crate) fn start_time_register(&self) -> u64 {
        self.next.unwrap_or(self.start)
    }

    /// A test's view of the unit.
    pub(crate) fn snapshot(&self) -> Sync0 {
        Sync0 {
            pulses: self.pulses,
            last_pulse: self.last,
            next_pulse: self.next,
            active: self.active,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const ON: u8 = ACTIVATE | SYNC0;

    #[test]
    fn sync0_fires_at_the_start_time_and_then_every_cycle() {
        let mut u = SyncUnit::default();
        u.on_start_time(1_000_000, 0, 0);
        u.on_activation(ON, 10);
        assert_eq!(u.activation_status(), 1, "first pulse pending");
        u.advance(999_999, 250_000);
        assert_eq!(u.snapshot().pulses, 0);
        u.advance(1_000_000, 250_000);
        assert_eq!(
            (u.snapshot().pulses, u.snapshot().last_pulse),
            (1, Some(1_000_000))
        );
        u.advance(1_760_000, 250_000); // 1.25, 1.5 and 1.75 ms
        let s = u.snapshot();
        assert_eq!(
            (s.pulses, s.last_pulse, s.next_pulse),
            (4, Some(1_750_000), Some(2_000_000))
        );
        assert_eq!((u.activation_status(), u.status()), (0, 1));
        u.on_activation(0, 1_800_000);
        u.advance(5_000_000, 250_000);
        assert_eq!(u.snapshot().pulses, 4, "deactivated");
    }

    #[test]
    fn a_start_time_in_the_past_never_fires_unless_asked_to_fire_at_once() {
        let mut u = SyncUnit::default();
        u.on_start_time(1_000, 0, 0);
        u.on_activation(ON, 5_000);
        u.advance(u64::MAX / 2, 1_000);
        assert_eq!(u.snapshot().pulses, 0);
        assert_eq!(
            u.activation_status(),
            0b101,
            "pending, start out of near future"
        );

        let mut u = SyncUnit::default();
        u.on_start_time(1_000, 0, 0);
        u.on_activation(ON | IMMEDIATE_IF_OUT_OF_NEAR_FUTURE, 5_000);
        u.advance(5_000, 1_000);
        assert_eq!(u.snapshot().last_pulse, Some(5_000));
    }

    #[test]
    fn a_zero_cycle_time_gives_one_pulse_and_auto_activation_starts_on_the_start_time() {
        let mut u = SyncUnit::default();
        assert_eq!(
            u.on_start_time(100, SYNC0 | AUTO_ACTIVATE, 0),
            ON | AUTO_ACTIVATE
        );
        u.advance(1_000_000_000, 0);
        u.advance(2_000_000_000, 0);
        assert_eq!(u.snapshot().pulses, 1);
        assert_eq!(u.snapshot().next_pulse, None);
    }

    #[test]
    fn hostile_values_do_not_panic() {
        let mut u = SyncUnit::default();
        for (start, activation, now, cycle) in [
            (u64::MAX, 0xFF, 0, 1),
            (0, 0xFF, u64::MAX, u32::MAX),
            (u64::MAX - 1, ON, u64::MAX - 2, 1),
        ] {
            u.on_start_time(start, activation, now);
            u.on_activation(activation, now);
            u.advance(now.wrapping_add(u64::MAX / 2), cycle);
            u.advance(u64::MAX, cycle);
        }
    }
}
