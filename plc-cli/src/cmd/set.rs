//! `plc set <segment> name=value...`: every assignment is parsed and checked first (type,
//! range, string capacity, read-only, input, status); then all of them go to the program as one
//! request, which it applies at the start of one cycle, all or none. `plc set` waits (bounded)
//! for its answer and reports the program's refusal, naming the variable and the reason.

use super::{Error, is_path, resolve};
use crate::display::{self, Format};
use plc_core::Value;
use plc_core::write::{Checked, Write};
use plc_shm::DynSegment;

/// A checked assignment: what the user named and the write as the owner will apply it.
#[derive(Clone, Debug)]
pub struct Assignment {
    pub label: String,
    pub write: Checked,
    /// The type of the value written, to print it as that type.
    pub iec_type: plc_core::IecType,
}

/// Parses `name=value` (or `path=value`) and checks it against the segment with the one write
/// check the owner makes again; the value is parsed as the variable's type.
pub fn check(seg: &DynSegment, assignment: &str) -> Result<Assignment, Error> {
    let (spec, text) = assignment
        .split_once('=')
        .ok_or_else(|| format!("`{assignment}`: write `name=value`"))?;
    let (label, index, leaf, iec_type) = if is_path(seg, spec) {
        let at = seg.locate(spec)?;
        (at.path, at.index, at.leaf, at.var.iec_type)
    } else {
        let (index, var, element) = resolve(seg, spec.trim())?;
        (
            spec.trim().to_string(),
            index,
            element.unwrap_or(0),
            var.iec_type,
        )
    };
    let value = Value::parse(text, iec_type).map_err(|e| format!("`{label}`: {e}"))?;
    let write = seg.check_write(Write { index, leaf, value })?;
    Ok(Assignment {
        label,
        write,
        iec_type,
    })
}

pub fn run(segment: &str, assignments: &[String]) -> Result<(), Error> {
    let seg = DynSegment::attach(segment)?;
    let checked: Vec<Assignment> = assignments
        .iter()
        .map(|a| check(&seg, a))
        .collect::<Result<_, _>>()?;
    // One request of at most MAX_WRITES writes; a longer list goes in several, each whole.
    let most = plc_shm::protocol::MAX_WRITES;
    for (n, part) in checked.chunks(most).enumerate() {
        let writes: Vec<Checked> = part.iter().map(|a| a.write).collect();
        if let Err(e) = seg.write_checked(&writes) {
            let done = n * most;
            return Err(if done == 0 {
                e.to_string()
            } else {
                format!("{e}\nthe first {done} assignments were written before it")
            }
            .into());
        }
        for a in part {
            let value = display::value(&a.write.write().value, a.iec_type, &Format::default());
            println!("{} <- {value}", display::escape_text(&a.label));
        }
    }
    Ok(())
}
