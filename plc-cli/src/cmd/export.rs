//! `plc export <segment>`: the running program's declaration as a JSON variable list in seed
//! 000's format (plus direction, read_only, at and dims, which plc-vars adds).

use super::Error;
use plc_io::shm::DynSegment;

pub fn run(segment: &str) -> Result<(), Error> {
    let seg = DynSegment::attach(segment)?;
    let json = plc_io::import::descriptor_to_json(seg.descriptor());
    println!("{}", serde_json::to_string_pretty(&json)?);
    Ok(())
}
