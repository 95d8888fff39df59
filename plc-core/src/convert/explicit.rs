//! The explicit conversion functions `<SOURCE>_TO_<TARGET>` of IEC 61131-3, in
//! snake case, for every pair of numeric, bit-string and boolean types.
//!
//! Semantics: narrowing integers wrap (two's complement, like `as`); real to integer truncates
//! toward zero and saturates at the bounds (NaN gives 0); integer to real rounds to nearest;
//! `LREAL` to `REAL` rounds (overflow gives infinity); to `BOOL` is "not zero"; from `BOOL` is 1
//! or 0. Each `checked_` variant returns `None` where the plain one would change the value
//! (wrap, truncate, saturate, round, overflow).
//!
//! ```
//! use plc_core::convert::explicit::*;
//! assert_eq!(dint_to_int(100_000), -31_072); // wraps, like DINT_TO_INT
//! assert_eq!(checked_dint_to_int(100_000), None);
//! assert_eq!(real_to_int(-2.9), -2); // truncates toward zero
//! assert_eq!(lreal_to_sint(1e10), 127); // saturates
//! assert_eq!(checked_real_to_int(2.5), None);
//! assert_eq!(word_to_bool(4), true);
//! ```

use super::Convert;

macro_rules! explicit {
    ($($name:ident, $checked:ident: $from:ty => $to:ty;)*) => {$(
        #[doc = concat!("`", stringify!($name), "`: see the [module documentation](self).")]
        #[inline]
        pub fn $name(value: $from) -> $to {
            Convert::<$to>::convert(value)
        }
        #[doc = concat!("`", stringify!($name), "`, or `None` if the value would change.")]
        #[inline]
        pub fn $checked(value: $from) -> Option<$to> {
            Convert::<$to>::checked(value)
        }
    )*};
}

explicit! {
    bool_to_sint, checked_bool_to_sint: bool => i8;
    bool_to_int, checked_bool_to_int: bool => i16;
    bool_to_dint, checked_bool_to_dint: bool => i32;
    bool_to_lint, checked_bool_to_lint: bool => i64;
    bool_to_usint, checked_bool_to_usint: bool => u8;
    bool_to_uint, checked_bool_to_uint: bool => u16;
    bool_to_udint, checked_bool_to_udint: bool => u32;
    bool_to_ulint, checked_bool_to_ulint: bool => u64;
    bool_to_real, checked_bool_to_real: bool => f32;
    bool_to_lreal, checked_bool_to_lreal: bool => f64;
    bool_to_byte, checked_bool_to_byte: bool => u8;
    bool_to_word, checked_bool_to_word: bool => u16;
    bool_to_dword, checked_bool_to_dword: bool => u32;
    bool_to_lword, checked_bool_to_lword: bool => u64;
    sint_to_bool, checked_sint_to_bool: i8 => bool;
    sint_to_int, checked_sint_to_int: i8 => i16;
    sint_to_dint, checked_sint_to_dint: i8 => i32;
    sint_to_lint, checked_sint_to_lint: i8 => i64;
    sint_to_usint, checked_sint_to_usint: i8 => u8;
    sint_to_uint, checked_sint_to_uint: i8 => u16;
    sint_to_udint, checked_sint_to_udint: i8 => u32;
    sint_to_ulint, checked_sint_to_ulint: i8 => u64;
    sint_to_real, checked_sint_to_real: i8 => f32;
    sint_to_lreal, checked_sint_to_lreal: i8 => f64;
    sint_to_byte, checked_sint_to_byte: i8 => u8;
    sint_to_word, checked_sint_to_word: i8 => u16;
    sint_to_dword, checked_sint_to_dword: i8 => u32;
    sint_to_lword, checked_sint_to_lword: i8 => u64;
    int_to_bool, checked_int_to_bool: i16 => bool;
    int_to_sint, checked_int_to_sint: i16 => i8;
    int_to_dint, checked_int_to_dint: i16 => i32;
    int_to_lint, checked_int_to_lint: i16 => i64;
    int_to_usint, checked_int_to_usint: i16 => u8;
    int_to_uint, checked_int_to_uint: i16 => u16;
    int_to_udint, checked_int_to_udint: i16 => u32;
    int_to_ulint, checked_int_to_ulint: i16 => u64;
    int_to_real, checked_int_to_real: i16 => f32;
    int_to_lreal, checked_int_to_lreal: i16 => f64;
    int_to_byte, checked_int_to_byte: i16 => u8;
    int_to_word, checked_int_to_word: i16 => u16;
    int_to_dword, checked_int_to_dword: i16 => u32;
    int_to_lword, checked_int_to_lword: i16 => u64;
    dint_to_bool, checked_dint_to_bool: i32 => bool;
    dint_to_sint, checked_dint_to_sint: i32 => i8;
    dint_to_int, checked_dint_to_int: i32 => i16;
    dint_to_lint, checked_dint_to_lint: i32 => i64;
    dint_to_usint, checked_dint_to_usint: i32 => u8;
    dint_to_uint, checked_dint_to_uint: i32 => u16;
    dint_to_udint, checked_dint_to_udint: i32 => u32;
    dint_to_ulint, checked_dint_to_ulint: i32 => u64;
    dint_to_real, checked_dint_to_real: i32 => f32;
    dint_to_lreal, checked_dint_to_lreal: i32 => f64;
    dint_to_byte, checked_dint_to_byte: i32 => u8;
    dint_to_word, checked_dint_to_word: i32 => u16;
    dint_to_dword, checked_dint_to_dword: i32 => u32;
    dint_to_lword, checked_dint_to_lword: i32 => u64;
    lint_to_bool, checked_lint_to_bool: i64 => bool;
    lint_to_sint, checked_lint_to_sint: i64 => i8;
    lint_to_int, checked_lint_to_int: i64 => i16;
    lint_to_dint, checked_lint_to_dint: i64 => i32;
    lint_to_usint, checked_lint_to_usint: i64 => u8;
    lint_to_uint, checked_lint_to_uint: i64 => u16;
    lint_to_udint, checked_lint_to_udint: i64 => u32;
    lint_to_ulint, checked_lint_to_ulint: i64 => u64;
    lint_to_real, checked_lint_to_real: i64 => f32;
    lint_to_lreal, checked_lint_to_lreal: i64 => f64;
    lint_to_byte, checked_lint_to_byte: i64 => u8;
    lint_to_word, checked_lint_to_word: i64 => u16;
    lint_to_dword, checked_lint_to_dword: i64 => u32;
    lint_to_lword, checked_lint_to_lword: i64 => u64;
    usint_to_bool, checked_usint_to_bool: u8 => bool;
    usint_to_sint, checked_usint_to_sint: u8 => i8;
    usint_to_int, checked_usint_to_int: u8 => i16;
    usint_to_dint, checked_usint_to_dint: u8 => i32;
    usint_to_lint, checked_usint_to_lint: u8 => i64;
    usint_to_uint, checked_usint_to_uint: u8 => u16;
    usint_to_udint, checked_usint_to_udint: u8 => u32;
    usint_to_ulint, checked_usint_to_ulint: u8 => u64;
    usint_to_real, checked_usint_to_real: u8 => f32;
    usint_to_lreal, checked_usint_to_lreal: u8 => f64;
    usint_to_byte, checked_usint_to_byte: u8 => u8;
    usint_to_word, checked_usint_to_word: u8 => u16;
    usint_to_dword, checked_usint_to_dword: u8 => u32;
    usint_to_lword, checked_usint_to_lword: u8 => u64;
    uint_to_bool, checked_uint_to_bool: u16 => bool;
    uint_to_sint, checked_uint_to_sint: u16 => i8;
    uint_to_int, checked_uint_to_int: u16 => i16;
    uint_to_dint, checked_uint_to_dint: u16 => i32;
    uint_to_lint, checked_uint_to_lint: u16 => i64;
    uint_to_usint, checked_uint_to_usint: u16 => u8;
    uint_to_udint, checked_uint_to_udint: u16 => u32;
    uint_to_ulint, checked_uint_to_ulint: u16 => u64;
    uint_to_real, checked_uint_to_real: u16 => f32;
    uint_to_lreal, checked_uint_to_lreal: u16 => f64;
    uint_to_byte, checked_uint_to_byte: u16 => u8;
    uint_to_word, checked_uint_to_word: u16 => u16;
    uint_to_dword, checked_uint_to_dword: u16 => u32;
    uint_to_lword, checked_uint_to_lword: u16 => u64;
    udint_to_bool, checked_udint_to_bool: u32 => bool;
    udint_to_sint, checked_udint_to_sint: u32 => i8;
    udint_to_int, checked_udint_to_int: u32 => i16;
    udint_to_dint, checked_udint_to_dint: u32 => i32;
    udint_to_lint, checked_udint_to_lint: u32 => i64;
    udint_to_usint, checked_udint_to_usint: u32 => u8;
    udint_to_uint, checked_udint_to_uint: u32 => u16;
    udint_to_ulint, checked_udint_to_ulint: u32 => u64;
    udint_to_real, checked_udint_to_real: u32 => f32;
    udint_to_lreal, checked_udint_to_lreal: u32 => f64;
    udint_to_byte, checked_udint_to_byte: u32 => u8;
    udint_to_word, checked_udint_to_word: u32 => u16;
    udint_to_dword, checked_udint_to_dword: u32 => u32;
    udint_to_lword, checked_udint_to_lword: u32 => u64;
    ulint_to_bool, checked_ulint_to_bool: u64 => bool;
    ulint_to_sint, checked_ulint_to_sint: u64 => i8;
    ulint_to_int, checked_ulint_to_int: u64 => i16;
    ulint_to_dint, checked_ulint_to_dint: u64 => i32;
    ulint_to_lint, checked_ulint_to_lint: u64 => i64;
    ulint_to_usint, checked_ulint_to_usint: u64 => u8;
    ulint_to_uint, checked_ulint_to_uint: u64 => u16;
    ulint_to_udint, checked_ulint_to_udint: u64 => u32;
    ulint_to_real, checked_ulint_to_real: u64 => f32;
    ulint_to_lreal, checked_ulint_to_lreal: u64 => f64;
    ulint_to_byte, checked_ulint_to_byte: u64 => u8;
    ulint_to_word, checked_ulint_to_word: u64 => u16;
    ulint_to_dword, checked_ulint_to_dword: u64 => u32;
    ulint_to_lword, checked_ulint_to_lword: u64 => u64;
    real_to_bool, checked_real_to_bool: f32 => bool;
    real_to_sint, checked_real_to_sint: f32 => i8;
    real_to_int, checked_real_to_int: f32 => i16;
    real_to_dint, checked_real_to_dint: f32 => i32;
    real_to_lint, checked_real_to_lint: f32 => i64;
    real_to_usint, checked_real_to_usint: f32 => u8;
    real_to_uint, checked_real_to_uint: f32 => u16;
    real_to_udint, checked_real_to_udint: f32 => u32;
    real_to_ulint, checked_real_to_ulint: f32 => u64;
    real_to_lreal, checked_real_to_lreal: f32 => f64;
    real_to_byte, checked_real_to_byte: f32 => u8;
    real_to_word, checked_real_to_word: f32 => u16;
    real_to_dword, checked_real_to_dword: f32 => u32;
    real_to_lword, checked_real_to_lword: f32 => u64;
    lreal_to_bool, checked_lreal_to_bool: f64 => bool;
    lreal_to_sint, checked_lreal_to_sint: f64 => i8;
    lreal_to_int, checked_lreal_to_int: f64 => i16;
    lreal_to_dint, checked_lreal_to_dint: f64 => i32;
    lreal_to_lint, checked_lreal_to_lint: f64 => i64;
    lreal_to_usint, checked_lreal_to_usint: f64 => u8;
    lreal_to_uint, checked_lreal_to_uint: f64 => u16;
    lreal_to_udint, checked_lreal_to_udint: f64 => u32;
    lreal_to_ulint, checked_lreal_to_ulint: f64 => u64;
    lreal_to_real, checked_lreal_to_real: f64 => f32;
    lreal_to_byte, checked_lreal_to_byte: f64 => u8;
    lreal_to_word, checked_lreal_to_word: f64 => u16;
    lreal_to_dword, checked_lreal_to_dword: f64 => u32;
    lreal_to_lword, checked_lreal_to_lword: f64 => u64;
    byte_to_bool, checked_byte_to_bool: u8 => bool;
    byte_to_sint, checked_byte_to_sint: u8 => i8;
    byte_to_int, checked_byte_to_int: u8 => i16;
    byte_to_dint, checked_byte_to_dint: u8 => i32;
    byte_to_lint, checked_byte_to_lint: u8 => i64;
    byte_to_usint, checked_byte_to_usint: u8 => u8;
    byte_to_uint, checked_byte_to_uint: u8 => u16;
    byte_to_udint, checked_byte_to_udint: u8 => u32;
    byte_to_ulint, checked_byte_to_ulint: u8 => u64;
    byte_to_real, checked_byte_to_real: u8 => f32;
    byte_to_lreal, checked_byte_to_lreal: u8 => f64;
    byte_to_word, checked_byte_to_word: u8 => u16;
    byte_to_dword, checked_byte_to_dword: u8 => u32;
    byte_to_lword, checked_byte_to_lword: u8 => u64;
    word_to_bool, checked_word_to_bool: u16 => bool;
    word_to_sint, checked_word_to_sint: u16 => i8;
    word_to_int, checked_word_to_int: u16 => i16;
    word_to_dint, checked_word_to_dint: u16 => i32;
    word_to_lint, checked_word_to_lint: u16 => i64;
    word_to_usint, checked_word_to_usint: u16 => u8;
    word_to_uint, checked_word_to_uint: u16 => u16;
    word_to_udint, checked_word_to_udint: u16 => u32;
    word_to_ulint, checked_word_to_ulint: u16 => u64;
    word_to_real, checked_word_to_real: u16 => f32;
    word_to_lreal, checked_word_to_lreal: u16 => f64;
    word_to_byte, checked_word_to_byte: u16 => u8;
    word_to_dword, checked_word_to_dword: u16 => u32;
    word_to_lword, checked_word_to_lword: u16 => u64;
    dword_to_bool, checked_dword_to_bool: u32 => bool;
    dword_to_sint, checked_dword_to_sint: u32 => i8;
    dword_to_int, checked_dword_to_int: u32 => i16;
    dword_to_dint, checked_dword_to_dint: u32 => i32;
    dword_to_lint, checked_dword_to_lint: u32 => i64;
    dword_to_usint, checked_dword_to_usint: u32 => u8;
    dword_to_uint, checked_dword_to_uint: u32 => u16;
    dword_to_udint, checked_dword_to_udint: u32 => u32;
    dword_to_ulint, checked_dword_to_ulint: u32 => u64;
    dword_to_real, checked_dword_to_real: u32 => f32;
    dword_to_lreal, checked_dword_to_lreal: u32 => f64;
    dword_to_byte, checked_dword_to_byte: u32 => u8;
    dword_to_word, checked_dword_to_word: u32 => u16;
    dword_to_lword, checked_dword_to_lword: u32 => u64;
    lword_to_bool, checked_lword_to_bool: u64 => bool;
    lword_to_sint, checked_lword_to_sint: u64 => i8;
    lword_to_int, checked_lword_to_int: u64 => i16;
    lword_to_dint, checked_lword_to_dint: u64 => i32;
    lword_to_lint, checked_lword_to_lint: u64 => i64;
    lword_to_usint, checked_lword_to_usint: u64 => u8;
    lword_to_uint, checked_lword_to_uint: u64 => u16;
    lword_to_udint, checked_lword_to_udint: u64 => u32;
    lword_to_ulint, checked_lword_to_ulint: u64 => u64;
    lword_to_real, checked_lword_to_real: u64 => f32;
    lword_to_lreal, checked_lword_to_lreal: u64 => f64;
    lword_to_byte, checked_lword_to_byte: u64 => u8;
    lword_to_word, checked_lword_to_word: u64 => u16;
    lword_to_dword, checked_lword_to_dword: u64 => u32;
}
