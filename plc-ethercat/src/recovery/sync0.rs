//! A DC SubDevice's clock and SYNC0 set up again after it lost its power, through the same
//! registers ethercrab writes at start-up (ETG.1000.4 / Beckhoff ESC datasheet, Section II,
//! 0x0900-0x09A7).
//!
//! A restarted ESC has its system time offset (0x0920) and propagation delay (0x0928) at 0,
//! so its copy of the system time is its own free-running clock, and its SYNC out unit is
//! off. Before it goes back to SAFE-OP (where a device that needs SYNC0 checks it):
//! - the offset: ethercrab's start-up way, a broadcast write of 0x0900 latches every
//!   clock's time at the same frame (0x0918), so the reference clock's system time at that
//!   moment minus the restarted device's own is the offset it needs, however loaded the
//!   machine (no two separate reads to line up). The delay ethercrab measured at start-up
//!   is written back: the cables did not change. The cyclic FRMW of every exchange then
//!   holds the clock, as for the others;
//! - SYNC0 as `configure_dc_sync` does it: 0x0981 off, the start time (0x0990) on a whole
//!   SYNC0 period of the reference's system time [`START_DELAY`](crate::dc) ahead, so its
//!   pulses fall on the same instants as the other devices', the cycle time (0x09A0), then
//!   0x0981 = SYNC0 + cyclic operation. 0x0980 (the SYNC unit assigned to EtherCAT) is
//!   0 at power-on and not written, as ethercrab does not.

use ethercrab::error::Error as CrabError;
use ethercrab::{Command, MainDevice, RegisterAddress};
use std::time::Duration;

// The registers, by ethercrab's names for them.
const RECEIVE_TIME_PORT0: u16 = RegisterAddress::DcTimePort0 as u16;
const RECEIVE_TIME_PU: u16 = RegisterAddress::DcReceiveTime as u16;
const SYSTEM_TIME: u16 = RegisterAddress::DcSystemTime as u16;
const SYSTEM_TIME_OFFSET: u16 = RegisterAddress::DcSystemTimeOffset as u16;
const SYSTEM_TIME_DELAY: u16 = RegisterAddress::DcSystemTimeTransmissionDelay as u16;
const SYNC_ACTIVATION: u16 = RegisterAddress::DcSyncActive as u16;
const SYNC0_START_TIME: u16 = RegisterAddress::DcSyncStartTime as u16;
const SYNC0_CYCLE_TIME: u16 = RegisterAddress::DcSync0CycleTime as u16;

/// 0x0981: cyclic operation (bit 0) and SYNC0 (bit 1), ethercrab's `SYNC0_ACTIVATE |
/// CYCLIC_OP_ENABLE`.
const SYNC0_ON: u8 = 0x03;

/// What a DC SubDevice had at start-up, to give it again after a power loss.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Sync0Setup {
    /// Station address of the DC reference clock (the first SubDevice with a DC unit).
    pub(crate) reference: u16,
    /// The SYNC0 period (ns), the description's `sync0`.
    pub(crate) period_ns: u32,
    /// How long SYNC0 starts after it is configured (ethercrab's `start_delay`).
    pub(crate) start_delay: Duration,
    /// The propagation delay ethercrab wrote to 0x0928 at start-up (ns).
    pub(crate) delay_ns: u32,
}

impl Sync0Setup {
    /// Reads the propagation delay ethercrab wrote to the SubDevice at `address`.
    pub(crate) async fn read(
        md: &MainDevice<'_>,
        address: u16,
        reference: u16,
        period_ns: u32,
        start_delay: Duration,
    ) -> Result<Self, CrabError> {
        let delay_ns: u32 = Command::fprd(address, SYSTEM_TIME_DELAY)
            .receive(md)
            .await?;
        Ok(Sync0Setup {
            reference,
            period_ns,
            start_delay,
            delay_ns,
        })
    }

    /// Whether the SubDevice at `address` has its SYNC0 running (0x0981 with SYNC0 and
    /// cyclic operation on).
    pub(crate) async fn is_active(md: &MainDevice<'_>, address: u16) -> Result<bool, CrabError> {
        let activation: u8 = Command::fprd(address, SYNC_ACTIVATION).receive(md).await?;
        Ok(activation & SYNC0_ON == SYNC0_ON)
    }

    /// Gives the SubDevice at `address` its clock offset, delay and SYNC0 again (see the
    /// module documentation).
    pub(crate) async fn restore(&self, md: &MainDevice<'_>, address: u16) -> Result<(), CrabError> {
        // The offset: both clocks latched by the same frame.
        Command::bwr(RECEIVE_TIME_PORT0)
            .ignore_wkc()
            .send(md, 0u32)
            .await?;
        let reference_latched: u64 = Command::fprd(self.reference, RECEIVE_TIME_PU)
            .receive(md)
            .await?;
        let reference_offset: u64 = Command::fprd(self.reference, SYSTEM_TIME_OFFSET)
            .receive(md)
            .await?;
        let own_latched: u64 = Command::fprd(address, RECEIVE_TIME_PU).receive(md).await?;
        let offset = offset_for(reference_latched, reference_offset, own_latched);
        Command::fpwr(address, SYSTEM_TIME_OFFSET)
            .send(md, offset)
            .await?;
        Command::fpwr(address, SYSTEM_TIME_DELAY)
            .send(md, self.delay_ns)
            .await?;

        // SYNC0, as at start-up.
        Command::fpwr(address, SYNC_ACTIVATION)
            .send(md, 0u8)
            .await?;
        let now: u64 = Command::fprd(self.reference, SYSTEM_TIME)
            .receive(md)
            .await?;
        let start = start_time(now, self.start_delay, self.period_ns).ok_or(CrabError::Internal)?;
        Command::fpwr(address, SYNC0_START_TIME)
            .send(md, start)
            .await?;
        Command::fpwr(address, SYNC0_CYCLE_TIME)
            .send(md, self.period_ns)
            .await?;
        Command::fpwr(address, SYNC_ACTIVATION)
            .send(md, SYNC0_ON)
            .await?;
        Ok(())
    }
}

/// The system time offset that gives a clock which latched `own` the system time of the
/// reference, which latched `reference` with offset `reference_offset` at the same frame.
/// Wrapping, as the ESC's 64-bit arithmetic.
fn offset_for(reference: u64, reference_offset: u64, own: u64) -> u64 {
    reference.wrapping_add(reference_offset).wrapping_sub(own)
}

/// The first SYNC0 pulse: `start_delay` after the system time `now`, rounded down to a whole
/// `period_ns` as ethercrab rounds it (so the pulses fall on the instants of the other
/// devices', whose start times were rounded the same way). `None` for a zero period.
fn start_time(now: u64, start_delay: Duration, period_ns: u32) -> Option<u64> {
    let period = u64::from(period_ns);
    let delay = u64::try_from(start_delay.as_nanos()).unwrap_or(u64::MAX);
    let t = now.saturating_add(delay);
    t.checked_div(period).map(|n| n * period)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_offset_gives_the_restarted_clock_the_reference_time() {
        // The reference read 5_000 with offset 1_000_000 (system time 1_005_000); the
        // restarted clock read 200 at the same frame.
        let offset = offset_for(5_000, 1_000_000, 200);
        assert_eq!(200u64.wrapping_add(offset), 1_005_000);
        // A restarted clock ahead of the reference's: the offset wraps, as in the ESC.
        let offset = offset_for(5_000, 0, 9_000);
        assert_eq!(9_000u64.wrapping_add(offset), 5_000);
    }

    #[test]
    fn sync0_starts_on_a_whole_period_after_the_delay() {
        let delay = Duration::from_millis(100);
        assert_eq!(
            start_time(1_234_567, delay, 1_000_000),
            Some(101_000_000),
            "rounded down to the period, still 99.8 ms ahead"
        );
        assert_eq!(start_time(0, delay, 1_000_000), Some(100_000_000));
        assert_eq!(start_time(5, delay, 0), None, "no period, no start");
        assert_eq!(
            start_time(u64::MAX - 10, delay, 1_000_000),
            Some(u64::MAX / 1_000_000 * 1_000_000),
            "no overflow"
        );
    }
}
