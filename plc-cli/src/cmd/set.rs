//! `plc set <segment> name=value...`: every assignment is parsed and checked first (type,
//! range, string capacity, read-only, input, status); then all of them go to the program as one
//! request, which it applies at the start of one cycle, all or none. `plc set` waits (bounded)
//! for its answer and reports the program's refusal, naming the variable and the reason.

use super::{Error, is_path, resolve};
use plc_core::Value;
use plc_shm::DynSegment;

/// A checked assignment: what the user named, the top-level variable, the element (for a
/// value inside a structure, its leaf number) and the value.
#[derive(Clone, Debug)]
pub struct Checked {
    pub label: String,
    pub name: String,
    pub element: usize,
    pub value: Value,
}

/// Parses and checks `name=value` (or `path=value`) against the segment, as the owner would.
pub fn check(seg: &DynSegment, assignment: &str) -> Result<Checked, Error> {
    let (spec, text) = assignment
        .split_once('=')
        .ok_or_else(|| format!("`{assignment}`: write `name=value`"))?;
    if is_path(seg, spec) {
        let at = seg.locate(spec)?;
        let value =
            Value::parse(text, at.var.iec_type).map_err(|e| format!("`{}`: {e}", at.path))?;
        let value = seg.check_location(&at, value)?;
        return Ok(Checked {
            name: seg.descriptor().variables[at.index].name.clone(),
            element: at.leaf,
            label: at.path,
            value,
        });
    }
    let (_, var, element) = resolve(seg, spec.trim())?;
    let element = element.unwrap_or(0);
    // Parsed as the variable's type; every other check is the library's, as the owner makes it.
    let value = Value::parse(text, var.iec_type).map_err(|e| format!("`{}`: {e}", var.name))?;
    let value = seg.check(&var.name, element, value)?;
    Ok(Checked {
        label: spec.trim().to_string(),
        name: var.name.clone(),
        element,
        value,
    })
}

pub fn run(segment: &str, assignments: &[String]) -> Result<(), Error> {
    let seg = DynSegment::attach(segment)?;
    let checked: Vec<Checked> = assignments
        .iter()
        .map(|a| check(&seg, a))
        .collect::<Result<_, _>>()?;
    // One request of at most 64 writes; a longer list goes in requests of 64, each whole.
    for (n, part) in checked.chunks(64).enumerate() {
        let writes: Vec<(&str, usize, Value)> = part
            .iter()
            .map(|c| (c.name.as_str(), c.element, c.value))
            .collect();
        if let Err(e) = seg.write_all(&writes) {
            let done = n * 64;
            return Err(if done == 0 {
                e.to_string()
            } else {
                format!("{e}\nthe first {done} assignments were written before it")
            }
            .into());
        }
        for c in part {
            println!("{} <- {}", c.label, c.value);
        }
    }
    Ok(())
}
