//! What a variable becomes as a Sparkplug metric: its datatype (IEC types as their widths
//! say), its value in the payload, a command's value back as a [`Value`], and the deadband
//! that decides whether a change is sent.

use crate::proto::{self, MetricValue, PropertyValue, PropertyValueKind};
use plc_core::{FixedString, IecType, Time, Value};

/// The Sparkplug B 3.0 datatypes this edge node sends (the specification's numbers).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u32)]
pub enum DataType {
    /// Signed 8 bits.
    Int8 = 1,
    /// Signed 16 bits.
    Int16 = 2,
    /// Signed 32 bits.
    Int32 = 3,
    /// Signed 64 bits.
    Int64 = 4,
    /// Unsigned 8 bits.
    UInt8 = 5,
    /// Unsigned 16 bits.
    UInt16 = 6,
    /// Unsigned 32 bits.
    UInt32 = 7,
    /// Unsigned 64 bits.
    UInt64 = 8,
    /// IEEE 754 single.
    Float = 9,
    /// IEEE 754 double.
    Double = 10,
    /// Boolean.
    Boolean = 11,
    /// UTF-8 string.
    String = 12,
}

impl DataType {
    /// The Sparkplug datatype of one element of IEC type `ty`: by width, bit strings
    /// (`BYTE`..`LWORD`) as the unsigned integers of their width, `LTIME` as Int64 nanoseconds
    /// (its metric carries the property `engUnit` = `ns`).
    ///
    /// ```
    /// use plc_core::IecType;
    /// use plc_sparkplug::metric::DataType;
    /// assert_eq!(DataType::of(IecType::Sint), DataType::Int8);
    /// assert_eq!(DataType::of(IecType::Ltime), DataType::Int64);
    /// ```
    pub fn of(ty: IecType) -> DataType {
        match ty {
            IecType::Bool => DataType::Boolean,
            IecType::Sint => DataType::Int8,
            IecType::Int => DataType::Int16,
            IecType::Dint => DataType::Int32,
            IecType::Lint | IecType::Ltime => DataType::Int64,
            IecType::Usint | IecType::Byte => DataType::UInt8,
            IecType::Uint | IecType::Word => DataType::UInt16,
            IecType::Udint | IecType::Dword => DataType::UInt32,
            IecType::Ulint | IecType::Lword => DataType::UInt64,
            IecType::Real => DataType::Float,
            IecType::Lreal => DataType::Double,
            IecType::String => DataType::String,
        }
    }

    /// The specification's number.
    pub fn code(self) -> u32 {
        self as u32
    }

    /// Bits of a signed or unsigned integer type (0 for the others).
    fn int_bits(self) -> u32 {
        match self {
            DataType::Int8 | DataType::UInt8 => 8,
            DataType::Int16 | DataType::UInt16 => 16,
            DataType::Int32 | DataType::UInt32 => 32,
            DataType::Int64 | DataType::UInt64 => 64,
            _ => 0,
        }
    }
}

/// The unit of an `LTIME` metric's value.
pub const LTIME_UNIT: &str = "ns";

/// A value as the payload carries it for datatype `dt`. Signed integers are sent in two's
/// complement of their own width (Int8 -1 is 0xFF), as the specification's examples and
/// independent hosts (pysparkplug) read them.
pub fn to_payload(dt: DataType, value: &Value) -> Option<MetricValue> {
    let bits = dt.int_bits();
    Some(match (dt, value) {
        (DataType::Boolean, Value::Bool(b)) => MetricValue::BooleanValue(*b),
        (DataType::Int64, Value::Int(i)) => MetricValue::LongValue(*i as u64),
        (DataType::Int64, Value::Time(t)) => MetricValue::LongValue(t.as_nanos() as u64),
        (DataType::Int8 | DataType::Int16 | DataType::Int32, Value::Int(i)) => {
            MetricValue::IntValue((*i as u32) & (u32::MAX >> (32 - bits)))
        }
        (DataType::UInt64, Value::UInt(u)) => MetricValue::LongValue(*u),
        (DataType::UInt8 | DataType::UInt16 | DataType::UInt32, Value::UInt(u)) => {
            MetricValue::IntValue(*u as u32)
        }
        (DataType::Float, Value::Real(r)) => MetricValue::FloatValue(*r as f32),
        (DataType::Double, Value::Real(r)) => MetricValue::DoubleValue(*r),
        (DataType::String, Value::Text(t)) => MetricValue::StringValue(t.as_str().to_string()),
        // A decoder gives each IEC type its own kind: anything else is a damaged descriptor.
        _ => return None,
    })
}

/// A command's value for a metric of IEC type `ty`, or why it is refused. The value must be
/// in the field the metric's datatype says; a signed integer may come in its own width's two's
/// complement or sign-extended to 32 bits (hosts differ). Range and capacity are checked
/// afterwards by the one write path.
pub fn from_payload(ty: IecType, value: Option<&MetricValue>) -> Result<Value, String> {
    let dt = DataType::of(ty);
    let Some(value) = value else {
        return Err("the metric carries no value".into());
    };
    let wrong = || {
        format!(
            "a {dt:?} metric's value must be in the payload's {} field",
            field_of(dt)
        )
    };
    Ok(match (dt, value) {
        (DataType::Boolean, MetricValue::BooleanValue(b)) => Value::Bool(*b),
        (DataType::Int8 | DataType::Int16 | DataType::Int32, MetricValue::IntValue(u)) => {
            let bits = dt.int_bits();
            let own = if bits < 32 && *u <= u32::MAX >> (32 - bits) {
                // Two's complement of the type's width.
                let shift = 32 - bits;
                i64::from(((*u << shift) as i32) >> shift)
            } else {
                i64::from(*u as i32)
            };
            Value::Int(own)
        }
        (DataType::Int64, MetricValue::LongValue(u)) if ty == IecType::Ltime => {
            Value::Time(Time::from_nanos(*u as i64))
        }
        (DataType::Int64, MetricValue::LongValue(u)) => Value::Int(*u as i64),
        (DataType::UInt8 | DataType::UInt16 | DataType::UInt32, MetricValue::IntValue(u)) => {
            Value::UInt(u64::from(*u))
        }
        (DataType::UInt64, MetricValue::LongValue(u)) => Value::UInt(*u),
        (DataType::Float, MetricValue::FloatValue(f)) => Value::Real(f64::from(*f)),
        (DataType::Double, MetricValue::DoubleValue(f)) => Value::Real(*f),
        (DataType::String, MetricValue::StringValue(s)) => {
            if s.len() > 255 {
                return Err(format!(
                    "the string has {} bytes; a STRING holds at most 255",
                    s.len()
                ));
            }
            Value::Text(FixedString::from_str_truncate(s))
        }
        _ => return Err(wrong()),
    })
}

fn field_of(dt: DataType) -> &'static str {
    match dt {
        DataType::Int8
        | DataType::Int16
        | DataType::Int32
        | DataType::UInt8
        | DataType::UInt16
        | DataType::UInt32 => "int_value",
        DataType::Int64 | DataType::UInt64 => "long_value",
        DataType::Float => "float_value",
        DataType::Double => "double_value",
        DataType::Boolean => "boolean_value",
        DataType::String => "string_value",
    }
}

/// Whether `new` differs enough from `sent`, the value last sent, to be sent: with deadband 0
/// every change (a REAL's NaN to NaN is no change; -0 to +0 is one); above 0 a number must move
/// by more than the deadband (NaN to a number and back always count), other kinds on any
/// change.
///
/// ```
/// use plc_core::Value;
/// use plc_sparkplug::metric::exceeds_deadband;
/// assert!(!exceeds_deadband(&Value::Real(1.0), &Value::Real(1.4), 0.5));
/// assert!(exceeds_deadband(&Value::Real(1.0), &Value::Real(1.6), 0.5));
/// ```
pub fn exceeds_deadband(sent: &Value, new: &Value, deadband: f64) -> bool {
    let number = |v: &Value| match v {
        Value::Int(i) => Some(*i as f64),
        Value::UInt(u) => Some(*u as f64),
        Value::Real(r) => Some(*r),
        Value::Time(t) => Some(t.as_nanos() as f64),
        _ => None,
    };
    if deadband > 0.0
        && let (Some(a), Some(b)) = (number(sent), number(new))
    {
        if a.is_nan() || b.is_nan() {
            return a.is_nan() != b.is_nan();
        }
        return (b - a).abs() > deadband;
    }
    match (sent, new) {
        (Value::Real(a), Value::Real(b)) => {
            a.to_bits() != b.to_bits() && !(a.is_nan() && b.is_nan())
        }
        _ => sent != new,
    }
}

/// A property of datatype String.
pub fn string_property(s: &str) -> PropertyValue {
    PropertyValue {
        r#type: Some(DataType::String.code()),
        is_null: None,
        value: Some(PropertyValueKind::StringValue(s.to_string())),
    }
}

/// A property of datatype Boolean.
pub fn bool_property(b: bool) -> PropertyValue {
    PropertyValue {
        r#type: Some(DataType::Boolean.code()),
        is_null: None,
        value: Some(PropertyValueKind::BooleanValue(b)),
    }
}

/// The deadband of a variable's metric: its own reporting deadband (`#[plc(deadband = 0.5)]`,
/// a list's `"deadband"`), else the node's default (`--deadband`). A declared deadband is
/// checked to be 0 or more when it is declared; one that is not (a damaged descriptor) is
/// passed over for the default rather than sending the value every cycle.
pub fn deadband(var: &plc_shm::VarDescriptor, default: f64) -> f64 {
    var.deadband
        .filter(|d| *d >= 0.0 && d.is_finite())
        .unwrap_or(default)
}

/// The properties of a variable's metric: `description` (when it has one), `readOnly` (true
/// where no tool may write it: read-only, input or status), `quantity` (when declared), and
/// `engUnit`, the declared `unit` (`#[plc(unit = "mm")]`), or `ns` for an `LTIME` (which
/// takes no declared unit).
pub fn properties(var: &plc_shm::VarDescriptor, writable: bool) -> proto::PropertySet {
    let mut set = proto::PropertySet::default();
    let mut add = |k: &str, v: PropertyValue| {
        set.keys.push(k.to_string());
        set.values.push(v);
    };
    if !var.description.is_empty() {
        add("description", string_property(&var.description));
    }
    add("readOnly", bool_property(!writable));
    if let Some(q) = &var.quantity {
        add("quantity", string_property(q));
    }
    if let Some(unit) = &var.unit {
        add("engUnit", string_property(unit));
    } else if var.iec_type == IecType::Ltime {
        add("engUnit", string_property(LTIME_UNIT));
    }
    set
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_iec_type_has_the_datatype_of_its_width() {
        use DataType::*;
        // In the order of `IecType::ALL`.
        let expected = [
            Boolean, Int8, Int16, Int32, Int64, UInt8, UInt16, UInt32, UInt64, Float, Double,
            UInt8, UInt16, UInt32, UInt64, String, Int64,
        ];
        for (ty, dt) in IecType::ALL.iter().zip(expected) {
            assert_eq!(DataType::of(*ty), dt, "{ty:?}");
        }
        assert_eq!(Int8.code(), 1);
        assert_eq!(Double.code(), 10);
        assert_eq!(Boolean.code(), 11);
        assert_eq!(String.code(), 12);
    }

    #[test]
    fn values_go_into_the_payload_and_back_unchanged() {
        let cases = [
            (IecType::Bool, Value::Bool(true)),
            (IecType::Sint, Value::Int(-1)),
            (IecType::Sint, Value::Int(-128)),
            (IecType::Int, Value::Int(-300)),
            (IecType::Dint, Value::Int(i64::from(i32::MIN))),
            (IecType::Lint, Value::Int(i64::MIN)),
            (IecType::Usint, Value::UInt(255)),
            (IecType::Word, Value::UInt(65535)),
            (IecType::Udint, Value::UInt(u64::from(u32::MAX))),
            (IecType::Ulint, Value::UInt(u64::MAX)),
            (IecType::Real, Value::Real(1.5)),
            (IecType::Lreal, Value::Real(-2.25)),
            (
                IecType::String,
                Value::Text(FixedString::from_str_truncate("héllo")),
            ),
            (
                IecType::Ltime,
                Value::Time(Time::from_nanos(-1_500_000_000)),
            ),
        ];
        for (ty, v) in cases {
            let p = to_payload(DataType::of(ty), &v).unwrap_or_else(|| panic!("{ty:?}"));
            assert_eq!(from_payload(ty, Some(&p)), Ok(v), "{ty:?}");
        }
    }

    #[test]
    fn signed_integers_are_sent_in_their_own_width_and_read_in_either_form() {
        assert_eq!(
            to_payload(DataType::Int8, &Value::Int(-1)),
            Some(MetricValue::IntValue(0xFF))
        );
        assert_eq!(
            to_payload(DataType::Int16, &Value::Int(-2)),
            Some(MetricValue::IntValue(0xFFFE))
        );
        assert_eq!(
            from_payload(IecType::Sint, Some(&MetricValue::IntValue(0xFFFF_FFFF))),
            Ok(Value::Int(-1))
        );
        assert_eq!(
            from_payload(IecType::Int, Some(&MetricValue::IntValue(0xFFFF_FFFE))),
            Ok(Value::Int(-2))
        );
        // Neither form: passed on as a 32-bit number for the write path to refuse by range.
        assert_eq!(
            from_payload(IecType::Sint, Some(&MetricValue::IntValue(0x1234))),
            Ok(Value::Int(0x1234))
        );
    }

    #[test]
    fn a_command_in_the_wrong_field_or_without_a_value_is_refused() {
        let e = from_payload(IecType::Uint, Some(&MetricValue::StringValue("1".into())));
        assert!(e.unwrap_err().contains("int_value"));
        assert!(from_payload(IecType::Bool, None).is_err());
        let long = "x".repeat(256);
        let e = from_payload(IecType::String, Some(&MetricValue::StringValue(long)));
        assert!(e.unwrap_err().contains("at most 255"));
    }

    #[test]
    fn deadband_zero_sends_every_change_and_a_deadband_only_larger_ones() {
        let r = Value::Real;
        assert!(!exceeds_deadband(&r(1.0), &r(1.0), 0.0));
        assert!(exceeds_deadband(&r(1.0), &r(1.0000001), 0.0));
        assert!(!exceeds_deadband(&r(f64::NAN), &r(f64::NAN), 0.0));
        assert!(exceeds_deadband(&r(0.0), &r(-0.0), 0.0));
        assert!(!exceeds_deadband(&r(10.0), &r(10.5), 0.5));
        assert!(exceeds_deadband(&r(10.0), &r(10.6), 0.5));
        assert!(exceeds_deadband(&r(10.0), &r(9.4), 0.5));
        assert!(exceeds_deadband(&r(10.0), &r(f64::NAN), 0.5));
        assert!(!exceeds_deadband(&Value::Int(10), &Value::Int(12), 2.0));
        assert!(exceeds_deadband(&Value::UInt(10), &Value::UInt(13), 2.0));
        // Not numbers: every change, whatever the deadband.
        assert!(exceeds_deadband(
            &Value::Bool(false),
            &Value::Bool(true),
            5.0
        ));
        let t = |s: &str| Value::Text(FixedString::from_str_truncate(s));
        assert!(exceeds_deadband(&t("a"), &t("b"), 5.0));
        assert!(!exceeds_deadband(&t("a"), &t("a"), 0.0));
    }

    /// A descriptor of one variable of type `iec`, with a unit and a deadband if given.
    fn var(iec: IecType, unit: Option<&str>, deadband: Option<f64>) -> plc_shm::VarDescriptor {
        plc_shm::VarDescriptor {
            quantity: Some("force".into()),
            unit: unit.map(str::to_string),
            deadband,
            ..plc_shm::VarDescriptor::basic("v", iec, 0, 8)
        }
    }

    fn property<'a>(set: &'a proto::PropertySet, key: &str) -> Option<&'a PropertyValueKind> {
        let i = set.keys.iter().position(|k| k == key)?;
        set.values[i].value.as_ref()
    }

    #[test]
    fn the_declared_unit_is_the_metric_s_eng_unit_and_ltime_keeps_ns() {
        let text = |s: &str| Some(PropertyValueKind::StringValue(s.into()));
        let with_unit = properties(&var(IecType::Real, Some("kN"), None), true);
        assert_eq!(property(&with_unit, "engUnit").cloned(), text("kN"));
        assert_eq!(property(&with_unit, "quantity").cloned(), text("force"));
        let without = properties(&var(IecType::Real, None, None), true);
        assert_eq!(property(&without, "engUnit"), None);
        let ltime = properties(&var(IecType::Ltime, None, None), true);
        assert_eq!(property(&ltime, "engUnit").cloned(), text(LTIME_UNIT));
    }

    #[test]
    fn a_declared_deadband_overrides_the_node_s_default() {
        assert_eq!(deadband(&var(IecType::Real, None, Some(0.5)), 2.0), 0.5);
        assert_eq!(deadband(&var(IecType::Real, None, Some(0.0)), 2.0), 0.0);
        assert_eq!(deadband(&var(IecType::Real, None, None), 2.0), 2.0);
        // A damaged descriptor's: the default, not a value sent every cycle.
        assert_eq!(deadband(&var(IecType::Real, None, Some(-1.0)), 2.0), 2.0);
        assert_eq!(
            deadband(&var(IecType::Real, None, Some(f64::NAN)), 2.0),
            2.0
        );
    }
}
