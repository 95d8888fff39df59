//! Values in image bytes, by descriptor: little endian numbers, a bool is any non-zero byte,
//! strings are zero padded UTF-8 (bytes from outside that are not UTF-8 give the valid prefix).

use super::descriptor::VarDescriptor;
use plc_core::{FixedString, IecType, TypeFamily, Value};

/// Decodes element `element` of `var` from a whole image.
pub fn decode(image: &[u8], var: &VarDescriptor, element: usize) -> Option<Value> {
    if element >= var.elements() {
        return None;
    }
    let size = var.element_size();
    let start = var.offset + element * size;
    let bytes = image.get(start..start + size)?;
    let mut w = [0u8; 8];
    if var.iec_type != IecType::String {
        w[..size.min(8)].copy_from_slice(&bytes[..size.min(8)]);
    }
    Some(match var.iec_type.family() {
        TypeFamily::Bool => Value::Bool(bytes.iter().any(|&b| b != 0)),
        TypeFamily::String => {
            let end = bytes.iter().position(|&b| b == 0).unwrap_or(bytes.len());
            let text = match std::str::from_utf8(&bytes[..end]) {
                Ok(s) => s,
                Err(e) => std::str::from_utf8(&bytes[..e.valid_up_to()]).unwrap_or_default(),
            };
            Value::Text(FixedString::from_str_truncate(text))
        }
        _ => from_raw(u64::from_le_bytes(w), var.iec_type, var.iec_type.bits()),
    })
}

/// The value of type `ty` held in the low `bits` bits of `raw` (a signed one sign-extended
/// from bit `bits - 1`, a REAL from its 32 bits). Numbers and bools: a STRING reads as 0.
pub(crate) fn from_raw(raw: u64, ty: IecType, bits: u32) -> Value {
    match ty.family() {
        TypeFamily::Bool => Value::Bool(raw != 0),
        TypeFamily::SignedInt => {
            let shift = 64 - bits.clamp(1, 64);
            Value::Int(((raw << shift) as i64) >> shift)
        }
        TypeFamily::Real if ty == IecType::Real => {
            Value::Real(f64::from(f32::from_bits(raw as u32)))
        }
        TypeFamily::Real => Value::Real(f64::from_bits(raw)),
        TypeFamily::Time => Value::Time(plc_core::Time::from_nanos(raw as i64)),
        _ => Value::UInt(raw),
    }
}

/// `v` as the raw bits of type `ty`, the inverse of [`from_raw`]; the caller keeps the low
/// bits it has room for. A number becomes a REAL or LREAL by conversion, text becomes 0.
#[cfg(any(feature = "ethercat", test))]
pub(crate) fn to_raw(v: Value, ty: IecType) -> u64 {
    let real = |f: f64| match ty {
        IecType::Real => u64::from((f as f32).to_bits()),
        _ => f.to_bits(),
    };
    match (v, ty.family()) {
        (Value::Bool(b), _) => u64::from(b),
        (Value::Int(i), TypeFamily::Real) => real(i as f64),
        (Value::UInt(u), TypeFamily::Real) => real(u as f64),
        (Value::Real(f), TypeFamily::Real) => real(f),
        (Value::Int(i), _) => i as u64,
        (Value::UInt(u), _) => u,
        (Value::Time(t), _) => t.as_nanos() as u64,
        (Value::Real(_) | Value::Text(_), _) => 0,
    }
}

#[cfg(test)]
mod tests {
    use super::{from_raw, to_raw};
    use plc_core::{IecType, Value};

    #[test]
    fn values_round_trip_through_raw_bits() {
        assert_eq!(
            from_raw(to_raw(Value::Int(-3), IecType::Int), IecType::Int, 16),
            Value::Int(-3)
        );
        assert_eq!(
            from_raw(to_raw(Value::Real(1.5), IecType::Real), IecType::Real, 32),
            Value::Real(1.5)
        );
        assert_eq!(
            from_raw(to_raw(Value::UInt(7), IecType::Lreal), IecType::Lreal, 64),
            Value::Real(7.0)
        );
        assert_eq!(from_raw(1, IecType::Bool, 1), Value::Bool(true));
    }

    #[test]
    fn a_signed_value_is_extended_from_its_own_width() {
        assert_eq!(from_raw(0xfff0, IecType::Int, 16), Value::Int(-16));
        assert_eq!(from_raw(0b1000, IecType::Sint, 4), Value::Int(-8));
        assert_eq!(from_raw(0x7f, IecType::Sint, 8), Value::Int(127));
        assert_eq!(from_raw(u64::MAX, IecType::Lint, 64), Value::Int(-1));
    }

    #[test]
    fn an_unsigned_value_is_not_extended() {
        assert_eq!(from_raw(0b1010, IecType::Uint, 4), Value::UInt(10));
        assert_eq!(from_raw(0xffff, IecType::Word, 16), Value::UInt(0xffff));
    }

    #[test]
    fn a_negative_integer_fills_the_bits_of_its_entry() {
        assert_eq!(to_raw(Value::Int(-1), IecType::Int) & 0xffff, 0xffff);
        assert_eq!(to_raw(Value::Text(Default::default()), IecType::Int), 0);
    }
}
