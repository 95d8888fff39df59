//! `plc get <segment> <name>...`: one consistent snapshot, every name from it.

use super::{Error, resolve, show};
use plc_io::shm::DynSegment;

pub fn run(segment: &str, names: &[String]) -> Result<(), Error> {
    let seg = DynSegment::attach(segment)?;
    let resolved: Vec<_> = names
        .iter()
        .map(|n| resolve(&seg, n))
        .collect::<Result<_, _>>()?;
    let image = seg.snapshot_bytes()?;
    for (spec, (i, _, element)) in names.iter().zip(resolved) {
        println!("{spec} = {}", show(&seg, &image, i, element));
    }
    Ok(())
}
