//! Retained values in the file's JSON, and the conversion of a value saved as one type for a
//! variable now of another.

use plc_core::convert::can_widen;
use plc_core::{FixedString, IecType, Time, TypeFamily, Value};

pub(super) fn to_json(v: &Value) -> serde_json::Value {
    match *v {
        Value::Bool(b) => b.into(),
        Value::Int(i) => i.into(),
        Value::UInt(u) => u.into(),
        Value::Real(r) if r.is_finite() => r.into(),
        Value::Real(r) => r.to_string().into(),
        Value::Text(t) => t.as_str().into(),
        // The IEC literal (`"LTIME#1m30s"`): exact, and readable in the file.
        Value::Time(t) => t.to_string().into(),
    }
}

/// A saved value, read as the type it was saved as: a STRING whose text is `inf` stays text, a
/// REAL saved as `"NaN"` (JSON has no NaN) is a number, an LTIME is its duration literal.
pub(super) fn from_json(v: &serde_json::Value, saved_as: IecType) -> Option<Value> {
    use serde_json::Value as J;
    Some(match (saved_as.family(), v) {
        (TypeFamily::Bool, J::Bool(b)) => Value::Bool(*b),
        (TypeFamily::SignedInt, J::Number(n)) => Value::Int(n.as_i64()?),
        (TypeFamily::UnsignedInt | TypeFamily::BitString, J::Number(n)) => Value::UInt(n.as_u64()?),
        (TypeFamily::Real, J::Number(n)) => Value::Real(n.as_f64()?),
        (TypeFamily::Real, J::String(s)) => Value::Real(s.parse::<f64>().ok()?),
        (TypeFamily::String, J::String(s)) => {
            let mut t = FixedString::<255>::new();
            t.try_set(s).ok()?;
            Value::Text(t)
        }
        (TypeFamily::Time, J::String(s)) => Value::Time(Time::parse(s).ok()?),
        _ => return None,
    })
}

/// Converts a saved value of type `from` for a variable now of type `to`, by IEC 61131-3's
/// widening (integer to wider integer, to real, REAL to LREAL). Other changes return `None`.
pub(super) fn widen(value: Value, from: IecType, to: IecType) -> Option<Value> {
    if from == to {
        return Some(value);
    }
    if !can_widen(from, to) {
        return None;
    }
    Some(match (value, to.is_real()) {
        (Value::Int(i), true) => Value::Real(i as f64),
        (Value::UInt(u), true) => Value::Real(u as f64),
        (v, _) => v,
    })
}
