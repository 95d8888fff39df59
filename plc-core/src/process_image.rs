//! Typed access to a process image by IEC 61131-3 address.

use crate::{IecAddress, Size};
use core::fmt;
use plc_rules::AddressError;

/// Byte order of words in a process image.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ByteOrder {
    /// Most significant byte first, as IEC 61131-3 process images, the `process-image` crate and most PLCs.
    #[default]
    BigEndian,
    /// Least significant byte first, as EtherCAT process data.
    LittleEndian,
}

/// Why a process image access failed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ProcessImageError {
    /// The address text did not parse.
    Address(AddressError),
    /// The item lies (partly) beyond the buffer.
    OutOfBounds {
        /// The address.
        address: IecAddress,
        /// The buffer's length in bytes.
        len: usize,
    },
    /// A W/D/L address whose byte offset is not a multiple of its size (IEC 61131-3 addressing's alignment
    /// table); allow it with [`ProcessImage::allow_unaligned`].
    Misaligned {
        /// The address.
        address: IecAddress,
    },
    /// The address's size does not match the Rust type read or written (X is `bool`, B 8-bit,
    /// W 16-bit, D 32-bit, L 64-bit).
    SizeMismatch {
        /// The address.
        address: IecAddress,
        /// The size the Rust type needs.
        expected: Size,
    },
}

impl fmt::Display for ProcessImageError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ProcessImageError::Address(e) => write!(f, "{e}"),
            ProcessImageError::OutOfBounds { address, len } => write!(
                f,
                "{address} needs bytes {}..{} but the process image has {len} bytes",
                address.byte_range().start,
                address.byte_range().end
            ),
            ProcessImageError::Misaligned { address } => write!(
                f,
                "{address} is not aligned to {} bytes: use an aligned offset or allow unaligned access",
                address.size.bytes()
            ),
            ProcessImageError::SizeMismatch { address, expected } => write!(
                f,
                "{address} addresses a {}-bit item but the value has {} bits (use %{}{}{})",
                address.size.bits(),
                expected.bits(),
                address.area.letter(),
                expected.letter(),
                address.byte
            ),
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for ProcessImageError {}

impl From<AddressError> for ProcessImageError {
    fn from(e: AddressError) -> Self {
        ProcessImageError::Address(e)
    }
}

mod sealed {
    pub trait Sealed {}
}

/// A Rust type that a process image address can hold: `bool` (X), `u8`/`i8` (B), `u16`/`i16`
/// (W), `u32`/`i32`/`f32` (D), `u64`/`i64`/`f64`/[`Time`](crate::Time) (L).
pub trait ProcessValue: Copy + sealed::Sealed {
    /// The address size this type needs.
    const SIZE: Size;
    /// Decodes from the item's bytes (`bit` for X).
    fn decode(bytes: &[u8], bit: u8, order: ByteOrder) -> Self;
    /// Encodes into the item's bytes (`bit` for X; other bits of the byte are kept).
    fn encode(self, bytes: &mut [u8], bit: u8, order: ByteOrder);
}

impl sealed::Sealed for bool {}
impl ProcessValue for bool {
    const SIZE: Size = Size::Bit;
    #[inline(always)]
    fn decode(bytes: &[u8], bit: u8, _: ByteOrder) -> Self {
        bytes[0] >> bit & 1 != 0
    }
    #[inline(always)]
    fn encode(self, bytes: &mut [u8], bit: u8, _: ByteOrder) {
        bytes[0] = (bytes[0] & !(1 << bit)) | ((self as u8) << bit);
    }
}

macro_rules! process_value {
    ($($t:ty => $size:ident, $n:literal;)*) => {$(
        impl sealed::Sealed for $t {}
        impl ProcessValue for $t {
            const SIZE: Size = Size::$size;
            #[inline(always)]
            fn decode(bytes: &[u8], _: u8, order: ByteOrder) -> Self {
                let mut raw = [0u8; $n];
                raw.copy_from_slice(&bytes[..$n]);
                match order {
                    ByteOrder::BigEndian => <$t>::from_be_bytes(raw),
                    ByteOrder::LittleEndian => <$t>::from_le_bytes(raw),
                }
            }
            #[inline(always)]
            fn encode(self, bytes: &mut [u8], _: u8, order: ByteOrder) {
                let raw = match order {
                    ByteOrder::BigEndian => self.to_be_bytes(),
                    ByteOrder::LittleEndian => self.to_le_bytes(),
                };
                bytes[..$n].copy_from_slice(&raw);
            }
        }
    )*};
}

process_value! {
    u8 => Byte, 1; i8 => Byte, 1;
    u16 => Word, 2; i16 => Word, 2;
    u32 => DoubleWord, 4; i32 => DoubleWord, 4; f32 => DoubleWord, 4;
    u64 => LongWord, 8; i64 => LongWord, 8; f64 => LongWord, 8;
}

/// An `LTIME` at an L address: its nanoseconds as a 64-bit integer.
impl sealed::Sealed for crate::Time {}
impl ProcessValue for crate::Time {
    const SIZE: Size = Size::LongWord;
    #[inline(always)]
    fn decode(bytes: &[u8], bit: u8, order: ByteOrder) -> Self {
        crate::Time::from_nanos(i64::decode(bytes, bit, order))
    }
    #[inline(always)]
    fn encode(self, bytes: &mut [u8], bit: u8, order: ByteOrder) {
        self.as_nanos().encode(bytes, bit, order)
    }
}

/// A process image over a byte buffer, read and written by IEC address (IEC 61131-3 addressing).
///
/// Words are big endian unless [`little_endian`](Self::little_endian) is set; W/D/L addresses
/// must be aligned to their size unless [`allow_unaligned`](Self::allow_unaligned) is set. Every
/// failure is an error, never a panic.
///
/// ```
/// use plc_core::ProcessImage;
/// // The IEC 61131-3 addressing example, as a process image of inputs.
/// let pii = [0x01, 0xFF, 0x12, 0x34, 0, 0, 0, 0x2A, 0, 0, 0, 0, 0, 0, 0, 7];
/// let pi = ProcessImage::new(&pii[..]);
/// let b1: bool = pi.get("%IX0.0")?;
/// let b2: bool = pi.get("%I0.1")?;
/// let by: u8 = pi.get("%IB1")?;
/// let w: u16 = pi.get("%IW2")?;
/// let d: u32 = pi.get("%ID4")?;
/// let l: u64 = pi.get("%IL8")?;
/// assert_eq!((b1, b2, by, w, d, l), (true, false, 0xFF, 0x1234, 42, 7));
/// assert!(pi.get::<u16>("%IW3").is_err()); // misaligned
/// # Ok::<(), plc_core::ProcessImageError>(())
/// ```
#[derive(Clone, Debug)]
pub struct ProcessImage<B> {
    buf: B,
    order: ByteOrder,
    unaligned: bool,
}

impl<B> ProcessImage<B> {
    /// A big-endian, alignment-checked process image over `buf`.
    pub const fn new(buf: B) -> Self {
        ProcessImage {
            buf,
            order: ByteOrder::BigEndian,
            unaligned: false,
        }
    }

    /// Uses little-endian words.
    pub fn little_endian(mut self) -> Self {
        self.order = ByteOrder::LittleEndian;
        self
    }

    /// Sets the byte order.
    pub fn with_byte_order(mut self, order: ByteOrder) -> Self {
        self.order = order;
        self
    }

    /// Allows W/D/L addresses at any byte offset.
    pub fn allow_unaligned(mut self) -> Self {
        self.unaligned = true;
        self
    }

    /// The byte order in use.
    pub fn byte_order(&self) -> ByteOrder {
        self.order
    }

    /// The buffer back.
    pub fn into_inner(self) -> B {
        self.buf
    }
}

impl<B: AsRef<[u8]>> ProcessImage<B> {
    /// The buffer's bytes.
    pub fn as_bytes(&self) -> &[u8] {
        self.buf.as_ref()
    }

    #[inline(always)]
    fn check<T: ProcessValue>(
        &self,
        address: &IecAddress,
        unaligned: bool,
    ) -> Result<(), ProcessImageError> {
        if address.size != T::SIZE {
            return Err(ProcessImageError::SizeMismatch {
                address: *address,
                expected: T::SIZE,
            });
        }
        if !unaligned && !address.is_aligned() {
            return Err(ProcessImageError::Misaligned { address: *address });
        }
        let len = self.buf.as_ref().len();
        if address.byte_range().end > len {
            return Err(ProcessImageError::OutOfBounds {
                address: *address,
                len,
            });
        }
        Ok(())
    }

    /// Reads the item at `address` as a `T` whose width matches the address size.
    #[inline]
    pub fn read<T: ProcessValue>(&self, address: &IecAddress) -> Result<T, ProcessImageError> {
        self.read_with(address, self.order, self.unaligned)
    }

    /// Reads with a given byte order and alignment rule instead of the image's own (the
    /// derive's located variables carry them in their declaration).
    #[inline]
    pub fn read_with<T: ProcessValue>(
        &self,
        address: &IecAddress,
        order: ByteOrder,
        unaligned: bool,
    ) -> Result<T, ProcessImageError> {
        self.check::<T>(address, unaligned)?;
        let bytes = &self.buf.as_ref()[address.byte as usize..];
        Ok(T::decode(bytes, address.bit.unwrap_or(0), order))
    }

    /// Parses `address` and reads it.
    pub fn get<T: ProcessValue>(&self, address: &str) -> Result<T, ProcessImageError> {
        self.read(&address.parse()?)
    }
}

impl<B: AsRef<[u8]> + AsMut<[u8]>> ProcessImage<B> {
    /// The buffer's bytes, mutable.
    pub fn as_bytes_mut(&mut self) -> &mut [u8] {
        self.buf.as_mut()
    }

    /// Writes `value` to the item at `address`; a bit write keeps the byte's other bits.
    #[inline]
    pub fn write<T: ProcessValue>(
        &mut self,
        address: &IecAddress,
        value: T,
    ) -> Result<(), ProcessImageError> {
        self.write_with(address, value, self.order, self.unaligned)
    }

    /// Writes with a given byte order and alignment rule instead of the image's own.
    #[inline]
    pub fn write_with<T: ProcessValue>(
        &mut self,
        address: &IecAddress,
        value: T,
        order: ByteOrder,
        unaligned: bool,
    ) -> Result<(), ProcessImageError> {
        self.check::<T>(address, unaligned)?;
        let bytes = &mut self.buf.as_mut()[address.byte as usize..];
        value.encode(bytes, address.bit.unwrap_or(0), order);
        Ok(())
    }

    /// Parses `address` and writes it.
    pub fn set<T: ProcessValue>(
        &mut self,
        address: &str,
        value: T,
    ) -> Result<(), ProcessImageError> {
        self.write(&address.parse()?, value)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn addressing_examples_read_big_endian() {
        let mut pii = [0u8; 16];
        pii[0] = 0b0000_0011;
        pii[1] = 0xAB;
        pii[2..4].copy_from_slice(&[0x12, 0x34]);
        pii[4..8].copy_from_slice(&[0xDE, 0xAD, 0xBE, 0xEF]);
        pii[8..16].copy_from_slice(&[1, 2, 3, 4, 5, 6, 7, 8]);
        let pi = ProcessImage::new(&pii);
        assert!(pi.get::<bool>("%IX0.0").unwrap());
        assert!(pi.get::<bool>("%I0.1").unwrap());
        assert!(!pi.get::<bool>("%IX0.2").unwrap());
        assert_eq!(pi.get::<u8>("%IB1").unwrap(), 0xAB);
        assert_eq!(pi.get::<u16>("%IW2").unwrap(), 0x1234);
        assert_eq!(pi.get::<u32>("%ID4").unwrap(), 0xDEAD_BEEF);
        assert_eq!(pi.get::<u64>("%IL8").unwrap(), 0x0102_0304_0506_0708);
        let le = ProcessImage::new(&pii).little_endian();
        assert_eq!(le.get::<u16>("%IW2").unwrap(), 0x3412);
    }

    #[test]
    fn writes_produce_hand_computed_bytes() {
        let mut piq = [0u8; 16];
        let mut pi = ProcessImage::new(&mut piq);
        pi.set("%QX100.4", true).unwrap_err();
        pi.set("%QX3.4", true).unwrap();
        pi.set("%QX3.0", true).unwrap();
        pi.set("%QX3.0", false).unwrap();
        pi.set("%QW4", -2i16).unwrap();
        pi.set("%QD8", 1.5f32).unwrap();
        pi.set("%QB1", 0x7Fu8).unwrap();
        assert_eq!(piq[3], 0b0001_0000);
        assert_eq!(&piq[4..6], &[0xFF, 0xFE]);
        assert_eq!(&piq[8..12], &[0x3F, 0xC0, 0x00, 0x00]);
        assert_eq!(piq[1], 0x7F);
    }

    #[test]
    fn a_time_is_a_long_word_of_nanoseconds() {
        let mut buf = [0u8; 16];
        let mut pi = ProcessImage::new(&mut buf);
        pi.set("%QL8", crate::Time::from_nanos(-2)).unwrap();
        assert!(
            pi.set("%QD8", crate::Time::ZERO).is_err(),
            "an LTIME needs an L address"
        );
        assert_eq!(
            pi.get::<crate::Time>("%QL8"),
            Ok(crate::Time::from_nanos(-2))
        );
        assert_eq!(&buf[8..16], &(-2i64).to_be_bytes());
    }

    #[test]
    fn errors_instead_of_panics() {
        let buf = [0u8; 4];
        let pi = ProcessImage::new(&buf);
        assert!(matches!(
            pi.get::<u16>("%IW3"),
            Err(ProcessImageError::Misaligned { .. })
        ));
        assert!(matches!(
            pi.get::<u32>("%ID4"),
            Err(ProcessImageError::OutOfBounds { len: 4, .. })
        ));
        assert!(matches!(
            pi.get::<u32>("%IW0"),
            Err(ProcessImageError::SizeMismatch { .. })
        ));
        assert!(matches!(
            pi.get::<u8>("%IQ0"),
            Err(ProcessImageError::Address(_))
        ));
        let un = ProcessImage::new(&buf).allow_unaligned();
        assert_eq!(un.get::<u16>("%IW1").unwrap(), 0);
        let e = pi.get::<u32>("%IW0").unwrap_err();
        assert_eq!(
            std::format!("{e}"),
            "%IW0 addresses a 16-bit item but the value has 32 bits (use %ID0)"
        );
    }
}
