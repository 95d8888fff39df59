//! From rows to what is drawn: numbers, step lines, labels, the grouping into panels and the
//! axis ranges.

use super::{MAX_LABEL_CHARS, SHARED_SPAN, Series};
use crate::trace::Column;
use plc_core::{IecType, Value};
use std::ops::Range;

/// A panel being grouped: its members, the union of their values, the smallest range among
/// them that is not zero, whether its members have units.
struct Group {
    members: Vec<usize>,
    union: Option<(f64, f64)>,
    smallest: f64,
    with_units: bool,
}

/// Groups numeric series into panels (see the [module documentation](self)), as indices.
pub fn panels(series: &[Series]) -> Vec<Vec<usize>> {
    let mut groups: Vec<Group> = Vec::new();
    for (i, s) in series.iter().enumerate() {
        let own = extent(s.points.iter().map(|p| p.1));
        let range = own.map_or(0.0, |(lo, hi)| hi - lo);
        let with_units = s.unit.is_some();
        let fits = |g: &&mut Group| {
            // The axis names its members' units: a value without one (a counter) on an axis
            // that says "s" would read as seconds, so the two kinds never share a panel.
            if g.with_units != with_units {
                return false;
            }
            let (lo, hi) = merge(g.union, own).unwrap_or((0.0, 0.0));
            let smallest = nonzero_min(g.smallest, range);
            smallest == 0.0 || hi - lo <= SHARED_SPAN * smallest
        };
        match groups.iter_mut().find(fits) {
            Some(g) => {
                g.members.push(i);
                g.union = merge(g.union, own);
                g.smallest = nonzero_min(g.smallest, range);
            }
            None => groups.push(Group {
                members: vec![i],
                union: own,
                smallest: range,
                with_units,
            }),
        }
    }
    groups.into_iter().map(|g| g.members).collect()
}

/// The smaller of two ranges, ignoring zero (a constant is flat on any axis).
fn nonzero_min(a: f64, b: f64) -> f64 {
    match (a > 0.0, b > 0.0) {
        (true, true) => a.min(b),
        (true, false) => a,
        _ => b,
    }
}

/// The union of two extents.
fn merge(a: Option<(f64, f64)>, b: Option<(f64, f64)>) -> Option<(f64, f64)> {
    match (a, b) {
        (Some(a), Some(b)) => Some((a.0.min(b.0), a.1.max(b.1))),
        (a, b) => a.or(b),
    }
}

/// The lowest and highest of `values`.
fn extent(values: impl Iterator<Item = f64>) -> Option<(f64, f64)> {
    values.fold(None, |e, v| merge(e, Some((v, v))))
}

/// An axis range around `values` with a 5% margin, never empty: 0..1 without values, the
/// value ±10% (±1 at zero) when constant.
pub fn padded(values: impl Iterator<Item = f64>) -> Range<f64> {
    match extent(values) {
        None => 0.0..1.0,
        Some((lo, hi)) if hi > lo => {
            let pad = (hi - lo) * 0.05;
            lo - pad..hi + pad
        }
        Some((v, _)) => {
            let pad = if v == 0.0 { 1.0 } else { v.abs() * 0.1 };
            v - pad..v + pad
        }
    }
}

/// A value as a number to draw: a BOOL 0 or 1, an LTIME in seconds; none for text or a
/// non-finite real.
pub fn number(v: &Value) -> Option<f64> {
    let n = match *v {
        Value::Bool(b) => b as u8 as f64,
        Value::Int(i) => i as f64,
        Value::UInt(u) => u as f64,
        Value::Real(r) => r,
        Value::Time(t) => t.as_secs_f64(),
        Value::Text(_) => return None,
    };
    n.is_finite().then_some(n)
}

/// Samples as a step line: each value holds until the next sample.
pub fn steps(points: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let mut out = Vec::with_capacity(points.len() * 2);
    for (k, &(t, v)) in points.iter().enumerate() {
        if let Some(&(_, before)) = k.checked_sub(1).map(|j| &points[j])
            && before != v
        {
            out.push((t, before));
        }
        out.push((t, v));
    }
    out
}

/// The unit drawn: the variable's, or seconds for an LTIME.
pub fn unit(c: &Column) -> Option<&str> {
    c.unit
        .as_deref()
        .or((c.iec_type == IecType::Ltime).then_some("s"))
}

/// `path (unit)`.
pub fn label(c: &Column) -> String {
    match unit(c) {
        Some(u) => format!("{} ({u})", c.path),
        None => c.path.clone(),
    }
}

/// A label cut to [`MAX_LABEL_CHARS`], keeping its end.
pub fn shorten(label: &str) -> String {
    let n = label.chars().count();
    if n <= MAX_LABEL_CHARS {
        return label.to_string();
    }
    let tail: String = label.chars().skip(n - MAX_LABEL_CHARS + 1).collect();
    format!("…{tail}")
}
