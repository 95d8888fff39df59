//! The basic types as [`PlcType`]s and [`PlcScalar`]s: the integers and floats, `bool`,
//! `FixedString<N>` and `Time`, with their located access; and the integers as [`BitSource`]s.

use super::{BitSource, ElementError, PlcScalar, PlcType, sealed};
use crate::place::StructPlace;
use crate::{FixedString, IecType, Time, Value};
use core::mem::size_of;
use zerocopy::byteorder::little_endian as le;

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

/// The place of a basic value's only leaf: all of it. Called only from this file's impls, of
/// the basic types.
fn whole_place<T: PlcType>(leaf: usize, each: &mut dyn FnMut(StructPlace<T>)) -> bool {
    if leaf != 0 {
        return false;
    }
    // SAFETY: `T` is one of this file's basic types: a bool, an integer, a float,
    // `FixedString<N>` (`[u8; N]`, transparent) or `Time` (an `i64`, transparent). None has
    // padding, and any bytes are a value of each but `bool`, which is one byte.
    each(unsafe { StructPlace::whole(0, size_of::<T>()) });
    true
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
            fn __places(leaf: usize, each: &mut dyn FnMut(StructPlace<Self>)) -> bool {
                whole_place(leaf, each)
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
    fn __places(leaf: usize, each: &mut dyn FnMut(StructPlace<Self>)) -> bool {
        whole_place(leaf, each)
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
    fn __places(leaf: usize, each: &mut dyn FnMut(StructPlace<Self>)) -> bool {
        whole_place(leaf, each)
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
    fn __places(leaf: usize, each: &mut dyn FnMut(StructPlace<Self>)) -> bool {
        whole_place(leaf, each)
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
