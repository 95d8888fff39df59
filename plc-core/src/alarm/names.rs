//! What tools call an alarm, and the bools a path suppresses alarms by: both need the
//! variables' description, so they are resolved once, when a program starts.

use super::decl::{AlarmDecl, SuppressWhen};
use crate::{IecType, VarInfo};
use plc_rules::path::{self, Visit};
use std::string::String;
use std::vec::Vec;

/// Each alarm's name: the path of the value it watches, as `plc get` takes it
/// (`door`, `limits[1]`, `stations[2].door`), in the order of `decls`. An alarm whose value
/// the variables do not have (a table of another program) is named by its numbers.
///
/// ```
/// use plc_core::{GlobalMemory, PlcStruct};
/// #[derive(PlcStruct, Debug, Clone)]
/// struct Station {
///     #[plc(alarm = "Door open")]
///     door: bool,
/// }
/// #[derive(GlobalMemory, Debug, Clone)]
/// struct Gm {
///     #[plc(alarm = "Overtravel")]
///     limits: [bool; 2],
///     stations: [Station; 3],
/// }
/// let names = plc_core::alarm::alarm_paths(Gm::VARIABLES, Gm::ALARMS);
/// assert_eq!(names, ["limits[0]", "limits[1]", "stations[0].door", "stations[1].door", "stations[2].door"]);
/// ```
pub fn alarm_paths(vars: &[VarInfo], decls: &[AlarmDecl]) -> Vec<String> {
    // Each basic variable or member once, by where its leaves start.
    let mut basics: Vec<(usize, usize, usize, String, &[usize])> = Vec::new();
    path::walk(vars, |v| {
        if let Visit::Basic(b) = v {
            let n = b.node.elements();
            basics.push((b.index, b.first_leaf, n, b.path, b.node.dims));
        }
    });
    decls
        .iter()
        .map(|d| {
            basics
                .iter()
                .find(|(i, first, n, _, _)| *i == d.index && (*first..first + n).contains(&d.leaf))
                .map_or_else(
                    || std::format!("#{}.{}", d.index, d.leaf),
                    |(_, first, _, p, dims)| {
                        if dims.is_empty() {
                            p.clone()
                        } else {
                            std::format!("{p}[{}]", path::coordinates(d.leaf - first, dims))
                        }
                    },
                )
        })
        .collect()
}

/// The basic value (variable index and leaf) whose bool suppresses an alarm, `None` if
/// nothing does; an error naming the path if it names no bool (a `suppress_when` path into a
/// structure or an array, which only the running program's variables can say).
pub fn resolve_suppress(
    vars: &[VarInfo],
    suppress: SuppressWhen,
) -> Result<Option<(usize, usize)>, String> {
    match suppress {
        SuppressWhen::Never => Ok(None),
        SuppressWhen::At { index, leaf } => Ok(Some((index, leaf))),
        SuppressWhen::Path(p) => match path::locate(vars, p) {
            Ok(f) if f.node.iec_type == IecType::Bool => Ok(Some((f.index, f.leaf))),
            Ok(f) => Err(std::format!(
                "`suppress_when = \"{p}\"` names a {}, not a bool",
                f.node.iec_type
            )),
            Err(e) => Err(std::format!("`suppress_when = \"{p}\"`: {e}")),
        },
    }
}
