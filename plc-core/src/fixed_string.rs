//! `FixedString<N>`: the JSON format's fixed-capacity string, stored as `N` zero-padded bytes.

use core::fmt;
use core::hash::{Hash, Hasher};
use zerocopy::{FromBytes, Immutable, IntoBytes, KnownLayout, Unaligned};

/// UTF-8 text of at most `N` bytes, zero padded, laid out as exactly `[u8; N]` so it can live in
/// shared memory (the JSON variable-list format: `string` is `FixedString<N>`, `N` = `max_length`, 1..=255).
///
/// The bytes may come from another process; reading never panics: [`as_str`](Self::as_str)
/// returns the longest valid UTF-8 prefix before the first zero byte.
///
/// ```
/// use plc_core::FixedString;
/// let mut id = FixedString::<8>::new();
/// id.set("TEST-001");
/// assert_eq!(id.as_str(), "TEST-001");
/// id.set("TEST-0001"); // the JSON variable-list format: silently truncated at a character boundary
/// assert_eq!(id, "TEST-000");
/// assert!(id.try_set("TEST-0001").is_err()); // refuses instead, leaving the value unchanged
/// assert_eq!(id.len(), 8);
/// ```
///
/// `N` must be 1..=255; other capacities fail to compile when used:
///
/// ```compile_fail
/// let s = plc_core::FixedString::<256>::new();
/// ```
#[derive(Clone, Copy, FromBytes, IntoBytes, KnownLayout, Immutable, Unaligned)]
#[repr(transparent)]
pub struct FixedString<const N: usize>([u8; N]);

/// The error of [`FixedString::try_set`]: the text would not be stored whole, because it is
/// longer than the capacity or because it holds a NUL (zero) byte, where a zero-padded string
/// ends.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Truncated {
    /// Bytes of the text that was refused.
    pub len: usize,
    /// The string's capacity in bytes.
    pub capacity: usize,
    /// The byte offset of the first NUL in the text, if it has one (reading would stop there).
    pub nul: Option<usize>,
}

impl fmt::Display for Truncated {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.nul {
            Some(at) => write!(
                f,
                "text of {} bytes has a NUL (zero) byte at byte {at}, where a string ends: \
                 remove it",
                self.len
            ),
            None => write!(
                f,
                "text of {} bytes does not fit a string of capacity {}: shorten it or raise the \
                 capacity",
                self.len, self.capacity
            ),
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for Truncated {}

/// `s` up to its first NUL: the text a zero-padded string can hold and give back.
fn before_nul(s: &str) -> &str {
    // NUL is one byte and never part of a longer UTF-8 sequence: the cut is a char boundary.
    s.split('\0').next().unwrap_or_default()
}

/// The longest prefix of `s` of at most `max` bytes that ends on a character boundary.
pub(crate) fn floor_char_boundary(s: &str, max: usize) -> &str {
    if s.len() <= max {
        return s;
    }
    let mut end = max;
    while !s.is_char_boundary(end) {
        end -= 1;
    }
    &s[..end]
}

impl<const N: usize> FixedString<N> {
    const VALID_CAPACITY: () = assert!(
        plc_rules::capacity::is_valid_string_capacity(N),
        "FixedString<N> needs a capacity N of 1..=255 bytes (`max_length` of a JSON variable list)"
    );

    /// An empty string.
    pub const fn new() -> Self {
        let () = Self::VALID_CAPACITY;
        FixedString([0; N])
    }

    /// An empty string without the capacity check, for `PlcType::__ZERO`: a declaration with
    /// a wrong capacity gets its one spanned error from the derive, not a second from here.
    #[doc(hidden)]
    pub(crate) const fn __zeroed() -> Self {
        FixedString([0; N])
    }

    /// A string holding `s`, truncated as [`set`](Self::set) does.
    ///
    /// ```
    /// assert_eq!(plc_core::FixedString::<4>::from_str_truncate("héllo"), "hél");
    /// ```
    pub fn from_str_truncate(s: &str) -> Self {
        let mut out = Self::new();
        out.set(s);
        out
    }

    /// Stores `s`, silently truncated at the last UTF-8 character boundary that fits,
    /// and at its first NUL if it has one (a zero byte ends the stored text, so what follows it
    /// could never be read back).
    ///
    /// ```
    /// let mut s = plc_core::FixedString::<8>::new();
    /// s.set("a\0b");
    /// assert_eq!(s, "a");
    /// ```
    pub fn set(&mut self, s: &str) {
        self.store(floor_char_boundary(before_nul(s), N));
    }

    /// Stores `s`, or refuses with [`Truncated`] if it is longer than the capacity or holds a
    /// NUL (the value stays unchanged): what `try_set` accepts, [`as_str`](Self::as_str) gives
    /// back whole.
    ///
    /// ```
    /// let mut s = plc_core::FixedString::<8>::from_str_truncate("old");
    /// let e = s.try_set("a\0b").unwrap_err();
    /// assert_eq!(e.nul, Some(1));
    /// assert_eq!(s, "old");
    /// ```
    pub fn try_set(&mut self, s: &str) -> Result<(), Truncated> {
        let nul = s.bytes().position(|b| b == 0);
        if s.len() > N || nul.is_some() {
            return Err(Truncated {
                len: s.len(),
                capacity: N,
                nul,
            });
        }
        self.store(s);
        Ok(())
    }

    fn store(&mut self, s: &str) {
        let () = Self::VALID_CAPACITY;
        self.0[..s.len()].copy_from_slice(s.as_bytes());
        self.0[s.len()..].fill(0);
    }

    /// The text: bytes up to the first zero, cut to the longest valid UTF-8 prefix (bytes written
    /// by another process need not be valid; this never panics).
    pub fn as_str(&self) -> &str {
        let bytes = &self.0[..self.len_bytes()];
        match core::str::from_utf8(bytes) {
            Ok(s) => s,
            // SAFETY-free fallback: `valid_up_to` is a boundary of valid UTF-8 by contract.
            Err(e) => core::str::from_utf8(&bytes[..e.valid_up_to()]).unwrap_or_default(),
        }
    }

    fn len_bytes(&self) -> usize {
        self.0.iter().position(|&b| b == 0).unwrap_or(N)
    }

    /// Length of [`as_str`](Self::as_str) in bytes.
    pub fn len(&self) -> usize {
        self.as_str().len()
    }

    /// Whether the text is empty, as [`len`](Self::len) is 0 (bytes from another process that
    /// begin with invalid UTF-8 read as empty, too).
    pub fn is_empty(&self) -> bool {
        self.as_str().is_empty()
    }

    /// The capacity `N` in bytes.
    pub const fn capacity(&self) -> usize {
        N
    }

    /// Empties the string (all bytes zero).
    pub fn clear(&mut self) {
        self.0 = [0; N];
    }

    /// The raw bytes, padding included.
    pub const fn as_bytes(&self) -> &[u8; N] {
        &self.0
    }

    /// Builds a string from raw bytes, exactly as shared memory holds them.
    pub const fn from_bytes(bytes: [u8; N]) -> Self {
        let () = Self::VALID_CAPACITY;
        FixedString(bytes)
    }
}

impl<const N: usize> Default for FixedString<N> {
    fn default() -> Self {
        Self::new()
    }
}

impl<const N: usize> fmt::Write for FixedString<N> {
    /// Appends `s`; fails (appending what fits, at a character boundary) when full, or at a
    /// NUL (appending what comes before it).
    fn write_str(&mut self, s: &str) -> fmt::Result {
        let used = self.len();
        let fits = floor_char_boundary(before_nul(s), N - used);
        self.0[used..used + fits.len()].copy_from_slice(fits.as_bytes());
        self.0[used + fits.len()..].fill(0);
        if fits.len() == s.len() {
            Ok(())
        } else {
            Err(fmt::Error)
        }
    }
}

impl<const N: usize> fmt::Display for FixedString<N> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(self.as_str())
    }
}

impl<const N: usize> fmt::Debug for FixedString<N> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(self.as_str(), f)
    }
}

/// Equality is by text: two strings with the same text are equal whatever invalid bytes follow.
impl<const N: usize> PartialEq for FixedString<N> {
    fn eq(&self, other: &Self) -> bool {
        self.as_str() == other.as_str()
    }
}

impl<const N: usize> Eq for FixedString<N> {}

impl<const N: usize> Hash for FixedString<N> {
    fn hash<H: Hasher>(&self, state: &mut H) {
        self.as_str().hash(state)
    }
}

impl<const N: usize> PartialEq<str> for FixedString<N> {
    fn eq(&self, other: &str) -> bool {
        self.as_str() == other
    }
}

impl<const N: usize> PartialEq<&str> for FixedString<N> {
    fn eq(&self, other: &&str) -> bool {
        self.as_str() == *other
    }
}

impl<const N: usize> PartialEq<FixedString<N>> for str {
    fn eq(&self, other: &FixedString<N>) -> bool {
        self == other.as_str()
    }
}

impl<const N: usize> AsRef<str> for FixedString<N> {
    fn as_ref(&self) -> &str {
        self.as_str()
    }
}

#[cfg(feature = "serde")]
impl<const N: usize> serde::Serialize for FixedString<N> {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_str(self.as_str())
    }
}

#[cfg(feature = "serde")]
impl<'de, const N: usize> serde::Deserialize<'de> for FixedString<N> {
    /// Refuses text longer than the capacity rather than truncating it silently.
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Visitor<const N: usize>;
        impl<const N: usize> serde::de::Visitor<'_> for Visitor<N> {
            type Value = FixedString<N>;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                write!(f, "a string of at most {N} bytes")
            }
            fn visit_str<E: serde::de::Error>(self, v: &str) -> Result<Self::Value, E> {
                let mut s = FixedString::new();
                s.try_set(v).map_err(E::custom)?;
                Ok(s)
            }
        }
        deserializer.deserialize_str(Visitor::<N>)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::fmt::Write;
    use proptest::prelude::*;
    use zerocopy::{FromBytes, IntoBytes};

    #[test]
    fn json_format_usage() {
        let mut test_id = FixedString::<64>::new();
        test_id.set("TEST-001");
        assert_eq!(test_id.as_str(), "TEST-001");
        let notes = FixedString::<255>::new();
        assert!(notes.is_empty());
    }

    #[test]
    fn truncation_never_splits_a_character() {
        // 2-byte é, 3-byte €, 4-byte 🦀, each cut in the middle.
        assert_eq!(FixedString::<2>::from_str_truncate("aé"), "a");
        assert_eq!(FixedString::<3>::from_str_truncate("aé"), "aé");
        assert_eq!(FixedString::<3>::from_str_truncate("a€"), "a");
        assert_eq!(FixedString::<4>::from_str_truncate("a€"), "a€");
        assert_eq!(FixedString::<4>::from_str_truncate("a🦀"), "a");
        assert_eq!(FixedString::<3>::from_str_truncate("a🦀"), "a");
        assert_eq!(FixedString::<5>::from_str_truncate("a🦀"), "a🦀");
        assert_eq!(FixedString::<1>::from_str_truncate("🦀"), "");
    }

    #[test]
    fn exact_capacity_fits_and_one_more_is_refused() {
        let mut s = FixedString::<4>::new();
        assert_eq!(s.try_set("abcd"), Ok(()));
        assert_eq!(s.len(), 4);
        assert_eq!(s.as_bytes(), b"abcd");
        assert_eq!(
            s.try_set("abcde"),
            Err(Truncated {
                len: 5,
                capacity: 4,
                nul: None,
            })
        );
        assert_eq!(s, "abcd", "a refused try_set changes nothing");
        s.set("x");
        assert_eq!(s.as_bytes(), b"x\0\0\0", "shorter text is zero padded");
    }

    #[test]
    fn invalid_bytes_from_outside_give_the_valid_prefix() {
        let s = FixedString::<6>::from_bytes(*b"ok\xff\xfeab");
        assert_eq!(s.as_str(), "ok");
        let s = FixedString::<4>::from_bytes([0xE2, 0x82, 0, 0]); // half a €
        assert_eq!(s.as_str(), "");
        let s = FixedString::<3>::from_bytes(*b"a\0b");
        assert_eq!(s.as_str(), "a");
    }

    #[test]
    fn a_nul_ends_set_and_is_refused_by_try_set() {
        let mut s = FixedString::<8>::new();
        s.set("a\0b");
        assert_eq!(
            s.as_bytes(),
            b"a\0\0\0\0\0\0\0",
            "nothing after the NUL is stored"
        );
        assert_eq!(s.as_str(), "a");
        let e = s.try_set("xy\0z").unwrap_err();
        assert_eq!(
            e,
            Truncated {
                len: 4,
                capacity: 8,
                nul: Some(2)
            }
        );
        assert!(e.to_string().contains("NUL (zero) byte at byte 2"), "{e}");
        assert_eq!(s, "a", "a refused try_set changes nothing");
        assert!(write!(s, "b\0c").is_err());
        assert_eq!(s, "ab");
    }

    #[test]
    fn is_empty_agrees_with_len_for_bytes_from_outside() {
        let invalid_first = FixedString::<4>::from_bytes([0xFF, b'a', 0, 0]);
        assert_eq!(invalid_first.len(), 0);
        assert!(invalid_first.is_empty());
        let text = FixedString::<4>::from_bytes(*b"ab\0\0");
        assert!(!text.is_empty());
        assert!(FixedString::<4>::from_bytes([0; 4]).is_empty());
    }

    #[test]
    fn fmt_write_appends_until_full() {
        let mut s = FixedString::<8>::new();
        write!(s, "n={}", 42).unwrap();
        assert_eq!(s, "n=42");
        assert!(write!(s, "+too long").is_err());
        assert_eq!(s, "n=42+too");
    }

    #[test]
    fn zerocopy_round_trip() {
        let s = FixedString::<5>::from_str_truncate("héj");
        let bytes = s.as_bytes().as_slice().to_vec();
        assert_eq!(s.as_bytes().as_bytes(), &bytes[..]);
        let back = FixedString::<5>::read_from_bytes(&bytes).unwrap();
        assert_eq!(back, s);
        assert_eq!(core::mem::size_of::<FixedString<5>>(), 5);
        assert_eq!(core::mem::align_of::<FixedString<5>>(), 1);
    }

    #[cfg(feature = "serde")]
    #[test]
    fn serde_round_trip_as_a_string() {
        let s = FixedString::<16>::from_str_truncate("Specimen \"A\"");
        let json = serde_json::to_string(&s).unwrap();
        assert_eq!(json, r#""Specimen \"A\"""#);
        assert_eq!(serde_json::from_str::<FixedString<16>>(&json).unwrap(), s);
        assert!(serde_json::from_str::<FixedString<2>>(r#""abc""#).is_err());
    }

    proptest! {
        #[test]
        fn set_keeps_the_longest_fitting_prefix(text in "\\PC{0,40}") {
            let s = FixedString::<16>::from_str_truncate(&text);
            prop_assert!(text.starts_with(s.as_str()));
            prop_assert!(s.len() <= 16);
            // Maximal: the next character would not have fitted.
            if let Some(next) = text[s.len()..].chars().next() {
                prop_assert!(s.len() + next.len_utf8() > 16);
            }
            prop_assert!(s.as_bytes()[s.len()..].iter().all(|&b| b == 0));
        }

        #[test]
        fn what_try_set_accepts_reads_back_whole(text in "[a\\x00é]{0,20}") {
            let mut s = FixedString::<16>::new();
            match s.try_set(&text) {
                Ok(()) => prop_assert_eq!(s.as_str(), text.as_str()),
                Err(e) => prop_assert!(text.len() > 16 || e.nul.is_some()),
            }
            s.set(&text);
            prop_assert!(text.starts_with(s.as_str()));
        }

        #[test]
        fn any_bytes_read_without_panic(bytes in proptest::array::uniform8(any::<u8>())) {
            let s = FixedString::<8>::from_bytes(bytes);
            let text = s.as_str();
            prop_assert!(bytes.starts_with(text.as_bytes()));
            prop_assert_eq!(s.is_empty(), text.is_empty());
        }
    }
}
