//! `plc set <segment> name=value...`: every assignment is parsed and checked first (type,
//! range, string capacity, read-only, input, status); only then are they posted, in order.

use super::{Error, resolve};
use plc_core::Value;
use plc_io::shm::DynSegment;

/// A checked assignment: variable name, element, value.
pub type Checked = (String, usize, Value);

/// Parses and checks `name=value` against the segment, as the owner would.
pub fn check(seg: &DynSegment, assignment: &str) -> Result<Checked, Error> {
    let (spec, text) = assignment
        .split_once('=')
        .ok_or_else(|| format!("`{assignment}`: write `name=value`"))?;
    let (_, var, element) = resolve(seg, spec.trim())?;
    if !var.writable_from_outside() {
        let why = if var.access == plc_core::Access::ReadOnly {
            "it is read-only"
        } else if var.direction == plc_core::Direction::Input {
            "it is an input: the hardware writes it every cycle"
        } else {
            "it is a status variable: the program reports it"
        };
        return Err(format!("`{}` cannot be written: {why}", var.name).into());
    }
    let value = Value::parse(text, var.iec_type)
        .and_then(|v| v.fit(var.iec_type, var.string_capacity()))
        .map_err(|e| format!("`{}`: {e}", var.name))?;
    Ok((var.name.clone(), element.unwrap_or(0), value))
}

pub fn run(segment: &str, assignments: &[String]) -> Result<(), Error> {
    let seg = DynSegment::attach(segment)?;
    let checked: Vec<Checked> = assignments
        .iter()
        .map(|a| check(&seg, a))
        .collect::<Result<_, _>>()?;
    for (name, element, value) in checked {
        seg.write_element(&name, element, value)?;
        println!("{name} <- {value}");
    }
    Ok(())
}
