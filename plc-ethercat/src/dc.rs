//! Distributed clocks: which SubDevices take SYNC0 (the description's devices with `dc`),
//! checked to have a DC unit before anything is configured, SYNC0 configured through
//! ethercrab in PRE-OP, and the clocks' agreement read while the bus runs.
//!
//! ethercrab's static drift compensation ([`Options::dc_static_sync_iterations`]) runs when
//! the bus is scanned; every exchange of a DC bus then distributes the reference clock's time
//! (`tx_rx_dc`), so the clocks stay together while the program runs.
//!
//! [`Options::dc_static_sync_iterations`]: super::Options::dc_static_sync_iterations

use super::config::{DcConfig, DeviceConfig};
use super::error::{EtherCatError, bus};
use super::group::{Group, Typed};
use super::recovery::{Configured, Sync0Setup};
use async_io::block_on;
use ethercrab::error::Error as CrabError;
use ethercrab::subdevice_group::{DcConfiguration, HasDc, NoDc, Op, PreOp, PreOpPdi};
use ethercrab::{DcSupport, DcSync, MainDevice, RegisterAddress};
use std::time::Duration;

/// How long after configuration SYNC0 starts: ethercrab rounds the first pulse to a whole
/// SYNC0 period after it. 100 ms leaves room for the datagrams that configure every DC
/// SubDevice (all must have their start time before it passes: a start time in the past is
/// never reached) and for going to SAFE-OP, even on a busy machine.
pub(super) const START_DELAY: Duration = Duration::from_millis(100);

/// A SubDevice configured for SYNC0.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) struct DcDevice {
    /// Ring position.
    pub(super) position: usize,
    /// Station address ethercrab gave it.
    pub(super) address: u16,
}

/// The devices with `dc` in the description, each checked to have a DC unit with a system
/// time (ethercrab's DC support flags, then a read of its system time register, which a
/// device that announces DC but has no system-time unit does not answer). Every device
/// without one is named in one error.
pub(super) fn check_units(
    group: &Typed<PreOp, NoDc>,
    md: &MainDevice<'static>,
    devices: &[DeviceConfig],
) -> Result<Vec<DcDevice>, EtherCatError> {
    let mut found = Vec::new();
    let mut problems = Vec::new();
    for (position, (sd, d)) in group.iter(md).zip(devices).enumerate() {
        if d.dc.is_none() {
            continue;
        }
        let what = format!("position {position} (`{}`, {})", d.name, sd.name());
        let fix = "remove `dc` from it in the bus description (its outputs then follow the \
                   frame, not SYNC0), or put a SubDevice with a DC unit there";
        if sd.dc_support() == DcSupport::None {
            problems.push(format!(
                "{what} has no distributed clock (its ESC reports no DC unit): {fix}"
            ));
            continue;
        }
        match block_on(sd.register_read::<u64>(RegisterAddress::DcSystemTime)) {
            Ok(_) => found.push(DcDevice {
                position,
                address: sd.configured_address(),
            }),
            Err(CrabError::WorkingCounter { received: 0, .. }) => problems.push(format!(
                "{what} has no distributed clock system time (its ESC announces DC but does \
                 not answer the system time register 0x0910, so it cannot take SYNC0): {fix}"
            )),
            Err(e) => return Err(bus("reading the system time of the DC SubDevices")(e)),
        }
    }
    if problems.is_empty() {
        Ok(found)
    } else {
        Err(EtherCatError::DistributedClocks(problems))
    }
}

/// SYNC0 on `dc_devices` and the group's process data configured: the group in PRE-OP with
/// its process data, exchanged with `tx_rx_dc` from now on.
pub(super) fn configure(
    mut group: Typed<PreOp, NoDc>,
    md: &MainDevice<'static>,
    dc_devices: &[DcDevice],
    dc: DcConfig,
) -> Result<Typed<PreOpPdi, HasDc>, EtherCatError> {
    for (position, mut sd) in group.iter_mut(md).enumerate() {
        if dc_devices.iter().any(|d| d.position == position) {
            sd.set_dc_sync(DcSync::Sync0);
        }
    }
    let group = block_on(group.into_pre_op_pdi(md))
        .map_err(bus("configuring the process data (PRE-OP)"))?;
    block_on(group.configure_dc_sync(md, configuration(dc)))
        .map_err(bus("configuring SYNC0 of the distributed clocks"))
}

/// ethercrab's group DC settings from the description's (validated: within u32 ns).
fn configuration(dc: DcConfig) -> DcConfiguration {
    let ns = |t: plc_rules::time::Time| Duration::from_nanos(t.as_nanos().max(0) as u64);
    DcConfiguration {
        start_delay: START_DELAY,
        sync0_period: ns(dc.sync0),
        sync0_shift: ns(dc.shift),
    }
}

/// Records on each DC device's entry of `configured` (ring order) its clock and SYNC0
/// settings, so recovery can give them again to one that lost its power (see
/// `recovery::sync0`): the reference clock (ethercrab's, the first SubDevice with a DC
/// unit), the SYNC0 period and start delay used at start-up, and the propagation delay
/// ethercrab measured.
pub(super) fn record_for_recovery(
    group: &Group<Op>,
    md: &MainDevice<'static>,
    dc_devices: &[DcDevice],
    dc: DcConfig,
    configured: &mut [Configured],
) -> Result<(), EtherCatError> {
    let Some(reference) = group
        .subdevices(md)
        .find(|sd| sd.dc_support().any())
        .map(|sd| sd.configured_address())
    else {
        // check_units found DC units, so ethercrab found a reference: not reached.
        return Ok(());
    };
    // Validation keeps sync0 within u32 nanoseconds.
    let period_ns = u32::try_from(configuration(dc).sync0_period.as_nanos()).unwrap_or(u32::MAX);
    for d in dc_devices {
        let Some(entry) = configured.get_mut(d.position) else {
            continue;
        };
        let setup = block_on(Sync0Setup::read(
            md,
            d.address,
            reference,
            period_ns,
            START_DELAY,
        ))
        .map_err(bus("reading the propagation delay of the DC SubDevices"))?;
        entry.sync0 = Some(setup);
    }
    Ok(())
}

/// The largest system time difference (register 0x092C, magnitude in ns) of `devices`, or
/// `None` if one did not answer.
///
/// 0x092C holds the last difference the device's time control loop measured between the
/// system time it received and its own copy: bit 31 the sign, bits 0-30 the magnitude.
pub(super) fn largest_difference(md: &MainDevice<'static>, devices: &[DcDevice]) -> Option<u32> {
    let mut largest = 0;
    for d in devices {
        let read =
            ethercrab::Command::fprd(d.address, RegisterAddress::DcSystemTimeDifference.into());
        let raw: u32 = block_on(read.receive(md)).ok()?;
        largest = largest.max(raw & 0x7FFF_FFFF);
    }
    Some(largest)
}

/// Why `period` cannot drive a bus whose SYNC0 is `dc`'s, if it cannot: SYNC0 must be a
/// whole multiple of the cycle's period, so each SYNC0 pulse meets the same point of a cycle.
pub(super) fn period_problem(dc: DcConfig, period: Duration) -> Option<String> {
    let sync0 = u128::try_from(dc.sync0.as_nanos()).ok()?;
    let p = period.as_nanos();
    if p != 0 && sync0 % p == 0 {
        return None;
    }
    Some(format!(
        "the bus description's SYNC0 period ({} ns) is not a whole multiple of the cycle's \
         period ({p} ns): set the runtime's period to SYNC0 or a whole fraction of it (e.g. \
         `.period(Duration::from_nanos({sync0}))`), or change `sync0` in the description",
        sync0
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use plc_rules::time::Time;

    fn dc(sync0_us: i64) -> DcConfig {
        DcConfig {
            sync0: Time::from_micros(sync0_us),
            shift: Time::ZERO,
        }
    }

    #[test]
    fn sync0_must_be_a_whole_multiple_of_the_period() {
        assert_eq!(period_problem(dc(1000), Duration::from_millis(1)), None);
        assert_eq!(period_problem(dc(2000), Duration::from_micros(500)), None);
        let p = period_problem(dc(1000), Duration::from_micros(300)).unwrap();
        assert!(p.contains("(1000000 ns) is not a whole multiple"), "{p}");
        assert!(period_problem(dc(1000), Duration::ZERO).is_some());
    }

    #[test]
    fn the_configuration_starts_sync0_after_the_start_delay() {
        let c = configuration(DcConfig {
            sync0: Time::from_millis(1),
            shift: Time::from_micros(250),
        });
        assert_eq!(c.start_delay, START_DELAY);
        assert_eq!(c.sync0_period, Duration::from_millis(1));
        assert_eq!(c.sync0_shift, Duration::from_micros(250));
    }
}
