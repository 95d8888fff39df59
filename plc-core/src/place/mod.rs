//! Where a basic value lies in a program's Rust struct, and its bytes captured there to be
//! written again: what a force holds, so that applying it at each of the cycle's boundaries is
//! a store per value at an offset known in advance, not a search through `set`.
//!
//! Only the derive knows where a field lies, and the compiler measures it: the derive's
//! table takes each field's offset from a pointer the compiler projects to that field
//! (`FieldPlaces::new`; the same answer as `core::mem::offset_of!`, which costs an inline
//! `const` body per field):
//! a [`StructPlace`] is made only through `unsafe` constructors, whose callers (the derive's
//! generated code, plc-core's impls for arrays and basic types) say what proves the place.
//! A hand-written [`GlobalMemory`] or [`PlcType`](crate::PlcType) that does not make places
//! says nothing ([`GlobalMemory::struct_places`] is `false`), and its values are set through
//! [`GlobalMemory::set`] as before.
//!
//! ```
//! use plc_core::{GlobalMemory, Value, place};
//! #[derive(GlobalMemory, Debug, Clone)]
//! struct Gm {
//!     status: u16,
//!     #[plc(source = "status", bit = 3)]
//!     flag: bool,
//!     speeds: [f32; 4],
//! }
//! let mut gm = Gm::default();
//! gm.set(1, 0, Value::Bool(true)).unwrap();
//! let mut held = Vec::new();
//! // The bool's byte, and its bit of the source word.
//! assert!(place::capture(&gm, 1, 0, |p| held.push(p)));
//! assert_eq!(held.len(), 2);
//! let mut other = Gm::default();
//! for p in &held {
//!     p.write(&mut other);
//! }
//! assert!(other.flag);
//! assert_eq!(other.status, 0b1000);
//! ```

use crate::GlobalMemory;
use core::fmt;
use core::marker::PhantomData;
use core::mem::size_of;

/// Where one basic value lies in a struct `S`: bytes `offset..offset + len` are the field
/// that holds it (a bool, integer, real, `FixedString` or `Time`), or, with
/// [`bit`](Self::bit), one bit of an integer field there (a bit-mapped bool's bit of its
/// source word, which a `set` of the bool also writes).
///
/// Made only by the derive (and plc-core for its own types), through `unsafe` constructors:
/// holding one means its maker proved it.
pub struct StructPlace<S> {
    offset: usize,
    len: usize,
    bit: Option<u8>,
    _in: PhantomData<fn() -> S>,
}

impl<S> Clone for StructPlace<S> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<S> Copy for StructPlace<S> {}

impl<S> PartialEq for StructPlace<S> {
    fn eq(&self, other: &Self) -> bool {
        (self.offset, self.len, self.bit) == (other.offset, other.len, other.bit)
    }
}

impl<S> Eq for StructPlace<S> {}

impl<S> fmt::Debug for StructPlace<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("StructPlace")
            .field("offset", &self.offset)
            .field("len", &self.len)
            .field("bit", &self.bit)
            .finish()
    }
}

impl<S> StructPlace<S> {
    /// Byte offset of the field in `S`.
    pub const fn offset(self) -> usize {
        self.offset
    }

    /// Bytes of the field (`size_of` its type).
    pub const fn len(self) -> usize {
        self.len
    }

    /// Whether the field has no bytes (never, for a place the derive made).
    pub const fn is_empty(self) -> bool {
        self.len == 0
    }

    /// For a bit of an integer field: the bit, 0 = least significant.
    pub const fn bit(self) -> Option<u8> {
        self.bit
    }

    /// The place of a whole field.
    ///
    /// # Safety
    ///
    /// In every `S`, bytes `offset..offset + len` are one field of a basic PLC type (`bool`,
    /// an integer, `f32`, `f64`, `FixedString<N>`, `Time`), so they are initialised (no
    /// padding), and any of them read from that field of one `S` and written at the same
    /// offsets of another leave a valid `S` (only a `bool` has invalid byte values, and it is
    /// one byte).
    #[doc(hidden)]
    pub const unsafe fn whole(offset: usize, len: usize) -> Self {
        StructPlace {
            offset,
            len,
            bit: None,
            _in: PhantomData,
        }
    }

    /// The place of bit `bit` of an integer field.
    ///
    /// # Safety
    ///
    /// In every `S`, bytes `offset..offset + len` are one integer field (every bit pattern
    /// valid), and `bit < 8 * len`.
    #[doc(hidden)]
    pub const unsafe fn bit_of(offset: usize, len: usize, bit: u8) -> Self {
        StructPlace {
            offset,
            len,
            bit: Some(bit),
            _in: PhantomData,
        }
    }

    /// The same place in a struct `O` that holds an `S` at byte `offset`.
    ///
    /// # Safety
    ///
    /// In every `O`, the bytes from `offset` are a field of type `S` (`offset` is
    /// `core::mem::offset_of!` of such a field, or an array item's `index * size_of::<S>()`).
    #[doc(hidden)]
    pub const unsafe fn within<O>(self, offset: usize) -> StructPlace<O> {
        StructPlace {
            offset: offset + self.offset,
            len: self.len,
            bit: self.bit,
            _in: PhantomData,
        }
    }

    /// Whether the place lies inside `S` and its bit inside its field: true of every place
    /// proved as the constructors require; checked again before a place is written through.
    const fn fits(self) -> bool {
        let end = match self.offset.checked_add(self.len) {
            Some(end) => end,
            None => return false,
        };
        let bit_ok = match self.bit {
            Some(b) => (b as usize) < 8 * self.len,
            None => true,
        };
        end <= size_of::<S>() && self.len > 0 && end <= u32::MAX as usize && bit_ok
    }

    /// The bytes the place holds in `from`, as stores that write them into another `S`: a
    /// whole field in pieces of 8, 4, 2 and 1 bytes, a bit as a masked byte. `false` (and
    /// nothing given) if the place does not lie inside `S`, which no proved place does.
    pub fn capture(self, from: &S, mut each: impl FnMut(PlacedBytes<S>)) -> bool {
        if !self.fits() {
            return false;
        }
        let base = (from as *const S).cast::<u8>();
        if let Some(bit) = self.bit {
            let byte = if cfg!(target_endian = "little") {
                bit as usize / 8
            } else {
                self.len - 1 - bit as usize / 8
            };
            let mask = 1u8 << (bit % 8);
            let offset = self.offset + byte;
            // SAFETY: `fits`: the byte lies in `from`, a byte of an integer field (the
            // constructor's promise), so it is initialised.
            let now = unsafe { base.add(offset).read() };
            each(PlacedBytes::new(
                offset,
                u64::from(now & mask),
                Width::Masked(mask),
            ));
            return true;
        }
        let mut at = 0;
        while at < self.len {
            let width = match self.len - at {
                8.. => Width::Eight,
                4..=7 => Width::Four,
                2..=3 => Width::Two,
                _ => Width::One,
            };
            let offset = self.offset + at;
            // SAFETY: `fits`: `offset..offset + width` lies in `from` and in the field, whose
            // bytes are initialised (the constructor's promise); reads are unaligned.
            let bits = unsafe {
                let p = base.add(offset);
                match width {
                    Width::Eight => p.cast::<u64>().read_unaligned(),
                    Width::Four => u64::from(p.cast::<u32>().read_unaligned()),
                    Width::Two => u64::from(p.cast::<u16>().read_unaligned()),
                    Width::One | Width::Masked(_) => u64::from(p.read()),
                }
            };
            each(PlacedBytes::new(offset, bits, width));
            at += width.bytes();
        }
        true
    }
}

/// How many bytes a [`PlacedBytes`] writes, and how.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Width {
    One,
    Two,
    Four,
    Eight,
    /// One byte, only the bits of the mask.
    Masked(u8),
}

impl Width {
    const fn bytes(self) -> usize {
        match self {
            Width::One | Width::Masked(_) => 1,
            Width::Two => 2,
            Width::Four => 4,
            Width::Eight => 8,
        }
    }
}

/// Bytes of a struct `S` captured at a [`StructPlace`] (by [`StructPlace::capture`]), to write
/// into an `S` again and again: one unaligned store of 1, 2, 4 or 8 bytes, or a masked byte.
pub struct PlacedBytes<S> {
    /// Fits: [`StructPlace::capture`] checks the place's end against `u32::MAX`.
    offset: u32,
    width: Width,
    /// The bytes as an integer of the width, in the machine's byte order (as read).
    bits: u64,
    _in: PhantomData<fn() -> S>,
}

impl<S> Clone for PlacedBytes<S> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<S> Copy for PlacedBytes<S> {}

/// The same bytes at the same place (a force of the value it holds already changes nothing).
impl<S> PartialEq for PlacedBytes<S> {
    fn eq(&self, other: &Self) -> bool {
        (self.offset, self.width, self.bits) == (other.offset, other.width, other.bits)
    }
}

impl<S> Eq for PlacedBytes<S> {}

impl<S> fmt::Debug for PlacedBytes<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("PlacedBytes")
            .field("offset", &self.offset)
            .field("width", &self.width)
            .field("bits", &self.bits)
            .finish()
    }
}

impl<S> PlacedBytes<S> {
    /// Only `capture` makes them, from a place that fits.
    fn new(offset: usize, bits: u64, width: Width) -> Self {
        PlacedBytes {
            offset: offset as u32,
            width,
            bits,
            _in: PhantomData,
        }
    }

    /// Byte offset in `S` of the first byte written.
    pub const fn offset(&self) -> usize {
        self.offset as usize
    }

    /// Bytes written (a masked byte counts as one).
    pub const fn len(&self) -> usize {
        self.width.bytes()
    }

    /// Whether nothing is written (never).
    pub const fn is_empty(&self) -> bool {
        false
    }

    /// Writes the bytes into `to`, at the offset they were captured from.
    #[inline(always)]
    pub fn write(&self, to: &mut S) {
        // SAFETY: `capture` made `self` from a `StructPlace<S>` that `fits`, so the bytes
        // written lie inside `to`; they were read from the same offsets of another `S`, in the
        // field the place's maker proved to be there, so they are a valid value of it (or of
        // some of its bytes: any bytes are but a bool's, which is one byte and written whole);
        // a masked byte changes bits of an integer, any of whose values is valid. The `&mut S`
        // makes the write exclusive.
        unsafe {
            let p = (to as *mut S).cast::<u8>().add(self.offset as usize);
            match self.width {
                Width::One => p.write(self.bits as u8),
                Width::Two => p.cast::<u16>().write_unaligned(self.bits as u16),
                Width::Four => p.cast::<u32>().write_unaligned(self.bits as u32),
                Width::Eight => p.cast::<u64>().write_unaligned(self.bits),
                Width::Masked(mask) => p.write((p.read() & !mask) | (self.bits as u8 & mask)),
            }
        }
    }

    /// Each byte it writes: its offset in `S`, the bits of it written (all for a whole
    /// piece) and their values.
    fn each_byte(&self, mut f: impl FnMut(usize, u8, u8)) {
        let at = self.offset as usize;
        match self.width {
            Width::Masked(mask) => f(at, mask, self.bits as u8),
            whole => {
                let n = whole.bytes();
                // The integer of width `n` holding the bytes, as `capture` read them.
                let bytes = match n {
                    8 => self.bits.to_ne_bytes(),
                    4 => widen((self.bits as u32).to_ne_bytes()),
                    2 => widen((self.bits as u16).to_ne_bytes()),
                    _ => widen([self.bits as u8]),
                };
                for (k, &byte) in bytes[..n].iter().enumerate() {
                    f(at + k, 0xff, byte);
                }
            }
        }
    }
}

/// `bytes` at the start of eight.
fn widen<const N: usize>(bytes: [u8; N]) -> [u8; 8] {
    let mut out = [0; 8];
    out[..N].copy_from_slice(&bytes);
    out
}

/// Captures value `element` of variable `index` as `gm` holds it: every store that writes it
/// again as a `set` of it would ([`GlobalMemory::struct_places`], a bit-mapped bool's bit of
/// its source word included), given to `each`. `false` if `T` does not say where the value
/// lies (a hand-written impl, or no such value): the caller then drops whatever it was given
/// and uses [`GlobalMemory::set`].
pub fn capture<T: GlobalMemory>(
    gm: &T,
    index: usize,
    element: usize,
    mut each: impl FnMut(PlacedBytes<T>),
) -> bool {
    let mut all = true;
    let found = T::struct_places(index, element, &mut |place: StructPlace<T>| {
        all &= place.capture(gm, &mut each);
    });
    found && all
}

pub(crate) mod fields;
#[cfg(feature = "std")]
mod held;
#[cfg(test)]
mod tests;

#[cfg(feature = "std")]
pub use held::HeldBytes;
