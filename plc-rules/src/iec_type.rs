//! The IEC 61131-3 elementary types plc-vars supports, with the Rust equivalents of the JSON variable-list format.

use core::fmt;
use core::str::FromStr;

/// An IEC 61131-3 elementary type.
///
/// A Rust integer maps to the integer family (`u16` is `UINT`); the bit-string family (`BYTE`,
/// `WORD`, `DWORD`, `LWORD`) shares the Rust types of the unsigned integers and is chosen with
/// `#[plc(iec_type = "WORD")]`.
///
/// | IEC | Rust | bits | | IEC | Rust | bits |
/// |---|---|---|---|---|---|---|
/// | BOOL | bool | 1 | | REAL | f32 | 32 |
/// | SINT / INT / DINT / LINT | i8 / i16 / i32 / i64 | 8..64 | | LREAL | f64 | 64 |
/// | USINT / UINT / UDINT / ULINT | u8 / u16 / u32 / u64 | 8..64 | | STRING | `FixedString<N>` | 8·N |
/// | BYTE / WORD / DWORD / LWORD | u8 / u16 / u32 / u64 | 8..64 | | LTIME | [`Time`](crate::Time) | 64 |
///
/// `LTIME` is IEC 61131-3's long duration, a signed 64-bit count of nanoseconds. plc-vars has
/// no 32-bit `TIME` type: `"TIME"` does not parse (declare `LTIME`), though `T#` and `TIME#`
/// literals are read as `LTIME` values (IEC 61131-3 widens `TIME` to `LTIME`).
///
/// ```
/// use plc_rules::IecType;
/// assert_eq!("dint".parse::<IecType>(), Ok(IecType::Dint));
/// assert_eq!("u8".parse::<IecType>(), Ok(IecType::Usint));
/// assert_eq!(IecType::Word.rust_name(), "u16");
/// assert_eq!(IecType::Lreal.to_string(), "LREAL");
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(into = "&'static str"))]
pub enum IecType {
    /// Boolean, `bool`.
    Bool,
    /// 8-bit signed integer, `i8`.
    Sint,
    /// 16-bit signed integer, `i16`.
    Int,
    /// 32-bit signed integer, `i32`.
    Dint,
    /// 64-bit signed integer, `i64`.
    Lint,
    /// 8-bit unsigned integer, `u8`.
    Usint,
    /// 16-bit unsigned integer, `u16`.
    Uint,
    /// 32-bit unsigned integer, `u32`.
    Udint,
    /// 64-bit unsigned integer, `u64`.
    Ulint,
    /// 32-bit IEEE 754 float, `f32`.
    Real,
    /// 64-bit IEEE 754 float, `f64`.
    Lreal,
    /// 8-bit bit string, `u8`.
    Byte,
    /// 16-bit bit string, `u16`.
    Word,
    /// 32-bit bit string, `u32`.
    Dword,
    /// 64-bit bit string, `u64`.
    Lword,
    /// Fixed-capacity UTF-8 text, `FixedString<N>`.
    String,
    /// Duration, a signed 64-bit count of nanoseconds, [`Time`](crate::Time): from
    /// [`Time::MIN`](crate::Time::MIN) to [`Time::MAX`](crate::Time::MAX), about ±292 years
    /// (not an integer: [`int_range`](Self::int_range) is `None`).
    Ltime,
}

/// The family of an [`IecType`], which decides what a value of it may become.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TypeFamily {
    /// `BOOL`.
    Bool,
    /// `SINT`, `INT`, `DINT`, `LINT`.
    SignedInt,
    /// `USINT`, `UINT`, `UDINT`, `ULINT`.
    UnsignedInt,
    /// `REAL`, `LREAL`.
    Real,
    /// `BYTE`, `WORD`, `DWORD`, `LWORD`.
    BitString,
    /// `STRING`.
    String,
    /// `LTIME`.
    Time,
}

impl IecType {
    /// Every type, in declaration order.
    pub const ALL: [IecType; 17] = [
        IecType::Bool,
        IecType::Sint,
        IecType::Int,
        IecType::Dint,
        IecType::Lint,
        IecType::Usint,
        IecType::Uint,
        IecType::Udint,
        IecType::Ulint,
        IecType::Real,
        IecType::Lreal,
        IecType::Byte,
        IecType::Word,
        IecType::Dword,
        IecType::Lword,
        IecType::String,
        IecType::Ltime,
    ];

    /// The IEC name in upper case, e.g. `"DINT"`.
    pub const fn name(self) -> &'static str {
        match self {
            IecType::Bool => "BOOL",
            IecType::Sint => "SINT",
            IecType::Int => "INT",
            IecType::Dint => "DINT",
            IecType::Lint => "LINT",
            IecType::Usint => "USINT",
            IecType::Uint => "UINT",
            IecType::Udint => "UDINT",
            IecType::Ulint => "ULINT",
            IecType::Real => "REAL",
            IecType::Lreal => "LREAL",
            IecType::Byte => "BYTE",
            IecType::Word => "WORD",
            IecType::Dword => "DWORD",
            IecType::Lword => "LWORD",
            IecType::String => "STRING",
            IecType::Ltime => "LTIME",
        }
    }

    /// The Rust type of the JSON variable-list format's type table (`"FixedString"` for
    /// `STRING`, `"Time"` for `LTIME`).
    pub const fn rust_name(self) -> &'static str {
        match self {
            IecType::Bool => "bool",
            IecType::Sint => "i8",
            IecType::Int => "i16",
            IecType::Dint => "i32",
            IecType::Lint => "i64",
            IecType::Usint | IecType::Byte => "u8",
            IecType::Uint | IecType::Word => "u16",
            IecType::Udint | IecType::Dword => "u32",
            IecType::Ulint | IecType::Lword => "u64",
            IecType::Real => "f32",
            IecType::Lreal => "f64",
            IecType::String => "FixedString",
            IecType::Ltime => "Time",
        }
    }

    /// The type's width in bits; 1 for `BOOL` and 0 for `STRING`, whose width is its capacity.
    pub const fn bits(self) -> u32 {
        match self {
            IecType::Bool => 1,
            IecType::Sint | IecType::Usint | IecType::Byte => 8,
            IecType::Int | IecType::Uint | IecType::Word => 16,
            IecType::Dint | IecType::Udint | IecType::Dword | IecType::Real => 32,
            IecType::Lint | IecType::Ulint | IecType::Lword | IecType::Lreal | IecType::Ltime => 64,
            IecType::String => 0,
        }
    }

    /// Bytes one value takes in an image (`BOOL` takes a byte; 0 for `STRING`).
    pub const fn image_size(self) -> usize {
        match self {
            IecType::Bool => 1,
            other => (other.bits() / 8) as usize,
        }
    }

    /// The type's family.
    pub const fn family(self) -> TypeFamily {
        match self {
            IecType::Bool => TypeFamily::Bool,
            IecType::Sint | IecType::Int | IecType::Dint | IecType::Lint => TypeFamily::SignedInt,
            IecType::Usint | IecType::Uint | IecType::Udint | IecType::Ulint => {
                TypeFamily::UnsignedInt
            }
            IecType::Real | IecType::Lreal => TypeFamily::Real,
            IecType::Byte | IecType::Word | IecType::Dword | IecType::Lword => {
                TypeFamily::BitString
            }
            IecType::String => TypeFamily::String,
            IecType::Ltime => TypeFamily::Time,
        }
    }

    /// Whether values are whole numbers stored in a Rust integer (integers and bit strings):
    /// what a bit-mapped bool's source must be.
    pub const fn is_integer(self) -> bool {
        matches!(
            self.family(),
            TypeFamily::SignedInt | TypeFamily::UnsignedInt | TypeFamily::BitString
        )
    }

    /// Whether the type is `REAL` or `LREAL`.
    pub const fn is_real(self) -> bool {
        matches!(self, IecType::Real | IecType::Lreal)
    }

    /// Whether the integer range is signed (only meaningful for [`is_integer`](Self::is_integer)).
    pub const fn is_signed(self) -> bool {
        matches!(self.family(), TypeFamily::SignedInt)
    }

    /// The smallest and largest whole number the type holds, for integer types.
    ///
    /// ```
    /// use plc_rules::IecType;
    /// assert_eq!(IecType::Sint.int_range(), Some((-128, 127)));
    /// assert_eq!(IecType::Real.int_range(), None);
    /// ```
    pub const fn int_range(self) -> Option<(i128, i128)> {
        if !self.is_integer() {
            return None;
        }
        let bits = self.bits();
        Some(if self.is_signed() {
            (-(1i128 << (bits - 1)), (1i128 << (bits - 1)) - 1)
        } else {
            (0, (1i128 << bits) - 1)
        })
    }

    /// The type an unannotated Rust type maps to (`u16` is `UINT`, never `WORD`; `Time` is
    /// `LTIME`). Exact case: `time` is no Rust type here.
    pub fn from_rust_name(name: &str) -> Option<IecType> {
        Some(match name {
            "bool" => IecType::Bool,
            "i8" => IecType::Sint,
            "i16" => IecType::Int,
            "i32" => IecType::Dint,
            "i64" => IecType::Lint,
            "u8" => IecType::Usint,
            "u16" => IecType::Uint,
            "u32" => IecType::Udint,
            "u64" => IecType::Ulint,
            "f32" => IecType::Real,
            "f64" => IecType::Lreal,
            "string" | "FixedString" => IecType::String,
            "Time" => IecType::Ltime,
            _ => return None,
        })
    }

    /// Whether `self` can declare a variable stored in Rust type `other`'s storage: same width and
    /// storage class. This is the `iec_type = "WORD"` check: `u16` may be `UINT` or `WORD`.
    pub const fn same_storage(self, other: IecType) -> bool {
        let a = self.rust_name().as_bytes();
        let b = other.rust_name().as_bytes();
        if a.len() != b.len() {
            return false;
        }
        let mut i = 0;
        while i < a.len() {
            if a[i] != b[i] {
                return false;
            }
            i += 1;
        }
        true
    }
}

impl fmt::Display for IecType {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(self.name())
    }
}

/// The error of parsing an [`IecType`]: the text named no supported type.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct UnknownType;

impl fmt::Display for UnknownType {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(
            "unknown type: use an IEC name (BOOL, SINT..LINT, USINT..ULINT, REAL, LREAL, \
             BYTE..LWORD, STRING, LTIME) or a Rust name (bool, i8..i64, u8..u64, f32, f64, \
             string); for a duration use LTIME, 64-bit nanoseconds (there is no 32-bit TIME)",
        )
    }
}

#[cfg(feature = "std")]
impl std::error::Error for UnknownType {}

impl FromStr for IecType {
    type Err = UnknownType;

    /// Parses an IEC or Rust name, case-insensitively.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let s = s.trim();
        for t in IecType::ALL {
            if s.eq_ignore_ascii_case(t.name()) {
                return Ok(t);
            }
        }
        const RUST: [(&str, IecType); 12] = [
            ("bool", IecType::Bool),
            ("i8", IecType::Sint),
            ("i16", IecType::Int),
            ("i32", IecType::Dint),
            ("i64", IecType::Lint),
            ("u8", IecType::Usint),
            ("u16", IecType::Uint),
            ("u32", IecType::Udint),
            ("u64", IecType::Ulint),
            ("f32", IecType::Real),
            ("f64", IecType::Lreal),
            ("fixedstring", IecType::String),
        ];
        RUST.iter()
            .find(|(n, _)| s.eq_ignore_ascii_case(n))
            .map(|&(_, t)| t)
            .ok_or(UnknownType)
    }
}

impl From<IecType> for &'static str {
    fn from(t: IecType) -> Self {
        t.name()
    }
}

impl TryFrom<&str> for IecType {
    type Error = UnknownType;
    fn try_from(s: &str) -> Result<Self, Self::Error> {
        s.parse()
    }
}

/// Deserializes from the name as [`FromStr`] reads it. A visitor, not `try_from = "&str"`: that
/// needs a string borrowed from the input and so fails for owned or escaped strings
/// (`serde_json::from_value`, `"DI\u004eT"`); `String` would need an allocator.
#[cfg(feature = "serde")]
impl<'de> serde::Deserialize<'de> for IecType {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Visitor;
        impl serde::de::Visitor<'_> for Visitor {
            type Value = IecType;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("an IEC 61131-3 or Rust type name such as \"DINT\" or \"i32\"")
            }
            fn visit_str<E: serde::de::Error>(self, v: &str) -> Result<IecType, E> {
                v.parse()
                    .map_err(|_| E::invalid_value(serde::de::Unexpected::Str(v), &self))
            }
        }
        deserializer.deserialize_str(Visitor)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn json_format_table_maps_rust_names_to_iec_types() {
        let table = [
            ("bool", IecType::Bool, 1),
            ("u8", IecType::Usint, 8),
            ("i8", IecType::Sint, 8),
            ("u16", IecType::Uint, 16),
            ("i16", IecType::Int, 16),
            ("u32", IecType::Udint, 32),
            ("i32", IecType::Dint, 32),
            ("u64", IecType::Ulint, 64),
            ("i64", IecType::Lint, 64),
            ("f32", IecType::Real, 32),
            ("f64", IecType::Lreal, 64),
        ];
        for (rust, iec, bits) in table {
            assert_eq!(rust.parse::<IecType>(), Ok(iec), "{rust}");
            assert_eq!(IecType::from_rust_name(rust), Some(iec));
            assert_eq!(iec.bits(), bits);
            assert_eq!(iec.rust_name(), rust);
        }
        assert_eq!("string".parse::<IecType>(), Ok(IecType::String));
        // The bit-string family shares storage with the unsigned integers (the JSON variable-list format: u8 = USINT / BYTE).
        assert!(IecType::Byte.same_storage(IecType::Usint));
        assert!(IecType::Lword.same_storage(IecType::Ulint));
        assert!(!IecType::Word.same_storage(IecType::Udint));
        assert!(!IecType::Word.same_storage(IecType::Int));
    }

    #[test]
    fn parsing_is_case_insensitive_and_display_is_the_iec_name() {
        for t in IecType::ALL {
            assert_eq!(t.name().parse::<IecType>(), Ok(t));
            assert_eq!(t.name().to_ascii_lowercase().parse::<IecType>(), Ok(t));
            assert_eq!(std::format!("{t}"), t.name());
        }
        assert_eq!("I32".parse::<IecType>(), Ok(IecType::Dint));
        // One duration type, LTIME; TIME (32-bit in many PLCs) is not silently made 64-bit.
        assert_eq!("TIME".parse::<IecType>(), Err(UnknownType));
        assert_eq!("ltime".parse::<IecType>(), Ok(IecType::Ltime));
        assert_eq!(IecType::from_rust_name("Time"), Some(IecType::Ltime));
        assert_eq!(IecType::Ltime.family(), TypeFamily::Time);
        assert_eq!(
            (IecType::Ltime.bits(), IecType::Ltime.image_size()),
            (64, 8)
        );
        assert_eq!(IecType::Ltime.int_range(), None);
        assert!(!IecType::Ltime.same_storage(IecType::Lint));
        assert_eq!("".parse::<IecType>(), Err(UnknownType));
    }

    #[test]
    fn integer_ranges_follow_the_width_and_sign() {
        assert_eq!(IecType::Ulint.int_range(), Some((0, u64::MAX as i128)));
        assert_eq!(
            IecType::Lint.int_range(),
            Some((i64::MIN as i128, i64::MAX as i128))
        );
        assert_eq!(IecType::Word.int_range(), Some((0, 65535)));
        assert_eq!(IecType::Bool.int_range(), None);
    }

    #[cfg(feature = "serde")]
    #[test]
    fn deserializes_from_owned_and_borrowed_strings() {
        use serde::Deserialize;
        use serde::de::value::{
            BorrowedStrDeserializer, Error, StrDeserializer, StringDeserializer,
        };
        let owned = StringDeserializer::<Error>::new("dint".into());
        assert_eq!(IecType::deserialize(owned), Ok(IecType::Dint));
        let transient = StrDeserializer::<Error>::new("u16");
        assert_eq!(IecType::deserialize(transient), Ok(IecType::Uint));
        let borrowed = BorrowedStrDeserializer::<Error>::new("LREAL");
        assert_eq!(IecType::deserialize(borrowed), Ok(IecType::Lreal));
        let unknown = IecType::deserialize(StringDeserializer::<Error>::new("INTEGER".into()));
        let message = unknown.unwrap_err().to_string();
        assert!(
            message.contains("\"INTEGER\"") && message.contains("DINT"),
            "{message}"
        );
    }
}
