//! `plc set <segment> name=value...`: every assignment is parsed and checked first (type,
//! range, string capacity, read-only, input, status); then all of them go to the program as one
//! request, which it applies at the start of one cycle, all or none. `plc set` waits (bounded)
//! for its answer and reports the program's refusal, naming the variable and the reason.

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
    let element = element.unwrap_or(0);
    // Parsed as the variable's type; every other check is the library's, as the owner makes it.
    let value = Value::parse(text, var.iec_type).map_err(|e| format!("`{}`: {e}", var.name))?;
    let value = seg.check(&var.name, element, value)?;
    Ok((var.name.clone(), element, value))
}

pub fn run(segment: &str, assignments: &[String]) -> Result<(), Error> {
    let seg = DynSegment::attach(segment)?;
    let checked: Vec<Checked> = assignments
        .iter()
        .map(|a| check(&seg, a))
        .collect::<Result<_, _>>()?;
    let writes: Vec<(&str, usize, Value)> = checked
        .iter()
        .map(|(name, element, value)| (name.as_str(), *element, *value))
        .collect();
    // One request of at most 64 writes; a longer list goes in requests of 64, each whole.
    for (n, part) in writes.chunks(64).enumerate() {
        if let Err(e) = seg.write_all(part) {
            let done = n * 64;
            return Err(if done == 0 {
                e.to_string()
            } else {
                format!("{e}\nthe first {done} assignments were written before it")
            }
            .into());
        }
        for (name, _, value) in part {
            println!("{name} <- {value}");
        }
    }
    Ok(())
}
