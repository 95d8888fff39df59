//! The located-access figure: three reads and three writes by IEC address (W, X, D), through
//! `plc_core::ProcessImage` and through the `process-image` crate, on the same addresses.

use plc_core::{Area, IecAddress, ProcessImage, Size};
use std::hint::black_box;

/// The addresses as constants: what the derive generates for `at = "..."` fields and what the
/// `process-image` crate's macros take.
pub const ADDRESSES: [IecAddress; 6] = [
    IecAddress::new(Area::Input, Size::Word, 16, None),
    IecAddress::new(Area::Input, Size::Bit, 3, Some(4)),
    IecAddress::new(Area::Input, Size::DoubleWord, 8, None),
    IecAddress::new(Area::Output, Size::Word, 2, None),
    IecAddress::new(Area::Output, Size::Bit, 5, Some(1)),
    IecAddress::new(Area::Output, Size::DoubleWord, 12, None),
];

/// The same addresses as text, for the variant that parses them at run time.
pub const TEXTS: [&str; 6] = ["%IW16", "%IX3.4", "%ID8", "%QW2", "%QX5.1", "%QD12"];

/// Bytes of the buffer both sides work on.
pub const BUFFER: usize = 64;

/// The accesses through `ProcessImage` at `a` (big endian, aligned).
#[inline(always)]
pub fn ours(buf: &mut [u8], a: &[IecAddress; 6]) {
    let mut pi = ProcessImage::new(buf);
    let w: u16 = pi.read(&a[0]).unwrap_or(0);
    let b: bool = pi.read(&a[1]).unwrap_or(false);
    let d: u32 = pi.read(&a[2]).unwrap_or(0);
    let _ = pi.write(&a[3], w.wrapping_add(1));
    let _ = pi.write(&a[4], !b);
    let _ = pi.write(&a[5], d ^ 1);
    black_box(pi.as_bytes());
}

/// The accesses through the `process-image` crate's `tag!`/`tag_mut!`.
#[inline(always)]
pub fn theirs(buf: &mut [u8]) {
    let w: u16 = process_image::tag!(&buf[..], W, 16);
    let b: bool = process_image::tag!(&buf[..], X, 3, 4);
    let d: u32 = process_image::tag!(&buf[..], D, 8);
    *process_image::tag_mut!(&mut buf[..], W, 2) = w.wrapping_add(1);
    *process_image::tag_mut!(&mut buf[..], X, 5, 1) = !b;
    *process_image::tag_mut!(&mut buf[..], D, 12) = d ^ 1;
    black_box(&buf);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn both_sides_do_the_same_accesses() {
        let (mut a, mut b) = ([0x5Au8; BUFFER], [0x5Au8; BUFFER]);
        for _ in 0..3 {
            ours(&mut a, &ADDRESSES);
            theirs(&mut b);
        }
        assert_eq!(a, b);
        let parsed = TEXTS.map(|t| t.parse::<IecAddress>().unwrap());
        assert_eq!(parsed, ADDRESSES);
    }
}
