//! `PlcType`: the Rust types a variable may have, and how each is stored in the image.
//!
//! The derive relies on this trait instead of reading type names, so a field declared through a
//! type alias (`type Word = u16;`) is checked and laid out exactly like one written `u16`.

use crate::{FixedString, IecType, Time, Value, ValueError};
use zerocopy::byteorder::little_endian as le;
use zerocopy::{FromBytes, Immutable, IntoBytes, KnownLayout, Unaligned};

/// Why an element could not be set.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ElementError {
    /// The element index is beyond the array.
    OutOfRange {
        /// The number of elements.
        len: usize,
    },
    /// The value does not fit.
    Value(ValueError),
}

impl core::fmt::Display for ElementError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            ElementError::OutOfRange { len } => write!(
                f,
                "element out of range: the variable has {len} element{} (0..{len})",
                if *len == 1 { "" } else { "s" }
            ),
            ElementError::Value(error) => core::fmt::Display::fmt(error, f),
        }
    }
}

// No `source`: Display already says what the inner `ValueError` says (as `SetError` does), and
// an error chain would print it twice.
#[cfg(feature = "std")]
impl std::error::Error for ElementError {}

pub(crate) mod sealed {
    /// Only plc-core's types and the derive's structures are `PlcType`s.
    pub trait Sealed {}
}

/// A supported variable type: `bool`, `u8`..`u64`, `i8`..`i64`, `f32`, `f64`, `FixedString<N>`,
/// a structure (`#[derive(PlcStruct)]`), or an array of these (the derive limits arrays to 3 dimensions and 65,535 items, the variable-editor rules).
///
/// ```
/// use plc_core::{PlcType, IecType};
/// assert_eq!(<[[f32; 4]; 3] as PlcType>::IEC_TYPE, IecType::Real);
/// assert_eq!(<[[f32; 4]; 3] as PlcType>::DIMS, &[3, 4]);
/// assert_eq!(<[[f32; 4]; 3] as PlcType>::ELEMENTS, 12);
/// ```
#[diagnostic::on_unimplemented(
    message = "`{Self}` is not a supported PLC variable type",
    label = "not a PLC variable type",
    note = "use bool, u8, u16, u32, u64, i8, i16, i32, i64, f32, f64, plc_core::FixedString<N>, \
            plc_core::Time, a #[derive(PlcStruct)] structure, or an array of these with up to 3 \
            dimensions"
)]
// `Clone`, not `Copy`: a structure (`#[derive(PlcStruct)]`) need only be `Clone`, as a
// GlobalMemory struct is; the image conversions work through references.
pub trait PlcType: Clone + sealed::Sealed + 'static {
    /// IEC type of one element, as the Rust type maps it (a `u16` is `UINT`).
    const IEC_TYPE: IecType;
    /// Number of array dimensions, 0 for a scalar.
    const RANK: usize;
    /// Array dimensions, outermost first; empty for a scalar.
    const DIMS: &'static [usize];
    /// Number of elements, 1 for a scalar.
    const ELEMENTS: usize;
    /// String capacity of one element in bytes, 0 for other types.
    const STRING_CAPACITY: usize;
    /// Basic values in one value of this type (its *leaves*, which `get_element` and
    /// `set_element` number): 1 for a scalar or string, one per element of an array of basic
    /// values; for a structure its members' leaves in declaration order, for an array of
    /// structures its elements' in row-major order.
    const LEAVES: usize = Self::ELEMENTS;
    /// A structure's members (`#[derive(PlcStruct)]`), offsets from the structure's start;
    /// for an array of structures, one element's; empty for basic types.
    const MEMBERS: &'static [crate::VarInfo] = &[];
    /// A structure's type name (`"Axis"`, `"TON"`); `None` for basic types.
    const TYPE_NAME: Option<&'static str> = None;
    /// Structure levels: 0 for a basic type, 1 plus its deepest member's for a structure.
    const DEPTH: usize = 0;
    /// The value whose stored form is all zero bytes (what `from_repr` gives for them), as a
    /// constant: a declaration starts from it in one copy, where a struct literal of every
    /// field's conversion made one function per declaration that the optimiser took minutes
    /// and gigabytes over for 10,000 variables.
    #[doc(hidden)]
    const __ZERO: Self;
    /// How the value is stored in the image: alignment 1, little endian, no padding.
    type Repr: FromBytes + IntoBytes + KnownLayout + Immutable + Unaligned + Copy;
    /// The stored form.
    fn to_repr(&self) -> Self::Repr;
    /// The value back from its stored form (a bool is `true` for any byte but 0).
    fn from_repr(repr: &Self::Repr) -> Self;
    /// Leaf `element` (for basic types the row-major element) as a [`Value`], `None` if out
    /// of range.
    fn get_element(&self, element: usize) -> Option<Value>;
    /// Sets element `element` from a [`Value`], checked against `ty` (the declared IEC type,
    /// which may be a bit string of the same width). Nothing changes on error.
    fn set_element(
        &mut self,
        element: usize,
        value: Value,
        ty: IecType,
    ) -> Result<(), ElementError>;

    // The derive's bit mapping and located access go through these total methods (no-ops or
    // errors for types they do not apply to), so a wrong type behind an alias is reported by
    // exactly one spanned `const` assertion instead of a cascade of unmet trait bounds.

    /// A structure's bit-mapped bools from their source words, recursively; nothing for basic
    /// types.
    #[doc(hidden)]
    #[inline(always)]
    fn __unpack_bits(&mut self) {}
    /// A structure's bit-mapped bools into their source words, recursively.
    #[doc(hidden)]
    #[inline(always)]
    fn __pack_bits(&mut self) {}
    /// Sets a structure's members to their declared initial values, recursively (a value
    /// starts zeroed); nothing for basic types.
    #[doc(hidden)]
    #[inline(always)]
    fn __init(&mut self) {}

    /// Bit `n` of an integer; `false` for other types.
    #[doc(hidden)]
    #[inline(always)]
    fn __bit(self, n: u32) -> bool {
        let _ = n;
        false
    }
    /// The integer with bit `n` set to `v`; other types unchanged.
    #[doc(hidden)]
    #[inline(always)]
    fn __with_bit(self, n: u32, v: bool) -> Self {
        let _ = (n, v);
        self
    }
    /// An integer's bits, zero-extended to 64; 0 for other types.
    #[doc(hidden)]
    #[inline(always)]
    fn __bits(self) -> u64 {
        0
    }
    /// The integer with the bits of `mask` taken from `bits`, the others unchanged; other
    /// types unchanged.
    #[doc(hidden)]
    #[inline(always)]
    fn __with_bits(self, mask: u64, bits: u64) -> Self {
        let _ = (mask, bits);
        self
    }
    /// A bool's value; `false` for other types.
    #[doc(hidden)]
    #[inline(always)]
    fn __to_bit(self) -> bool {
        false
    }
    /// Sets a bool; other types unchanged.
    #[doc(hidden)]
    #[inline(always)]
    fn __set_from_bit(&mut self, bit: bool) {
        let _ = bit;
    }
    /// Reads a located scalar from a process image; an error for strings and arrays.
    #[doc(hidden)]
    fn __read_located<B: AsRef<[u8]>>(
        &mut self,
        image: &crate::ProcessImage<B>,
        address: &crate::IecAddress,
        order: crate::ByteOrder,
        unaligned: bool,
    ) -> Result<(), crate::ProcessImageError> {
        let _ = (image, order, unaligned);
        Err(crate::ProcessImageError::SizeMismatch {
            address: *address,
            expected: address.size,
        })
    }
    /// Writes a located scalar into a process image; an error for strings and arrays.
    #[doc(hidden)]
    fn __write_located<B: AsRef<[u8]> + AsMut<[u8]>>(
        self,
        image: &mut crate::ProcessImage<B>,
        address: &crate::IecAddress,
        order: crate::ByteOrder,
        unaligned: bool,
    ) -> Result<(), crate::ProcessImageError> {
        let _ = (image, order, unaligned);
        Err(crate::ProcessImageError::SizeMismatch {
            address: *address,
            expected: address.size,
        })
    }
}

/// Located access for the scalars that a process image address can hold.
macro_rules! located {
    () => {
        fn __read_located<B: AsRef<[u8]>>(
            &mut self,
            image: &crate::ProcessImage<B>,
            address: &crate::IecAddress,
            order: crate::ByteOrder,
            unaligned: bool,
        ) -> Result<(), crate::ProcessImageError> {
            *self = image.read_with(address, order, unaligned)?;
            Ok(())
        }
        fn __write_located<B: AsRef<[u8]> + AsMut<[u8]>>(
            self,
            image: &mut crate::ProcessImage<B>,
            address: &crate::IecAddress,
            order: crate::ByteOrder,
            unaligned: bool,
        ) -> Result<(), crate::ProcessImageError> {
            image.write_with(address, self, order, unaligned)
        }
    };
}

/// `set_element` of a scalar: only element 0, the value fitted to `ty` (and a string's
/// `capacity`); nothing changes on error.
fn set_scalar<T: PlcScalar>(
    scalar: &mut T,
    element: usize,
    value: Value,
    ty: IecType,
    capacity: usize,
) -> Result<(), ElementError> {
    if element != 0 {
        return Err(ElementError::OutOfRange { len: 1 });
    }
    *scalar = T::from_fitted(value.fit(ty, capacity).map_err(ElementError::Value)?);
    Ok(())
}

/// A scalar (non-array) variable type.
pub trait PlcScalar: PlcType {
    /// The value as a [`Value`].
    fn to_value(&self) -> Value;
    /// The typed value from a [`Value`] already checked with [`Value::fit`].
    fn from_fitted(value: Value) -> Self;
}

macro_rules! scalar {
    ($($kind:ident $t:ty => $iec:ident, $repr:ty, $variant:ident, $as:ty;)*) => {$(
        impl sealed::Sealed for $t {}
        impl PlcType for $t {
            const IEC_TYPE: IecType = IecType::$iec;
            const RANK: usize = 0;
            const DIMS: &'static [usize] = &[];
            const ELEMENTS: usize = 1;
            const STRING_CAPACITY: usize = 0;
            const __ZERO: Self = 0 as $t;
            type Repr = $repr;
            #[inline(always)]
            fn to_repr(&self) -> $repr {
                <$repr>::from(*self)
            }
            #[inline(always)]
            fn from_repr(repr: &$repr) -> Self {
                <$t>::from(*repr)
            }
            fn get_element(&self, element: usize) -> Option<Value> {
                (element == 0).then(|| self.to_value())
            }
            fn set_element(&mut self, element: usize, value: Value, ty: IecType)
                -> Result<(), ElementError> {
                set_scalar(self, element, value, ty, 0)
            }
            located!();
            bits!($kind $t);
        }
        impl PlcScalar for $t {
            #[inline]
            fn to_value(&self) -> Value {
                Value::$variant(*self as $as)
            }
            #[inline]
            fn from_fitted(value: Value) -> Self {
                match value {
                    Value::Int(v) => v as $t,
                    Value::UInt(v) => v as $t,
                    Value::Real(v) => v as $t,
                    _ => <$t>::default(),
                }
            }
        }
    )*};
}

/// Bit access for integers; nothing for floats.
macro_rules! bits {
    (float $t:ty) => {};
    (int $t:ty) => {
        #[inline(always)]
        fn __bit(self, n: u32) -> bool {
            (self >> n) & 1 != 0
        }
        #[inline(always)]
        fn __with_bit(self, n: u32, v: bool) -> Self {
            (self & !(1 << n)) | ((v as $t) << n)
        }
        #[inline(always)]
        fn __bits(self) -> u64 {
            (self as u64) & (u64::MAX >> (64 - <$t>::BITS))
        }
        #[inline(always)]
        fn __with_bits(self, mask: u64, bits: u64) -> Self {
            (((self as u64) & !mask) | (bits & mask)) as $t
        }
    };
}

scalar! {
    int i8 => Sint, i8, Int, i64;
    int i16 => Int, le::I16, Int, i64;
    int i32 => Dint, le::I32, Int, i64;
    int i64 => Lint, le::I64, Int, i64;
    int u8 => Usint, u8, UInt, u64;
    int u16 => Uint, le::U16, UInt, u64;
    int u32 => Udint, le::U32, UInt, u64;
    int u64 => Ulint, le::U64, UInt, u64;
    float f32 => Real, le::F32, Real, f64;
    float f64 => Lreal, le::F64, Real, f64;
}

impl sealed::Sealed for bool {}
impl PlcType for bool {
    const IEC_TYPE: IecType = IecType::Bool;
    const RANK: usize = 0;
    const DIMS: &'static [usize] = &[];
    const ELEMENTS: usize = 1;
    const STRING_CAPACITY: usize = 0;
    const __ZERO: Self = false;
    type Repr = u8;
    #[inline(always)]
    fn to_repr(&self) -> u8 {
        *self as u8
    }
    #[inline(always)]
    fn from_repr(repr: &u8) -> Self {
        *repr != 0
    }
    fn get_element(&self, element: usize) -> Option<Value> {
        (element == 0).then_some(Value::Bool(*self))
    }
    fn set_element(
        &mut self,
        element: usize,
        value: Value,
        ty: IecType,
    ) -> Result<(), ElementError> {
        set_scalar(self, element, value, ty, 0)
    }
    #[inline(always)]
    fn __to_bit(self) -> bool {
        self
    }
    #[inline(always)]
    fn __set_from_bit(&mut self, bit: bool) {
        *self = bit;
    }
    located!();
}
impl PlcScalar for bool {
    fn to_value(&self) -> Value {
        Value::Bool(*self)
    }
    fn from_fitted(value: Value) -> Self {
        matches!(value, Value::Bool(true))
    }
}

impl<const N: usize> sealed::Sealed for FixedString<N> {}
impl<const N: usize> PlcType for FixedString<N> {
    const IEC_TYPE: IecType = IecType::String;
    const RANK: usize = 0;
    const DIMS: &'static [usize] = &[];
    const ELEMENTS: usize = 1;
    const STRING_CAPACITY: usize = N;
    const __ZERO: Self = FixedString::__zeroed();
    type Repr = FixedString<N>;
    #[inline(always)]
    fn to_repr(&self) -> Self {
        *self
    }
    #[inline(always)]
    fn from_repr(repr: &Self) -> Self {
        *repr
    }
    fn get_element(&self, element: usize) -> Option<Value> {
        (element == 0).then(|| self.to_value())
    }
    fn set_element(
        &mut self,
        element: usize,
        value: Value,
        ty: IecType,
    ) -> Result<(), ElementError> {
        set_scalar(self, element, value, ty, N)
    }
}
impl<const N: usize> PlcScalar for FixedString<N> {
    fn to_value(&self) -> Value {
        Value::Text(FixedString::from_str_truncate(self.as_str()))
    }
    fn from_fitted(value: Value) -> Self {
        match value {
            Value::Text(t) => FixedString::from_str_truncate(t.as_str()),
            _ => FixedString::new(),
        }
    }
}

/// `LTIME`: stored as its nanoseconds, a little-endian `i64`.
impl sealed::Sealed for Time {}
impl PlcType for Time {
    const IEC_TYPE: IecType = IecType::Ltime;
    const RANK: usize = 0;
    const DIMS: &'static [usize] = &[];
    const ELEMENTS: usize = 1;
    const STRING_CAPACITY: usize = 0;
    const __ZERO: Self = Time::ZERO;
    type Repr = le::I64;
    #[inline(always)]
    fn to_repr(&self) -> le::I64 {
        le::I64::new(self.as_nanos())
    }
    #[inline(always)]
    fn from_repr(repr: &le::I64) -> Self {
        Time::from_nanos(repr.get())
    }
    fn get_element(&self, element: usize) -> Option<Value> {
        (element == 0).then_some(Value::Time(*self))
    }
    fn set_element(
        &mut self,
        element: usize,
        value: Value,
        ty: IecType,
    ) -> Result<(), ElementError> {
        set_scalar(self, element, value, ty, 0)
    }
    located!();
}
impl PlcScalar for Time {
    fn to_value(&self) -> Value {
        Value::Time(*self)
    }
    fn from_fitted(value: Value) -> Self {
        match value {
            Value::Time(t) => t,
            _ => Time::ZERO,
        }
    }
}

impl<T: PlcType, const N: usize> sealed::Sealed for [T; N] {}
impl<T: PlcType, const N: usize> PlcType for [T; N] {
    const IEC_TYPE: IecType = T::IEC_TYPE;
    const __ZERO: Self = [T::__ZERO; N];
    const RANK: usize = T::RANK + 1;
    const DIMS: &'static [usize] = {
        // Dimensions beyond the third are cut here; the derive rejects such arrays with a
        // spanned error (the variable-editor rules: at most 3 dimensions).
        const fn dim<T: PlcType>(i: usize) -> usize {
            if i < T::DIMS.len() { T::DIMS[i] } else { 0 }
        }
        match T::RANK {
            0 => &[N],
            1 => &[N, dim::<T>(0)],
            _ => &[N, dim::<T>(0), dim::<T>(1)],
        }
    };
    const ELEMENTS: usize = N * T::ELEMENTS;
    const STRING_CAPACITY: usize = T::STRING_CAPACITY;
    const LEAVES: usize = N * T::LEAVES;
    const MEMBERS: &'static [crate::VarInfo] = T::MEMBERS;
    const TYPE_NAME: Option<&'static str> = T::TYPE_NAME;
    const DEPTH: usize = T::DEPTH;
    type Repr = [T::Repr; N];
    #[inline(always)]
    fn to_repr(&self) -> Self::Repr {
        core::array::from_fn(|i| self[i].to_repr())
    }
    #[inline(always)]
    fn from_repr(repr: &Self::Repr) -> Self {
        core::array::from_fn(|i| T::from_repr(&repr[i]))
    }
    fn get_element(&self, element: usize) -> Option<Value> {
        let inner = T::LEAVES;
        self.get(element / inner)?.get_element(element % inner)
    }
    fn set_element(
        &mut self,
        element: usize,
        value: Value,
        ty: IecType,
    ) -> Result<(), ElementError> {
        let inner = T::LEAVES;
        let len = Self::LEAVES;
        let Some(item) = self.get_mut(element / inner) else {
            return Err(ElementError::OutOfRange { len });
        };
        item.set_element(element % inner, value, ty)
            .map_err(|e| match e {
                ElementError::OutOfRange { .. } => ElementError::OutOfRange { len },
                other => other,
            })
    }
    #[inline(always)]
    fn __unpack_bits(&mut self) {
        // Optimised away for arrays of basic values, whose elements do nothing.
        if T::DEPTH > 0 {
            self.iter_mut().for_each(T::__unpack_bits);
        }
    }
    #[inline(always)]
    fn __pack_bits(&mut self) {
        if T::DEPTH > 0 {
            self.iter_mut().for_each(T::__pack_bits);
        }
    }
    #[inline(always)]
    fn __init(&mut self) {
        if T::DEPTH > 0 {
            self.iter_mut().for_each(T::__init);
        }
    }
}

/// An integer type that can be the source word of bit-mapped bools (the JSON variable-list format: `u8`..`u64`,
/// `i8`..`i64`).
#[diagnostic::on_unimplemented(
    message = "`{Self}` cannot be the source of bit-mapped bools",
    label = "not an integer",
    note = "a `source` must be an integer: u8, u16, u32, u64, i8, i16, i32 or i64"
)]
pub trait BitSource: PlcScalar {
    /// Width in bits.
    const BITS: u32;
    /// Bit `n` of the value.
    fn bit(self, n: u32) -> bool;
    /// The value with bit `n` set to `v`, other bits unchanged (branch free).
    fn with_bit(self, n: u32, v: bool) -> Self;
}

macro_rules! bit_source {
    ($($t:ty),*) => {$(
        impl BitSource for $t {
            const BITS: u32 = <$t>::BITS;
            #[inline(always)]
            fn bit(self, n: u32) -> bool {
                self.__bit(n)
            }
            #[inline(always)]
            fn with_bit(self, n: u32, v: bool) -> Self {
                self.__with_bit(n, v)
            }
        }
    )*};
}
bit_source!(u8, u16, u32, u64, i8, i16, i32, i64);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arrays_report_dims_and_elements() {
        type A = [[[u8; 2]; 3]; 4];
        assert_eq!(A::DIMS, &[4, 3, 2]);
        assert_eq!((A::RANK, A::ELEMENTS), (3, 24));
        assert_eq!(<u8 as PlcType>::DIMS, &[] as &[usize]);
        assert_eq!(<[FixedString<8>; 2]>::STRING_CAPACITY, 8);
    }

    #[test]
    fn row_major_elements() {
        let mut a = [[0u16; 3]; 2];
        a.set_element(4, Value::UInt(9), IecType::Uint).unwrap();
        assert_eq!(a[1][1], 9);
        assert_eq!(a.get_element(4), Some(Value::UInt(9)));
        assert_eq!(a.get_element(6), None);
        assert_eq!(
            a.set_element(6, Value::UInt(1), IecType::Uint),
            Err(ElementError::OutOfRange { len: 6 })
        );
        assert!(matches!(
            a.set_element(0, Value::Int(-1), IecType::Uint),
            Err(ElementError::Value(_))
        ));
        assert_eq!(a[0][0], 0);
    }

    #[test]
    fn repr_is_little_endian_and_unaligned() {
        let r = 0x1234u16.to_repr();
        assert_eq!(r.as_bytes(), &[0x34, 0x12]);
        assert_eq!(core::mem::align_of::<<[f64; 3] as PlcType>::Repr>(), 1);
        assert!(bool::from_repr(&7));
        assert_eq!(f64::from_repr(&(-2.5f64).to_repr()), -2.5);
    }

    #[test]
    fn element_errors_explain_themselves() {
        let out = ElementError::OutOfRange { len: 6 };
        assert_eq!(
            out.to_string(),
            "element out of range: the variable has 6 elements (0..6)"
        );
        let value = [0u8; 1]
            .set_element(0, Value::Int(-1), IecType::Usint)
            .unwrap_err();
        assert_eq!(value.to_string(), "out of range for USINT (0..=255)");
        #[cfg(feature = "std")]
        {
            let boxed: Box<dyn std::error::Error> = Box::new(value);
            assert_eq!(boxed.to_string(), "out of range for USINT (0..=255)");
        }
    }

    #[test]
    fn a_time_is_its_nanoseconds_in_little_endian() {
        let t = Time::from_nanos(-2);
        assert_eq!(t.to_repr().as_bytes(), &(-2i64).to_le_bytes());
        assert_eq!(Time::from_repr(&t.to_repr()), t);
        let mut times = [Time::ZERO; 2];
        times
            .set_element(1, Value::Time(Time::from_secs(5)), IecType::Ltime)
            .unwrap();
        assert_eq!(times.get_element(1), Some(Value::Time(Time::from_secs(5))));
        assert!(times.set_element(0, Value::Int(5), IecType::Ltime).is_err());
        assert_eq!(<Time as PlcType>::IEC_TYPE, IecType::Ltime);
    }

    #[test]
    fn bit_source_keeps_other_bits() {
        assert_eq!(0b1010u8.with_bit(0, true), 0b1011);
        assert_eq!(0b1010u8.with_bit(1, false), 0b1000);
        assert!((-1i16).bit(15));
        assert_eq!(0i64.with_bit(63, true), i64::MIN);
    }
}
