//! One module per subcommand, and what they share: finding a variable and formatting values.

pub mod alarm_actions;
pub mod alarm_history;
pub mod alarms;
pub mod bus;
pub mod change;
pub mod change_server;
pub mod change_wire;
pub mod export;
pub mod force;
pub mod get;
pub mod import;
pub mod list;
pub mod log;
pub mod mqtt;
pub mod new;
pub mod opcua;
pub mod run;
pub mod set;
pub mod trace;
pub mod watch;
pub mod watch_marks;

use crate::display::{self, Format};
use plc_core::rules::path::segments;
use plc_shm::{DynSegment, PathLocation, PathTarget, VarDescriptor};

/// The error type of the commands: a message for the user.
pub type Error = Box<dyn std::error::Error>;

/// The period of `--rate` (per second, at most `max`, at least once an hour: the period of a
/// smaller rate does not fit a `Duration`, and nobody waits longer for one line).
pub fn period_of(rate: f64, max: f64, what: &str) -> Result<std::time::Duration, Error> {
    const MIN: f64 = 1.0 / 3600.0;
    if !(MIN..=max).contains(&rate) {
        return Err(format!(
            "--rate must be between 1/3600 (one an hour) and {max} {what} per second, not {rate}"
        )
        .into());
    }
    Ok(std::time::Duration::from_secs_f64(1.0 / rate))
}

/// A duration as an operator writes it: `30m`, `1h`, or an IEC literal such as `T#2h30m`.
pub fn duration(text: &str) -> Result<plc_core::Time, plc_core::TimeError> {
    let text = text.trim();
    if text.contains('#') {
        plc_core::Time::parse(text)
    } else {
        plc_core::Time::parse(&format!("T#{text}"))
    }
}

/// Whether `spec` names a value inside a structure or by coordinates (`axes[1].pos`,
/// `grid[1,2]`), or a structured variable: such names go through the paths of the
/// segment's descriptor.
pub fn is_path(seg: &DynSegment, spec: &str) -> bool {
    let head = spec.split(['[', '.']).next().unwrap_or(spec);
    spec.contains(['.', ','])
        || seg
            .index_of(head.trim())
            .is_some_and(|i| !seg.descriptor().variables[i].members.is_empty())
}

/// Every basic value `spec` reaches: itself, or everything inside a structure or array of
/// structures, member by member and element by element (what `plc get lift` prints).
pub fn leaves_of(seg: &DynSegment, spec: &str) -> Result<Vec<PathLocation>, Error> {
    // Bounded: a tool prints at most this many values for one name.
    const MAX: usize = 100_000;
    let mut out = Vec::new();
    let mut todo = vec![spec.trim().to_string()];
    while let Some(p) = todo.pop() {
        match seg.resolve_path(&p)? {
            PathTarget::Value(at) => out.push(*at),
            PathTarget::Group(children) => todo.extend(children.into_iter().rev()),
        }
        if out.len() + todo.len() > MAX {
            return Err(format!("`{spec}` holds more than {MAX} values: name fewer").into());
        }
    }
    Ok(out)
}

/// `name` or `name[element]` (flat or by coordinates), resolved against the segment's
/// descriptor by the one path parser.
pub fn resolve<'a>(
    seg: &'a DynSegment,
    spec: &str,
) -> Result<(usize, &'a VarDescriptor, Option<usize>), Error> {
    let parts = segments(spec)
        .collect::<Result<Vec<_>, _>>()
        .map_err(|e| format!("`{spec}`: {e}"))?;
    let [part] = parts.as_slice() else {
        return Err(format!("`{spec}`: name one variable, or one element as `name[3]`").into());
    };
    let i = seg.index_of(part.name).ok_or_else(|| {
        format!(
            "segment `{}` has no variable `{}` (`plc list {}` shows them)",
            seg.name(),
            part.name,
            seg.name()
        )
    })?;
    let var = &seg.descriptor().variables[i];
    let element = part
        .index
        .map(|index| index.flat(&var.dims))
        .transpose()
        .map_err(|e| format!("`{spec}`: {e}"))?;
    Ok((i, var, element))
}

/// A variable's value (all elements of an array, as `[a, b, c]`) from an image, as `f` asks.
pub fn show(
    seg: &DynSegment,
    image: &[u8],
    index: usize,
    element: Option<usize>,
    f: &Format,
) -> String {
    let var = &seg.descriptor().variables[index];
    let listed = element.is_none() && !var.dims.is_empty();
    let one = |e: usize| match var.value_in(image, e) {
        None => "?".to_string(),
        // In a list each string is quoted, so a comma or quote in it is not read as the list's.
        Some(v @ plc_core::Value::Text(_)) if listed => {
            format!(
                "\"{}\"",
                display::value(&v, var.iec_type, f).replace('"', "\\\"")
            )
        }
        Some(v) => display::value(&v, var.iec_type, f),
    };
    if listed {
        format!(
            "[{}]",
            (0..var.elements()).map(one).collect::<Vec<_>>().join(", ")
        )
    } else {
        one(element.unwrap_or(0))
    }
}

/// The type as users read it: `REAL`, `STRING(64)`, `REAL[3,4]`, `Axis[3]`.
pub fn type_text(var: &VarDescriptor) -> String {
    let base = if let Some(name) = &var.type_name {
        name.clone()
    } else if var.iec_type == plc_core::IecType::String {
        format!("STRING({})", var.string_capacity())
    } else {
        var.iec_type.name().to_string()
    };
    if var.dims.is_empty() {
        base
    } else {
        let dims: Vec<String> = var.dims.iter().map(|d| d.to_string()).collect();
        format!("{base}[{}]", dims.join(","))
    }
}
