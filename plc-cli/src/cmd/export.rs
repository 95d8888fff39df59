//! `plc export <segment> [--csv]`: the running program's declaration as a JSON variable list in
//! the JSON variable-list format (plus direction, read_only, at and dims, which plc-vars adds), or as the CSV
//! table `plc import --csv` reads.

use super::Error;
use plc_shm::DynSegment;

pub fn run(segment: &str, csv: bool) -> Result<(), Error> {
    let seg = DynSegment::attach(segment)?;
    if csv {
        print!("{}", plc_import::descriptor_to_csv(seg.descriptor())?);
    } else {
        let json = plc_import::descriptor_to_json(seg.descriptor())?;
        println!("{}", serde_json::to_string_pretty(&json)?);
    }
    Ok(())
}
