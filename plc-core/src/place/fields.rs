//! The places of a derived struct's fields, for the derive's generated code
//! (`GlobalMemory::struct_places`, `PlcType::__places`): a table with one [`FieldPlaces`] per
//! field, built in a `const` from pointers to the fields of one uninitialised struct, and the
//! bit of a source word.

use super::StructPlace;
use crate::PlcType;
use core::mem::size_of;

/// What the places of one field of `S` are found by: its offset, its basic values, and its
/// type's own places moved to that offset. Made only by [`FieldPlaces::new`], which is where
/// the derive proves the offset.
pub struct FieldPlaces<S> {
    offset: usize,
    leaves: usize,
    places: PlacesFn<S>,
}

/// What gives the places of a field's leaf: `(offset, leaf, each)`, as [`places_of`].
type PlacesFn<S> = fn(usize, usize, &mut dyn FnMut(StructPlace<S>)) -> bool;

impl<S> FieldPlaces<S> {
    /// The field of type `F` that `field` points to, in the `S` at `base`: its offset is
    /// where `field` lies from `base`, as the compiler projected it. In a `const` (as the
    /// derive builds its table), a field that would not lie inside `S` fails to compile.
    ///
    /// # Safety
    ///
    /// `field` is `&raw const (*base).f` of a field `f` of `S` (whose type is then `F`), and
    /// `base` points to an `S`, initialised or not (as `MaybeUninit::<S>::as_ptr` gives).
    pub const unsafe fn new<F: PlcType>(base: *const S, field: *const F) -> Self {
        // SAFETY: the caller's promise puts both pointers in the one allocation of the `S` at
        // `base`, `field` at or after it.
        let offset = unsafe { field.cast::<u8>().offset_from(base.cast::<u8>()) };
        assert!(
            offset >= 0 && offset as usize + size_of::<F>() <= size_of::<S>(),
            "a field's place must lie inside its struct"
        );
        FieldPlaces {
            offset: offset as usize,
            leaves: F::LEAVES,
            places: places_of::<S, F>,
        }
    }

    /// Where the field lies in `S`, in bytes from its start, as [`FieldPlaces::new`] measured.
    #[inline]
    pub const fn offset(&self) -> usize {
        self.offset
    }

    /// Basic values in the field ([`PlcType::LEAVES`]).
    #[inline]
    pub const fn leaves(&self) -> usize {
        self.leaves
    }

    /// Gives `each` the place of the field's basic value `leaf`, in `S`; `false` if it has
    /// no such value or its type does not say where it lies.
    #[inline]
    pub fn places(&self, leaf: usize, each: &mut dyn FnMut(StructPlace<S>)) -> bool {
        (self.places)(self.offset, leaf, each)
    }
}

/// The places of leaf `leaf` of the `F` at `offset` of `S`. Reached only through a
/// [`FieldPlaces`], whose `new` had the offset proved.
fn places_of<S, F: PlcType>(
    offset: usize,
    leaf: usize,
    each: &mut dyn FnMut(StructPlace<S>),
) -> bool {
    F::__places(leaf, &mut |place: StructPlace<F>| {
        // SAFETY: `FieldPlaces::new`'s caller promised that `offset` is where `S` holds a
        // field of type `F`, and only `new` pairs an offset with this function.
        each(unsafe { place.within::<S>(offset) })
    })
}

/// Gives `each` the place of bit `bit` of the field of type `W` at `offset` of `S`: what a
/// `set` of a bit-mapped bool writes besides the bool. `false` if `W` is not one of the
/// integer types or the bit is beyond it (the derive refuses both at compile time).
///
/// # Safety
///
/// `offset` is `core::mem::offset_of!(S, field)` of a field of `S` whose type is `W`.
pub unsafe fn bit_places<S, W: PlcType>(
    offset: usize,
    bit: u32,
    each: &mut dyn FnMut(StructPlace<S>),
) -> bool {
    if !is_integer::<W>() || bit >= 8 * size_of::<W>() as u32 {
        return false;
    }
    // SAFETY: the caller's promise puts a `W` at `offset`, one of Rust's integers (checked
    // just above by type, not by what a `PlcType` impl says of itself: every bit pattern is
    // one of its values), and the bit lies within it.
    each(unsafe { StructPlace::bit_of(offset, size_of::<W>(), bit as u8) });
    true
}

/// Whether `W` is one of Rust's integer types, the only bit sources.
fn is_integer<W: 'static>() -> bool {
    use core::any::TypeId;
    let w = TypeId::of::<W>();
    [
        TypeId::of::<u8>(),
        TypeId::of::<u16>(),
        TypeId::of::<u32>(),
        TypeId::of::<u64>(),
        TypeId::of::<i8>(),
        TypeId::of::<i16>(),
        TypeId::of::<i32>(),
        TypeId::of::<i64>(),
    ]
    .contains(&w)
}
