//! IEC 61131-3 direct addresses.
//!
//! ```text
//!  +------- The process image that is referenced: I=inputs, Q=outputs, M=internal memory
//!  |+------ The type of the tag: X=bit, B=byte, W=word, D=double word, L=long word
//!  || +---- The byte offset inside the process image
//!  || |  +- The bit offset in the addressed byte
//!  vv v  v
//! %IX100.4 = bit 4 in byte address 100
//! %IB8     = byte at address 8
//! %IW16    = word starting at address 16
//! ```
//!
//! | size | Rust | bytes | alignment |
//! |---|---|---|---|
//! | X (may be omitted) | bool | bit | none |
//! | B | u8 / i8 | 1 | none |
//! | W | u16 / i16 | 2 | 2 |
//! | D | u32 / i32 / f32 | 4 | 4 |
//! | L | u64 / i64 / f64 | 8 | 8 |
//!
//! plc-vars follows IEC 61131-3 where the variable-editor rules differ: `X` is a bit, `B` a byte.
//!
//! ```
//! use plc_rules::{IecAddress, Area, Size};
//! let a: IecAddress = "%I0.1".parse().unwrap();
//! assert_eq!((a.area, a.size, a.byte, a.bit), (Area::Input, Size::Bit, 0, Some(1)));
//! assert_eq!(a.to_string(), "%IX0.1");
//! let e = "%IX3.8".parse::<IecAddress>().unwrap_err();
//! assert_eq!(e.to_string(), "`%IX3.8`: bit 8 out of range 0..=7");
//! ```

use core::fmt;
use core::str::FromStr;

/// The process image an address refers to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Area {
    /// `%I`: inputs.
    Input,
    /// `%Q`: outputs.
    Output,
    /// `%M`: internal memory.
    Memory,
}

/// The size of the addressed item.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Size {
    /// `X`: one bit.
    Bit,
    /// `B`: a byte.
    Byte,
    /// `W`: a 16-bit word.
    Word,
    /// `D`: a 32-bit double word.
    DoubleWord,
    /// `L`: a 64-bit long word.
    LongWord,
}

impl Area {
    /// The area letter.
    pub const fn letter(self) -> char {
        match self {
            Area::Input => 'I',
            Area::Output => 'Q',
            Area::Memory => 'M',
        }
    }
}

impl Size {
    /// The size letter.
    pub const fn letter(self) -> char {
        match self {
            Size::Bit => 'X',
            Size::Byte => 'B',
            Size::Word => 'W',
            Size::DoubleWord => 'D',
            Size::LongWord => 'L',
        }
    }

    /// Width in bits (1 for `X`).
    pub const fn bits(self) -> u32 {
        match self {
            Size::Bit => 1,
            Size::Byte => 8,
            Size::Word => 16,
            Size::DoubleWord => 32,
            Size::LongWord => 64,
        }
    }

    /// Bytes the item spans (1 for `X`: the byte that holds the bit).
    pub const fn bytes(self) -> usize {
        match self {
            Size::Bit | Size::Byte => 1,
            other => (other.bits() / 8) as usize,
        }
    }

    /// The size whose width is `bits` (1 is `X`).
    pub const fn from_bits(bits: u32) -> Option<Size> {
        Some(match bits {
            1 => Size::Bit,
            8 => Size::Byte,
            16 => Size::Word,
            32 => Size::DoubleWord,
            64 => Size::LongWord,
            _ => return None,
        })
    }
}

/// A direct address such as `%IX100.4`, `%QB8`, `%IW16`, `%MD4` or `%IL8`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct IecAddress {
    /// The process image.
    pub area: Area,
    /// The item's size.
    pub size: Size,
    /// Byte offset in the process image.
    pub byte: u32,
    /// Bit in the byte, 0..=7; `Some` exactly for [`Size::Bit`].
    pub bit: Option<u8>,
}

impl IecAddress {
    /// An address from its parts, for constants: `bit` is `Some(0..=7)` exactly for
    /// [`Size::Bit`]. In a `const` a wrong combination is a compile error.
    ///
    /// ```
    /// use plc_rules::{Area, IecAddress, Size};
    /// const START: IecAddress = IecAddress::new(Area::Input, Size::Bit, 3, Some(4));
    /// assert_eq!(START, "%IX3.4".parse().unwrap());
    /// ```
    ///
    /// ```compile_fail
    /// use plc_rules::{Area, IecAddress, Size};
    /// const BAD: IecAddress = IecAddress::new(Area::Input, Size::Word, 4, Some(1));
    /// ```
    ///
    /// # Panics
    /// If `bit` is `None` for a bit, `Some` for any other size, or above 7.
    pub const fn new(area: Area, size: Size, byte: u32, bit: Option<u8>) -> Self {
        match (size, bit) {
            (Size::Bit, Some(b)) => assert!(b <= 7, "an IEC address bit is 0..=7"),
            (Size::Bit, None) => panic!("a bit address (X) needs a bit 0..=7"),
            (_, Some(_)) => panic!("only a bit address (X) has a bit"),
            (_, None) => {}
        }
        IecAddress {
            area,
            size,
            byte,
            bit,
        }
    }

    /// The range of bytes the item occupies.
    pub const fn byte_range(&self) -> core::ops::Range<usize> {
        let start = self.byte as usize;
        start..start + self.size.bytes()
    }

    /// Whether the byte offset is a multiple of the item's size (IEC 61131-3 addressing's alignment rule).
    pub const fn is_aligned(&self) -> bool {
        (self.byte as usize).is_multiple_of(self.size.bytes())
    }

    /// Whether two addresses in the same area share a bit.
    pub fn overlaps(&self, other: &IecAddress) -> bool {
        if self.area != other.area {
            return false;
        }
        let (a, b) = (self.byte_range(), other.byte_range());
        if a.start >= b.end || b.start >= a.end {
            return false;
        }
        match (self.bit, other.bit) {
            (Some(x), Some(y)) => x == y,
            _ => true,
        }
    }
}

/// What is wrong with an address's text.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AddressErrorKind {
    /// It does not start with `%`.
    MissingPercent,
    /// The area letter is not I, Q or M (the character found, if any).
    BadArea(Option<char>),
    /// The size letter is not X, B, W, D or L.
    BadSize(char),
    /// There is no byte offset.
    MissingByte,
    /// The byte offset does not start with a digit (`%IWx4`, `%IW-4`) or is 2^32 or more.
    BadByte,
    /// A bit address without `.bit`.
    MissingBit,
    /// The bit does not start with a digit (`%IX0.`, `%IX0.-1`).
    BadBit,
    /// The bit is beyond 7 (`u32::MAX` for a bit number too large for a `u32`).
    BitOutOfRange(u32),
    /// A byte/word/dword/lword address with a `.bit`.
    BitOnNonBit,
    /// Something follows the address.
    Trailing,
}

/// The error of parsing an [`IecAddress`]: the text and what is wrong with it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct AddressError {
    text: AddressText,
    /// What is wrong.
    pub kind: AddressErrorKind,
}

/// The first 32 bytes of the text, kept without allocation so the error works in `no_std`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct AddressText {
    bytes: [u8; 32],
    len: u8,
}

impl AddressText {
    fn new(s: &str) -> Self {
        let mut end = s.len().min(32);
        while !s.is_char_boundary(end) {
            end -= 1;
        }
        let mut bytes = [0; 32];
        bytes[..end].copy_from_slice(&s.as_bytes()[..end]);
        AddressText {
            bytes,
            len: end as u8,
        }
    }

    fn as_str(&self) -> &str {
        core::str::from_utf8(&self.bytes[..self.len as usize]).unwrap_or("")
    }
}

impl AddressError {
    /// The address text the error is about (its first 32 bytes).
    pub fn text(&self) -> &str {
        self.text.as_str()
    }
}

impl fmt::Display for AddressErrorKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            AddressErrorKind::MissingPercent => f.write_str("an address starts with `%`, e.g. `%IW4`"),
            AddressErrorKind::BadArea(Some(c)) => write!(
                f,
                "area `{c}` is not I (input), Q (output) or M (memory)"
            ),
            AddressErrorKind::BadArea(None) => {
                f.write_str("the area is missing: I (input), Q (output) or M (memory)")
            }
            AddressErrorKind::BadSize(c) => write!(
                f,
                "size `{c}` is not X (bit), B (byte), W (word), D (double word) or L (long word)"
            ),
            AddressErrorKind::MissingByte => f.write_str("the byte offset is missing, e.g. `%IW4`"),
            AddressErrorKind::BadByte => f.write_str("the byte offset is not a number below 2^32"),
            AddressErrorKind::MissingBit => {
                f.write_str("a bit address needs `.bit` after the byte, e.g. `%IX0.1`")
            }
            AddressErrorKind::BadBit => f.write_str("the bit is not a number"),
            AddressErrorKind::BitOutOfRange(u32::MAX) => {
                f.write_str("the bit number is out of range 0..=7")
            }
            AddressErrorKind::BitOutOfRange(b) => write!(f, "bit {b} out of range 0..=7"),
            AddressErrorKind::BitOnNonBit => f.write_str(
                "only bit (X) addresses take `.bit`; byte, word, double and long word addresses do not",
            ),
            AddressErrorKind::Trailing => f.write_str("unexpected characters after the address"),
        }
    }
}

impl fmt::Display for AddressError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "`{}`: {}", self.text(), self.kind)
    }
}

#[cfg(feature = "std")]
impl std::error::Error for AddressError {}

/// How many ASCII digits `s` starts with.
fn leading_digits(s: &str) -> usize {
    s.bytes().take_while(u8::is_ascii_digit).count()
}

fn parse_number(digits: &str) -> Option<u32> {
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    digits.parse().ok()
}

impl FromStr for IecAddress {
    type Err = AddressError;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let err = |kind| AddressError {
            text: AddressText::new(s),
            kind,
        };
        let rest = s
            .strip_prefix('%')
            .ok_or(err(AddressErrorKind::MissingPercent))?;
        let mut chars = rest.chars();
        let area = match chars.next().map(|c| c.to_ascii_uppercase()) {
            Some('I') => Area::Input,
            Some('Q') => Area::Output,
            Some('M') => Area::Memory,
            other => return Err(err(AddressErrorKind::BadArea(other))),
        };
        let rest = chars.as_str();
        let (size, rest) = match rest.chars().next() {
            Some(c) if c.is_ascii_digit() => (Size::Bit, rest),
            None => return Err(err(AddressErrorKind::MissingByte)),
            Some(c) => {
                let size = match c.to_ascii_uppercase() {
                    'X' => Size::Bit,
                    'B' => Size::Byte,
                    'W' => Size::Word,
                    'D' => Size::DoubleWord,
                    'L' => Size::LongWord,
                    _ => return Err(err(AddressErrorKind::BadSize(c))),
                };
                (size, &rest[c.len_utf8()..])
            }
        };
        let (byte_text, bit_text) = match rest.split_once('.') {
            Some((b, bit)) => (b, Some(bit)),
            None => (rest, None),
        };
        if byte_text.is_empty() {
            return Err(err(AddressErrorKind::MissingByte));
        }
        // A number that does not start with a digit is a bad number (`%IWx4`, `%IW-4`); one
        // that starts with digits and goes on is an address with something after it (`%IW4x`).
        match leading_digits(byte_text) {
            0 => return Err(err(AddressErrorKind::BadByte)),
            n if n < byte_text.len() => return Err(err(AddressErrorKind::Trailing)),
            _ => {}
        }
        let byte = parse_number(byte_text).ok_or(err(AddressErrorKind::BadByte))?;
        let bit = match (size, bit_text) {
            (Size::Bit, None) => return Err(err(AddressErrorKind::MissingBit)),
            (Size::Bit, Some(t)) => {
                match leading_digits(t) {
                    0 => return Err(err(AddressErrorKind::BadBit)),
                    n if n < t.len() => return Err(err(AddressErrorKind::Trailing)),
                    _ => {}
                }
                // All digits: only a number beyond u32 fails to parse, and it is out of range.
                let bit = parse_number(t).unwrap_or(u32::MAX);
                if bit > 7 {
                    return Err(err(AddressErrorKind::BitOutOfRange(bit)));
                }
                Some(bit as u8)
            }
            (_, Some(_)) => return Err(err(AddressErrorKind::BitOnNonBit)),
            (_, None) => None,
        };
        Ok(IecAddress {
            area,
            size,
            byte,
            bit,
        })
    }
}

impl fmt::Display for IecAddress {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "%{}{}{}",
            self.area.letter(),
            self.size.letter(),
            self.byte
        )?;
        match self.bit {
            Some(bit) => write!(f, ".{bit}"),
            None => Ok(()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kind(s: &str) -> AddressErrorKind {
        s.parse::<IecAddress>().unwrap_err().kind
    }

    #[test]
    fn addressing_examples_parse() {
        let a: IecAddress = "%IX100.4".parse().unwrap();
        assert_eq!(
            (a.area, a.size, a.byte, a.bit),
            (Area::Input, Size::Bit, 100, Some(4))
        );
        let b: IecAddress = "%IB8".parse().unwrap();
        assert_eq!((b.size, b.byte, b.bit), (Size::Byte, 8, None));
        let w: IecAddress = "%IW16".parse().unwrap();
        assert_eq!((w.size, w.byte), (Size::Word, 16));
        let d: IecAddress = "%MD4".parse().unwrap();
        assert_eq!((d.area, d.size), (Area::Memory, Size::DoubleWord));
        let l: IecAddress = "%IL8".parse().unwrap();
        assert_eq!(l.size, Size::LongWord);
        assert_eq!("%QB8".parse::<IecAddress>().unwrap().area, Area::Output);
    }

    #[test]
    fn display_round_trips_every_area_and_size() {
        for area in ["I", "Q", "M"] {
            for size in ["X", "B", "W", "D", "L"] {
                let text = if size == "X" {
                    std::format!("%{area}{size}16.7")
                } else {
                    std::format!("%{area}{size}16")
                };
                let a: IecAddress = text.parse().unwrap();
                assert_eq!(a.to_string(), text);
                assert_eq!(a.to_string().parse::<IecAddress>().unwrap(), a);
            }
        }
        assert_eq!("%i0.1".parse::<IecAddress>().unwrap().to_string(), "%IX0.1");
    }

    #[test]
    fn every_error_class_is_named() {
        assert_eq!(kind("IX0.1"), AddressErrorKind::MissingPercent);
        assert_eq!(kind("%ZX0.1"), AddressErrorKind::BadArea(Some('Z')));
        assert_eq!(kind("%"), AddressErrorKind::BadArea(None));
        assert_eq!(kind("%IS4"), AddressErrorKind::BadSize('S'));
        assert_eq!(kind("%IW"), AddressErrorKind::MissingByte);
        assert_eq!(kind("%I"), AddressErrorKind::MissingByte);
        assert_eq!(kind("%IW99999999999"), AddressErrorKind::BadByte);
        assert_eq!(kind("%IX3"), AddressErrorKind::MissingBit);
        assert_eq!(kind("%IX3."), AddressErrorKind::BadBit);
        assert_eq!(kind("%IX3.8"), AddressErrorKind::BitOutOfRange(8));
        assert_eq!(kind("%IW4.1"), AddressErrorKind::BitOnNonBit);
        assert_eq!(kind("%IW4x"), AddressErrorKind::Trailing);
        assert_eq!(kind("%IX1.2z"), AddressErrorKind::Trailing);
        assert_eq!(kind("%IX1.2.3"), AddressErrorKind::Trailing);
    }

    #[test]
    fn a_byte_or_bit_that_is_no_number_is_named_as_such() {
        assert_eq!(kind("%IWx4"), AddressErrorKind::BadByte);
        assert_eq!(kind("%IW-4"), AddressErrorKind::BadByte);
        assert_eq!(kind("%IW+4"), AddressErrorKind::BadByte);
        assert_eq!(kind("%IX.1"), AddressErrorKind::MissingByte);
        assert_eq!(kind("%IX0.x"), AddressErrorKind::BadBit);
        assert_eq!(kind("%IX0.-1"), AddressErrorKind::BadBit);
        assert_eq!(
            kind("%IX3.99999999999"),
            AddressErrorKind::BitOutOfRange(u32::MAX)
        );
        assert_eq!(
            kind("%IX3.4294967295"),
            AddressErrorKind::BitOutOfRange(u32::MAX)
        );
        assert_eq!(
            kind("%IX3.4294967294"),
            AddressErrorKind::BitOutOfRange(4294967294)
        );
        assert_eq!(
            "%IX3.99999999999"
                .parse::<IecAddress>()
                .unwrap_err()
                .to_string(),
            "`%IX3.99999999999`: the bit number is out of range 0..=7"
        );
        assert_eq!(
            "%IWx4".parse::<IecAddress>().unwrap_err().to_string(),
            "`%IWx4`: the byte offset is not a number below 2^32"
        );
        assert_eq!(
            "%IX3.8".parse::<IecAddress>().unwrap_err().to_string(),
            "`%IX3.8`: bit 8 out of range 0..=7"
        );
    }

    #[test]
    fn alignment_and_overlap() {
        let p = |s: &str| s.parse::<IecAddress>().unwrap();
        assert!(p("%IW16").is_aligned() && !p("%IW3").is_aligned());
        assert!(p("%ID8").is_aligned() && !p("%ID6").is_aligned());
        assert!(p("%IL8").is_aligned() && !p("%IL4").is_aligned());
        assert!(p("%IX3.1").is_aligned() && p("%IB3").is_aligned());
        assert!(p("%IW4").overlaps(&p("%IB5")));
        assert!(p("%IX5.2").overlaps(&p("%IW4")));
        assert!(!p("%IX5.2").overlaps(&p("%IX5.3")));
        assert!(!p("%IW4").overlaps(&p("%QW4")));
        assert!(!p("%IW4").overlaps(&p("%IW6")));
    }
}
