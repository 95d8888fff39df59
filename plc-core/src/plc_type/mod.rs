//! `PlcType`: the Rust types a variable may have, and how each is stored in the image.
//!
//! The derive relies on this trait instead of reading type names, so a field declared through a
//! type alias (`type Word = u16;`) is checked and laid out exactly like one written `u16`.
//!
//! This module holds the traits and their error; the impls are in `scalars` (the basic types)
//! and `arrays`.

use crate::{IecType, Value, ValueError};
use zerocopy::{FromBytes, Immutable, IntoBytes, KnownLayout, Unaligned};

mod arrays;
mod scalars;
#[cfg(test)]
mod tests;

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
    /// A structure's alarms (`#[plc(alarm = "...")]` on its members), leaves counted from
    /// the structure's start; for an array of structures, one element's; empty for basic
    /// types. A program's table holds a copy per instance
    /// ([`GlobalMemory::ALARMS`](crate::GlobalMemory::ALARMS)).
    const ALARMS: &'static [crate::alarm::AlarmDecl] = &[];
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
    /// Gives `each` every place of leaf `leaf` in a `Self` that a `set_element` of it writes
    /// (see [`place`](crate::place)): a basic value's whole bytes, an array item's leaf
    /// moved to the item, a structure member's leaf moved to the member (and a bit-mapped
    /// bool's bit of its source word). `false` if there is no such leaf or the type does not
    /// say where it lies, as a type written by hand does not: its values are set through
    /// `set_element`.
    #[doc(hidden)]
    fn __places(leaf: usize, each: &mut dyn FnMut(crate::place::StructPlace<Self>)) -> bool {
        let _ = (leaf, each);
        false
    }

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

/// A scalar (non-array) variable type.
pub trait PlcScalar: PlcType {
    /// The value as a [`Value`].
    fn to_value(&self) -> Value;
    /// The typed value from a [`Value`] already checked with [`Value::fit`].
    fn from_fitted(value: Value) -> Self;
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
