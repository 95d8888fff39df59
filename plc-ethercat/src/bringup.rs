//! Bringing the bus up: scan, identity check against the description, start-up SDOs in
//! PRE-OP, PRE-OP -> SAFE-OP,
//! process data sizes checked, one exchange, OP, and the SyncManager and FMMU settings read
//! back for recovery.

use super::config::DeviceConfig;
use super::error::{EtherCatError, bus};
use super::layout::BusLayout;
use super::process_data::Group;
use super::recovery::Configured;
use super::{MAX_PDI, MAX_SUBDEVICES};
use async_io::block_on;
use ethercrab::subdevice_group::Op;
use ethercrab::{MainDevice, SubDeviceIdentity};

/// The bus in OP, and what ethercrab configured on each SubDevice (ring order).
pub(super) fn bring_up(
    md: &MainDevice<'static>,
    devices: &[DeviceConfig],
    layout: &BusLayout,
) -> Result<(Group<Op>, Vec<Configured>), EtherCatError> {
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
    // In PRE-OP, where the mailbox is up and the process data not yet configured.
    for (pos, (sd, device)) in group.iter(md).zip(devices).enumerate() {
        block_on(super::startup::write(&sd, pos, device))?;
    }
    let group = block_on(group.into_safe_op(md)).map_err(bus("going to SAFE-OP"))?;
    let reported: Vec<(usize, usize)> = group
        .iter(md)
        .map(|sd| (sd.inputs_raw().len(), sd.outputs_raw().len()))
        .collect();
    layout
        .check_sizes(&reported)
        .map_err(EtherCatError::Layout)?;
    // Outputs are zero in ethercrab's fresh PDI; one exchange before OP makes the
    // SubDevices' outputs valid, as the SyncManager watchdogs expect.
    block_on(group.tx_rx(md)).map_err(bus("the first SAFE-OP exchange"))?;
    let group = block_on(group.into_op(md)).map_err(bus("going to OP"))?;
    let mut configured = Vec::new();
    for (pos, sd) in group.iter(md).enumerate() {
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
    Ok((group, configured))
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
