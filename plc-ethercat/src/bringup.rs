//! Bringing the bus up: scan, identity check against the description, the DC SubDevices
//! checked (`dc`), start-up SDOs in PRE-OP, SYNC0 configured where the description asks for
//! it, PRE-OP -> SAFE-OP, process data sizes checked, one exchange, OP, and the SyncManager
//! and FMMU settings read back for recovery.

use super::config::{DcConfig, DeviceConfig};
use super::dc::DcDevice;
use super::error::{EtherCatError, bus};
use super::group::Group;
use super::layout::BusLayout;
use super::recovery::Configured;
use super::{MAX_PDI, MAX_SUBDEVICES};
use async_io::block_on;
use ethercrab::subdevice_group::{Op, SafeOp};
use ethercrab::{MainDevice, SubDeviceIdentity};
use plc_shm::BusState;
use std::time::{Duration, Instant};

/// The bus in OP.
pub(super) struct Up {
    /// The group, with SYNC0 if the description asks for it.
    pub(super) group: Group<Op>,
    /// What ethercrab configured on each SubDevice (ring order).
    pub(super) configured: Vec<Configured>,
    /// The SubDevices configured for SYNC0 (empty without `dc`).
    pub(super) dc_devices: Vec<DcDevice>,
}

/// The bus in OP, and what ethercrab configured on each SubDevice (ring order).
/// `state_transition` bounds the wait for OP of a bus with SYNC0, which is exchanged with
/// while it gets there.
pub(super) fn bring_up(
    md: &MainDevice<'static>,
    devices: &[DeviceConfig],
    layout: &BusLayout,
    dc: Option<DcConfig>,
    state_transition: Duration,
) -> Result<Up, EtherCatError> {
    let group = block_on(md.init_single_group::<MAX_SUBDEVICES, MAX_PDI>(now))
        .map_err(bus("scanning the bus (init to PRE-OP)"))?;
    let found: Vec<_> = group
        .iter(md)
        .map(|sd| (sd.name().to_owned(), sd.identity()))
        .collect();
    let problems = identity_problems(devices, &found);
    if !problems.is_empty() {
        return Err(EtherCatError::Identity(problems));
    }
    let dc_devices = super::dc::check_units(&group, md, devices)?;
    // In PRE-OP, where the mailbox is up and the process data not yet configured.
    for (pos, (sd, device)) in group.iter(md).zip(devices).enumerate() {
        block_on(super::startup::write(&sd, pos, device))?;
    }
    let group: Group<SafeOp> = match dc {
        Some(dc) if !dc_devices.is_empty() => {
            let g = super::dc::configure(group, md, &dc_devices, dc)?;
            Group::Dc(block_on(g.into_safe_op(md)).map_err(bus("going to SAFE-OP"))?)
        }
        _ => Group::Free(block_on(group.into_safe_op(md)).map_err(bus("going to SAFE-OP"))?),
    };
    let reported: Vec<(usize, usize)> = group
        .subdevices(md)
        .map(|sd| (sd.inputs_raw().len(), sd.outputs_raw().len()))
        .collect();
    layout
        .check_sizes(&reported)
        .map_err(EtherCatError::Layout)?;
    // Outputs are zero in ethercrab's fresh PDI; one exchange before OP makes the
    // SubDevices' outputs valid, as the SyncManager watchdogs expect.
    block_on(group.exchange(md)).map_err(bus("the first SAFE-OP exchange"))?;
    let group = match group {
        Group::Free(_) => block_on(group.into_op(md)).map_err(bus("going to OP"))?,
        Group::Dc(_) => into_op_exchanging(group, md, state_transition)?,
    };
    let mut configured = Vec::new();
    for (pos, sd) in group.subdevices(md).enumerate() {
        let id = sd.identity();
        let c = block_on(Configured::read(
            md,
            pos as u16,
            sd.configured_address(),
            sd.name(),
            (id.vendor_id, id.product_id),
        ))
        .map_err(bus("reading back the SyncManager and FMMU settings"))?;
        configured.push(c);
    }
    Ok(Up {
        group,
        configured,
        dc_devices,
    })
}

/// SAFE-OP -> OP for a bus with SYNC0, as ethercrab's DC example does it: OP requested, then
/// the process data exchanged on the DC time until every SubDevice is in OP (a DC SubDevice
/// checks SYNC0 and fresh process data before it enters OP), for at most `timeout`.
fn into_op_exchanging(
    group: Group<SafeOp>,
    md: &MainDevice<'static>,
    timeout: Duration,
) -> Result<Group<Op>, EtherCatError> {
    let group = block_on(group.request_into_op(md)).map_err(bus("going to OP"))?;
    let deadline = Instant::now() + timeout;
    loop {
        let answer = block_on(group.exchange(md)).map_err(bus("going to OP"))?;
        if answer.state == BusState::Op {
            return Ok(group);
        }
        if Instant::now() >= deadline {
            return Err(EtherCatError::DistributedClocks(vec![format!(
                "the bus did not reach OP within {timeout:?} of SYNC0 being configured (it is \
                 {}): a SubDevice refuses OP when SYNC0 does not suit it; check each device \
                 with `dc` supports SYNC0 at the description's `sync0` (its documentation \
                 gives the range), or remove `dc` from it",
                answer.state
            )]));
        }
        let wait = answer
            .cycle
            .map_or(Duration::from_millis(1), |c| c.next_cycle_wait);
        std::thread::sleep(wait.min(Duration::from_millis(10)));
    }
}

fn now() -> u64 {
    ethercrab::std::ethercat_now()
}

/// What differs between the SubDevices `expected` by the description and those `found` on
/// the bus (name and identity, ring order): one line per position, empty when they match.
/// The revision is compared only where the description gives one.
fn identity_problems(
    expected: &[DeviceConfig],
    found: &[(String, SubDeviceIdentity)],
) -> Vec<String> {
    let mut problems = Vec::new();
    for (pos, want) in expected.iter().enumerate() {
        match found.get(pos) {
            None => problems.push(format!(
                "position {pos}: expected `{}` ({}), found no SubDevice (the bus has {})",
                want.name,
                want.identity,
                found.len()
            )),
            Some((name, id)) => {
                let w = want.identity;
                if id.vendor_id != w.vendor
                    || id.product_id != w.product
                    || w.revision.is_some_and(|r| r != id.revision)
                {
                    problems.push(format!(
                        "position {pos}: expected `{}` ({}), found {name} (vendor {:#x}, \
                         product {:#010x}, revision {:#010x})",
                        want.name, w, id.vendor_id, id.product_id, id.revision
                    ));
                }
            }
        }
    }
    for (pos, (name, id)) in found.iter().enumerate().skip(expected.len()) {
        problems.push(format!(
            "position {pos}: found {name} (vendor {:#x}, product {:#010x}), which the \
             description does not list: add it",
            id.vendor_id, id.product_id
        ));
    }
    problems
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::devices;

    fn on_bus(d: &DeviceConfig, revision: u32) -> (String, SubDeviceIdentity) {
        let name = format!("model of {}", d.name);
        let id = SubDeviceIdentity {
            vendor_id: d.identity.vendor,
            product_id: d.identity.product,
            revision,
            serial: 0,
        };
        (name, id)
    }

    fn described() -> Vec<DeviceConfig> {
        vec![devices::ek1100("coupler"), devices::el1004("inputs")]
    }

    #[test]
    fn the_described_devices_in_ring_order_match() {
        let want = described();
        let found: Vec<_> = want.iter().map(|d| on_bus(d, 0x0011_0000)).collect();
        assert_eq!(identity_problems(&want, &found), Vec::<String>::new());
    }

    #[test]
    fn a_swapped_product_is_named_by_position() {
        let want = described();
        let found = vec![on_bus(&want[0], 0), on_bus(&devices::el2004("x"), 0)];
        let problems = identity_problems(&want, &found);
        assert_eq!(problems.len(), 1, "{problems:?}");
        assert!(
            problems[0].starts_with("position 1: expected `inputs`"),
            "{}",
            problems[0]
        );
        assert!(problems[0].contains("found model of x"), "{}", problems[0]);
    }

    #[test]
    fn a_revision_is_checked_only_where_the_description_gives_one() {
        let mut want = described();
        let found: Vec<_> = want.iter().map(|d| on_bus(d, 0x0013_0000)).collect();
        assert!(
            identity_problems(&want, &found).is_empty(),
            "no revision described"
        );
        want[1].identity.revision = Some(0x0012_0000);
        let problems = identity_problems(&want, &found);
        assert!(problems[0].contains("revision 0x00130000"), "{problems:?}");
    }

    #[test]
    fn missing_and_extra_devices_are_each_reported() {
        let want = described();
        let short = vec![on_bus(&want[0], 0)];
        assert_eq!(
            identity_problems(&want, &short),
            [format!(
                "position 1: expected `inputs` ({}), found no SubDevice (the bus has 1)",
                want[1].identity
            )]
        );
        let long = vec![
            on_bus(&want[0], 0),
            on_bus(&want[1], 0),
            on_bus(&devices::el2004("x"), 0),
        ];
        let problems = identity_problems(&want, &long);
        assert_eq!(problems.len(), 1);
        assert!(
            problems[0].starts_with("position 2: found model of x"),
            "{}",
            problems[0]
        );
        assert!(problems[0].ends_with("which the description does not list: add it"));
    }
}
