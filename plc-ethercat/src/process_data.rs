//! Process data: the linked variables of the struct to and from each SubDevice's bytes.

use super::group::{Exchanged, Group};
use super::layout::{read_bits, write_bits};
use super::resolve::Binding;
use async_io::block_on;
use ethercrab::MainDevice;
use ethercrab::error::Error as CrabError;
use ethercrab::subdevice_group::HasPdi;
use plc_core::Value;
use plc_core::memory::Memory;

/// The linked outputs of `gm` into the process data, then one exchange of the frame.
pub(super) fn cycle<S: HasPdi, T: Memory>(
    g: &Group<S>,
    md: &MainDevice<'static>,
    gm: &T,
    outputs: &[Binding],
) -> Result<Exchanged, CrabError> {
    write_outputs(g, md, gm, outputs);
    #[cfg(feature = "cycle-probe")]
    return plc_runtime::probe::bus_exchange(|| block_on(g.exchange(md)));
    #[cfg(not(feature = "cycle-probe"))]
    block_on(g.exchange(md))
}

/// Runs of bindings on one SubDevice: resolution groups them by device, so each device's
/// process data is locked once per cycle, not once per variable.
fn per_device(bindings: &[Binding]) -> impl Iterator<Item = (usize, &[Binding])> {
    bindings
        .chunk_by(|a, b| a.entry.device == b.entry.device)
        .map(|run| (run[0].entry.device, run))
}

fn write_outputs<S: HasPdi, T: Memory>(
    g: &Group<S>,
    md: &MainDevice<'static>,
    gm: &T,
    outputs: &[Binding],
) {
    for (dev, run) in per_device(outputs) {
        // A device index comes from the layout ethercrab's sizes were checked against.
        let Ok(sd) = g.subdevice(md, dev) else {
            continue;
        };
        let mut out = sd.outputs_raw_mut();
        for b in run {
            if let Some(v) = gm.try_get(b.var, 0) {
                let e = &b.entry;
                write_bits(&mut out, e.bit_offset, e.bits, v.to_raw_bits(e.iec_type));
            }
        }
    }
}

/// The linked inputs from the process data into `gm`.
pub(super) fn copy_inputs<S: HasPdi, T: Memory>(
    g: &Group<S>,
    md: &MainDevice<'static>,
    gm: &mut T,
    inputs: &[Binding],
) {
    for (dev, run) in per_device(inputs) {
        let Ok(sd) = g.subdevice(md, dev) else {
            continue;
        };
        let data = sd.inputs_raw();
        for b in run {
            let e = &b.entry;
            let raw = read_bits(&data, e.bit_offset, e.bits);
            // Resolution checked that the entry's type widens to the variable's, so `set`
            // accepts the value.
            let _ = gm.set(b.var, 0, Value::from_raw_bits(raw, e.iec_type, e.bits));
        }
    }
}

/// Every linked input of `gm` to its zero.
pub(super) fn zero_inputs<T: Memory>(gm: &mut T, inputs: &[Binding]) {
    for b in inputs {
        // The zero of the variable's own type is always in range.
        let _ = gm.set(b.var, 0, Value::zero(b.var_type));
    }
}

/// Every output byte of the group to zero.
pub(super) fn zero_outputs<S: HasPdi>(g: &Group<S>, md: &MainDevice<'static>) {
    for sd in g.subdevices(md) {
        sd.outputs_raw_mut().fill(0);
    }
}

#[cfg(test)]
mod tests {
    use super::per_device;
    use crate::layout::BusLayout;
    use crate::resolve::resolve;
    use crate::{BusConfig, devices};

    #[derive(plc_core::GlobalMemory, Clone)]
    struct Gm {
        #[plc(link = "ethercat.left.output1", direction = "output")]
        a: bool,
        #[plc(link = "ethercat.left.output3", direction = "output")]
        b: bool,
        #[plc(link = "ethercat.right.output2", direction = "output")]
        c: bool,
    }

    #[test]
    fn bindings_come_in_one_run_per_device() {
        let bus = BusConfig {
            devices: vec![
                devices::ek1100("coupler"),
                devices::el2004("left"),
                devices::el2004("right"),
            ],
        };
        let bindings = resolve::<Gm>(&BusLayout::new(&bus)).unwrap();
        let runs: Vec<(usize, Vec<usize>)> = per_device(&bindings)
            .map(|(dev, run)| (dev, run.iter().map(|b| b.var).collect()))
            .collect();
        assert_eq!(runs, [(1, vec![0, 1]), (2, vec![2])]);
    }

    #[test]
    fn no_bindings_give_no_runs() {
        assert_eq!(per_device(&[]).count(), 0);
    }
}
