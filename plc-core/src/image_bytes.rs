//! The image of a derived struct is one byte array with each variable's stored form
//! (`PlcType::Repr`) at a constant offset, one after the other in declaration order. These are
//! the pieces the derive builds it from.
//!
//! Why bytes rather than a `#[repr(C)]` struct with a field per variable: zerocopy's
//! `derive(FromBytes)` emits several trait impls per field (field projections keyed by a
//! const-evaluated name hash): `cargo check` after an edit of a 2,000-variable struct took
//! 19-20 s that way, 4-5 s this way (docs/benchmarks-history.md). The layout is the same either way: every
//! `Repr` has alignment 1, so a struct of them has no padding and puts each field exactly where
//! these offsets do.

use crate::PlcType;
use core::mem::size_of;
use zerocopy::FromBytes;

/// The offset of each variable, stored one after the other, from the sizes of their stored
/// forms.
///
/// ```
/// # use plc_core::__private::offsets;
/// assert_eq!(offsets([1, 4, 2]), [0, 1, 5]);
/// ```
pub const fn offsets<const N: usize>(sizes: [usize; N]) -> [usize; N] {
    let mut out = [0; N];
    let mut at = 0;
    let mut i = 0;
    while i < N {
        out[i] = at;
        at += sizes[i];
        i += 1;
    }
    out
}

/// The bytes of an image of variables with these sizes.
pub const fn image_size(sizes: &[usize]) -> usize {
    let mut total = 0;
    let mut i = 0;
    while i < sizes.len() {
        total += sizes[i];
        i += 1;
    }
    total
}

/// The stored form of a `T` at `offset` of `image`. With a constant offset into a fixed-size
/// array, as the derive calls it, the range and size checks fold away.
#[inline(always)]
pub fn repr_at<T: PlcType>(image: &[u8], offset: usize) -> &T::Repr {
    match T::Repr::ref_from_bytes(&image[offset..offset + size_of::<T::Repr>()]) {
        Ok(repr) => repr,
        // The slice has exactly the size of `Repr`, whose alignment is 1.
        Err(_) => unreachable!(),
    }
}

/// The stored form of a `T` at `offset` of `image`, to write.
#[inline(always)]
pub fn repr_at_mut<T: PlcType>(image: &mut [u8], offset: usize) -> &mut T::Repr {
    match T::Repr::mut_from_bytes(&mut image[offset..offset + size_of::<T::Repr>()]) {
        Ok(repr) => repr,
        Err(_) => unreachable!(),
    }
}

/// The step of each of the `P` columns of a run of fields (`offsets[r * P + j]` is where
/// repetition `r` of column `j` starts), or `None` when some column does not step evenly.
///
/// The derive converts a long run of same-typed fields with one loop (code that does not
/// grow with the fields) when the compiler laid the fields out evenly, which it does in
/// practice but does not promise: the derive asks this in a `const` and otherwise reads every
/// offset from a table.
///
/// ```
/// # use plc_core::__private::run_steps;
/// assert_eq!(run_steps::<2>(&[0, 8, 2, 12, 4, 16]), Some([2, 4]));
/// assert_eq!(run_steps::<1>(&[0, 2, 6]), None);
/// assert_eq!(run_steps::<1>(&[4, 2]), None);
/// ```
pub const fn run_steps<const P: usize>(offsets: &[usize]) -> Option<[usize; P]> {
    if P == 0 || offsets.len() < 2 * P || !offsets.len().is_multiple_of(P) {
        return None;
    }
    let mut steps = [0; P];
    let mut j = 0;
    while j < P {
        if offsets[P + j] < offsets[j] {
            return None;
        }
        steps[j] = offsets[P + j] - offsets[j];
        j += 1;
    }
    let mut k = P;
    while k < offsets.len() {
        if offsets[k] != offsets[k - P] + steps[k % P] {
            return None;
        }
        k += 1;
    }
    Some(steps)
}

/// The field of type `T` at byte `offset` of `s`.
///
/// # Safety
///
/// `offset` is `core::mem::offset_of!(S, field)` of a field of `s` whose type is `T`.
#[inline(always)]
pub unsafe fn field_at<S, T>(s: &S, offset: usize) -> &T {
    // SAFETY: by the caller's promise the bytes at `offset` are a field of type `T`: in
    // bounds, aligned for `T`, initialised, and borrowed for as long as `s` is.
    unsafe { &*(s as *const S).cast::<u8>().add(offset).cast::<T>() }
}

/// The field of type `T` at byte `offset` of `s`, to write.
///
/// # Safety
///
/// As [`field_at`].
#[inline(always)]
pub unsafe fn field_at_mut<S, T>(s: &mut S, offset: usize) -> &mut T {
    // SAFETY: as in `field_at`; the `&mut S` makes the borrow exclusive.
    unsafe { &mut *(s as *mut S).cast::<u8>().add(offset).cast::<T>() }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::FixedString;
    use zerocopy::byteorder::little_endian;

    #[test]
    fn stored_forms_sit_at_their_offsets_little_endian() {
        let sizes = [
            size_of::<<bool as PlcType>::Repr>(),
            size_of::<<u16 as PlcType>::Repr>(),
            size_of::<<FixedString<3> as PlcType>::Repr>(),
            size_of::<<f32 as PlcType>::Repr>(),
        ];
        let at = offsets(sizes);
        assert_eq!(at, [0, 1, 3, 3 + sizes[2]]);
        let mut image = [0u8; 32];
        assert!(image_size(&sizes) <= image.len());
        *repr_at_mut::<u16>(&mut image, at[1]) = little_endian::U16::new(0x1234);
        *repr_at_mut::<f32>(&mut image, at[3]) = little_endian::F32::new(1.5);
        assert_eq!(image[1..3], [0x34, 0x12]);
        assert_eq!(repr_at::<u16>(&image, at[1]).get(), 0x1234);
        assert_eq!(repr_at::<f32>(&image, at[3]).get(), 1.5);
        assert_eq!(image[at[3]..at[3] + 4], 1.5f32.to_le_bytes());
    }

    #[test]
    fn runs_step_evenly_or_not_at_all() {
        assert_eq!(run_steps::<1>(&[3, 5, 7, 9]), Some([2]));
        assert_eq!(run_steps::<3>(&[0, 40, 8, 1, 41, 10]), Some([1, 1, 2]));
        assert_eq!(run_steps::<2>(&[0, 1, 2]), None, "not whole repetitions");
        assert_eq!(run_steps::<2>(&[0, 1]), None, "one repetition is no run");
        assert_eq!(run_steps::<1>(&[0, 2, 4, 7]), None);
        assert_eq!(run_steps::<0>(&[]), None);
    }

    #[test]
    fn fields_are_found_at_their_offsets() {
        struct S {
            a: u16,
            b: u64,
        }
        let mut s = S { a: 1, b: 2 };
        // SAFETY: the offsets are those of `a: u16` and `b: u64`.
        unsafe {
            *field_at_mut::<S, u64>(&mut s, core::mem::offset_of!(S, b)) = 7;
            assert_eq!(*field_at::<S, u16>(&s, core::mem::offset_of!(S, a)), 1);
        }
        assert_eq!((s.a, s.b), (1, 7));
    }

    #[test]
    fn no_variables_make_an_empty_image() {
        assert_eq!(offsets::<0>([]), [0usize; 0]);
        assert_eq!(image_size(&[]), 0);
    }
}
