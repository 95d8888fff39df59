//! The image of a derived struct is one byte array with each variable's stored form
//! (`PlcType::Repr`) at a constant offset, one after the other in declaration order. These are
//! the pieces the derive builds it from.
//!
//! Why bytes rather than a `#[repr(C)]` struct with a field per variable: zerocopy's
//! `derive(FromBytes)` emits several trait impls per field (field projections keyed by a
//! const-evaluated name hash): `cargo check` after an edit of a 2,000-variable struct took
//! 19-20 s that way, 4-5 s this way (BENCHMARKS.md). The layout is the same either way: every
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
    fn no_variables_make_an_empty_image() {
        assert_eq!(offsets::<0>([]), [0usize; 0]);
        assert_eq!(image_size(&[]), 0);
    }
}
