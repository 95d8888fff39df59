//! Values as the raw bits of their type, for I/O that moves them bit-exact (an EtherCAT entry of
//! any width), and the zero of each type, which outputs take in a safe state.

use crate::{IecType, Time, TypeFamily, Value};

impl Value {
    /// The zero of a type: `false`, 0, 0.0, "" or `T#0s`.
    ///
    /// ```
    /// use plc_core::{IecType, Value};
    /// assert_eq!(Value::zero(IecType::Bool), Value::Bool(false));
    /// assert_eq!(Value::zero(IecType::Lreal), Value::Real(0.0));
    /// ```
    pub fn zero(ty: IecType) -> Value {
        match ty.family() {
            TypeFamily::Bool => Value::Bool(false),
            TypeFamily::Real => Value::Real(0.0),
            TypeFamily::String => Value::Text(Default::default()),
            TypeFamily::Time => Value::Time(Time::ZERO),
            _ => Value::UInt(0),
        }
    }

    /// The value of type `ty` held in the low `bits` bits of `raw` (a signed one sign-extended
    /// from bit `bits - 1`, a REAL from its 32 bits). Numbers and bools: a STRING reads as 0.
    ///
    /// ```
    /// use plc_core::{IecType, Value};
    /// assert_eq!(Value::from_raw_bits(0xfff0, IecType::Int, 16), Value::Int(-16));
    /// ```
    pub fn from_raw_bits(raw: u64, ty: IecType, bits: u32) -> Value {
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
            TypeFamily::Time => Value::Time(Time::from_nanos(raw as i64)),
            _ => Value::UInt(raw),
        }
    }

    /// This value as the raw bits of type `ty`, the inverse of [`Value::from_raw_bits`]; the
    /// caller keeps the low bits it has room for. A number becomes a REAL or LREAL by
    /// conversion, text becomes 0.
    ///
    /// ```
    /// use plc_core::{IecType, Value};
    /// assert_eq!(Value::Int(-1).to_raw_bits(IecType::Int) & 0xffff, 0xffff);
    /// ```
    pub fn to_raw_bits(&self, ty: IecType) -> u64 {
        let real = |f: f64| match ty {
            IecType::Real => u64::from((f as f32).to_bits()),
            _ => f.to_bits(),
        };
        match (self, ty.family()) {
            (Value::Bool(b), _) => u64::from(*b),
            (Value::Int(i), TypeFamily::Real) => real(*i as f64),
            (Value::UInt(u), TypeFamily::Real) => real(*u as f64),
            (Value::Real(f), TypeFamily::Real) => real(*f),
            (Value::Int(i), _) => *i as u64,
            (Value::UInt(u), _) => *u,
            (Value::Time(t), _) => t.as_nanos() as u64,
            (Value::Real(_) | Value::Text(_), _) => 0,
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::{IecType, Value};

    fn round_trip(v: Value, ty: IecType, bits: u32) -> Value {
        Value::from_raw_bits(v.to_raw_bits(ty), ty, bits)
    }

    #[test]
    fn values_round_trip_through_raw_bits() {
        assert_eq!(round_trip(Value::Int(-3), IecType::Int, 16), Value::Int(-3));
        assert_eq!(
            round_trip(Value::Real(1.5), IecType::Real, 32),
            Value::Real(1.5)
        );
        assert_eq!(
            round_trip(Value::UInt(7), IecType::Lreal, 64),
            Value::Real(7.0)
        );
        assert_eq!(Value::from_raw_bits(1, IecType::Bool, 1), Value::Bool(true));
    }

    #[test]
    fn a_signed_value_is_extended_from_its_own_width() {
        assert_eq!(
            Value::from_raw_bits(0xfff0, IecType::Int, 16),
            Value::Int(-16)
        );
        assert_eq!(
            Value::from_raw_bits(0b1000, IecType::Sint, 4),
            Value::Int(-8)
        );
        assert_eq!(
            Value::from_raw_bits(0x7f, IecType::Sint, 8),
            Value::Int(127)
        );
        assert_eq!(
            Value::from_raw_bits(u64::MAX, IecType::Lint, 64),
            Value::Int(-1)
        );
    }

    #[test]
    fn an_unsigned_value_is_not_extended() {
        assert_eq!(
            Value::from_raw_bits(0b1010, IecType::Uint, 4),
            Value::UInt(10)
        );
        assert_eq!(
            Value::from_raw_bits(0xffff, IecType::Word, 16),
            Value::UInt(0xffff)
        );
    }

    #[test]
    fn a_negative_integer_fills_the_bits_of_its_entry() {
        assert_eq!(Value::Int(-1).to_raw_bits(IecType::Int) & 0xffff, 0xffff);
        assert_eq!(Value::Text(Default::default()).to_raw_bits(IecType::Int), 0);
    }
}
