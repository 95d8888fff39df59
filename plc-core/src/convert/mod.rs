//! Type conversions (IEC 61131-3): implicit widening and the explicit conversion functions.
//!
//! - [`can_widen`] / [`can_widen_with`]: IEC 61131-3's widening matrices (from `plc-rules`).
//! - [`Widen`]: the implicit widenings as a Rust trait, implemented for exactly the pairs of Rust
//!   primitives that [`can_widen`] allows, so a forbidden widening does not compile.
//! - [`explicit`]: `dint_to_int`, `real_to_int`, ... with IEC semantics and `checked_` variants.
//!
//! ```
//! use plc_core::convert::Widen;
//! let wide: i32 = 5i16.widen();
//! let real: f64 = 7u32.widen();
//! assert_eq!((wide, real), (5, 7.0));
//! ```
//!
//! A narrowing or lossy conversion is a compile error:
//!
//! ```compile_fail
//! use plc_core::convert::Widen;
//! let r: f32 = 7i32.widen(); // DINT does not widen to REAL (IEC 61131-3)
//! ```

pub mod explicit;

pub use plc_rules::widening::{WideningOptions, can_widen, can_widen_with};

/// An implicit widening of IEC 61131-3 between Rust primitives: integer to a wider integer (an
/// unsigned one also to a strictly wider signed one), integer to `f32`/`f64` where exact, `f32`
/// to `f64`, and each type to itself.
///
/// `u64`/`i64` to `f64` is allowed because the IEC 61131-3 widening matrix says so; an `f64` holds 53
/// significant bits, so larger values are rounded.
#[diagnostic::on_unimplemented(
    message = "`{Self}` does not widen implicitly to `{T}` (IEC 61131-3)",
    label = "not an implicit widening",
    note = "convert explicitly with a `<source>_to_<target>` function of \
            `plc_core::convert::explicit`, named by the IEC types in snake case, such as \
            `real_to_lint` (f32 to i64) or `dint_to_int` (i32 to i16)"
)]
pub trait Widen<T> {
    /// The value as a `T`.
    fn widen(self) -> T;
}

macro_rules! widen {
    ($($from:ty => $($to:ty),+;)*) => {$($(
        impl Widen<$to> for $from {
            #[inline(always)]
            fn widen(self) -> $to {
                self as $to
            }
        }
    )+)*};
}

widen! {
    i8 => i8, i16, i32, i64, f32, f64;
    i16 => i16, i32, i64, f32, f64;
    i32 => i32, i64, f64;
    i64 => i64, f64;
    u8 => u8, u16, u32, u64, i16, i32, i64, f32, f64;
    u16 => u16, u32, u64, i32, i64, f32, f64;
    u32 => u32, u64, i64, f64;
    u64 => u64, f64;
    f32 => f32, f64;
    f64 => f64;
}

impl Widen<bool> for bool {
    #[inline(always)]
    fn widen(self) -> bool {
        self
    }
}

/// One explicit conversion with IEC semantics; the named functions in [`explicit`] call it.
pub(crate) trait Convert<T> {
    fn convert(self) -> T;
    fn checked(self) -> Option<T>;
}

macro_rules! each_pair {
    ($rule:ident: $($from:ty),* => $tos:tt) => { $( each_pair!(@one $rule, $from, $tos); )* };
    (@one $rule:ident, $from:ty, [$($to:ty),*]) => { $( $rule!($from, $to); )* };
}

macro_rules! int_to_int {
    ($from:ty, $to:ty) => {
        impl Convert<$to> for $from {
            #[inline]
            fn convert(self) -> $to {
                self as $to
            }
            #[inline]
            #[allow(irrefutable_let_patterns, clippy::useless_conversion)]
            fn checked(self) -> Option<$to> {
                <$to>::try_from(self).ok()
            }
        }
    };
}

macro_rules! int_to_real {
    ($from:ty, $to:ty) => {
        impl Convert<$to> for $from {
            #[inline]
            fn convert(self) -> $to {
                self as $to
            }
            #[inline]
            fn checked(self) -> Option<$to> {
                let r = self as $to;
                (r as i128 == self as i128).then_some(r)
            }
        }
    };
}

macro_rules! real_to_int {
    ($from:ty, $to:ty) => {
        impl Convert<$to> for $from {
            // `as` truncates toward zero, saturates at the bounds and maps NaN to 0.
            #[inline]
            fn convert(self) -> $to {
                self as $to
            }
            #[inline]
            fn checked(self) -> Option<$to> {
                // `as i128` truncates; equal after the round trip means a whole number (no
                // `f64::trunc` in `no_std`). Values beyond i128 saturate and fail either check.
                let whole = self as i128;
                if self.is_finite() && whole as $from == self {
                    <$to>::try_from(whole).ok()
                } else {
                    None
                }
            }
        }
    };
}

macro_rules! bool_to_num {
    ($from:ty, $to:ty) => {
        impl Convert<$to> for bool {
            #[inline]
            fn convert(self) -> $to {
                self as u8 as $to
            }
            #[inline]
            fn checked(self) -> Option<$to> {
                Some(self.convert())
            }
        }
    };
}

macro_rules! num_to_bool {
    ($from:ty, $to:ty) => {
        impl Convert<bool> for $from {
            #[inline]
            #[allow(clippy::float_cmp)]
            fn convert(self) -> bool {
                self != (0 as $from)
            }
            #[inline]
            #[allow(clippy::float_cmp)]
            fn checked(self) -> Option<bool> {
                match self {
                    v if v == (0 as $from) => Some(false),
                    v if v == (1 as $from) => Some(true),
                    _ => None,
                }
            }
        }
    };
}

each_pair!(int_to_int: i8, i16, i32, i64, u8, u16, u32, u64 => [i8, i16, i32, i64, u8, u16, u32, u64]);
each_pair!(int_to_real: i8, i16, i32, i64, u8, u16, u32, u64 => [f32, f64]);
each_pair!(real_to_int: f32, f64 => [i8, i16, i32, i64, u8, u16, u32, u64]);
each_pair!(bool_to_num: bool => [i8, i16, i32, i64, u8, u16, u32, u64, f32, f64]);
each_pair!(num_to_bool: i8, i16, i32, i64, u8, u16, u32, u64, f32, f64 => [bool]);

impl Convert<f64> for f32 {
    #[inline]
    fn convert(self) -> f64 {
        self as f64
    }
    #[inline]
    fn checked(self) -> Option<f64> {
        Some(self as f64)
    }
}

impl Convert<f32> for f64 {
    #[inline]
    fn convert(self) -> f32 {
        self as f32
    }
    #[inline]
    fn checked(self) -> Option<f32> {
        let r = self as f32;
        (r as f64 == self || self.is_nan()).then_some(r)
    }
}

#[cfg(test)]
mod tests {
    use super::explicit::*;
    use super::*;
    use crate::IecType;

    /// Detects at compile time whether `Widen<$to>` is implemented for `$from`, by autoref
    /// method resolution: the inherent-like trait on `&Probe` wins only when the bound holds.
    macro_rules! implements_widen {
        ($from:ty, $to:ty) => {{
            struct Probe<F, T>(core::marker::PhantomData<(F, T)>);
            #[allow(dead_code)]
            trait Yes {
                fn check(&self) -> bool {
                    true
                }
            }
            #[allow(dead_code)]
            trait No {
                fn check(&self) -> bool {
                    false
                }
            }
            impl<F: Widen<T>, T> Yes for Probe<F, T> {}
            impl<F, T> No for &Probe<F, T> {}
            (&Probe::<$from, $to>(core::marker::PhantomData)).check()
        }};
    }

    macro_rules! check_all {
        ($($from:ty : $fi:ident),* ; $tos:tt) => {{
            let mut checked = 0;
            $( check_all!(@row $from, $fi, $tos, checked); )*
            checked
        }};
        (@row $from:ty, $fi:ident, [$($to:ty : $ti:ident),*], $n:ident) => {$(
            assert_eq!(
                implements_widen!($from, $to),
                can_widen(IecType::$fi, IecType::$ti),
                "Widen<{}> for {}", stringify!($to), stringify!($from)
            );
            $n += 1;
        )*};
    }

    #[test]
    fn widen_impls_are_exactly_the_pairs_can_widen_allows() {
        let n = check_all!(
            bool: Bool, i8: Sint, i16: Int, i32: Dint, i64: Lint, u8: Usint, u16: Uint,
            u32: Udint, u64: Ulint, f32: Real, f64: Lreal;
            [bool: Bool, i8: Sint, i16: Int, i32: Dint, i64: Lint, u8: Usint, u16: Uint,
             u32: Udint, u64: Ulint, f32: Real, f64: Lreal]
        );
        assert_eq!(n, 121);
    }

    #[test]
    fn narrowing_integers_wrap() {
        assert_eq!(dint_to_int(100_000), -31_072);
        assert_eq!(int_to_usint(-1), 255);
        assert_eq!(ulint_to_lint(u64::MAX), -1);
        assert_eq!(checked_int_to_usint(-1), None);
        assert_eq!(checked_int_to_usint(200), Some(200));
        assert_eq!(dword_to_word(0x1234_5678), 0x5678);
        assert_eq!(byte_to_int(0xFF), 255);
    }

    #[test]
    fn real_to_integer_truncates_toward_zero_and_saturates() {
        assert_eq!(real_to_int(2.9), 2);
        assert_eq!(real_to_int(-2.9), -2);
        assert_eq!(lreal_to_dint(1e20), i32::MAX);
        assert_eq!(lreal_to_dint(-1e20), i32::MIN);
        assert_eq!(lreal_to_udint(-5.0), 0);
        assert_eq!(real_to_dint(f32::NAN), 0);
        assert_eq!(checked_real_to_int(2.0), Some(2));
        assert_eq!(checked_real_to_int(2.5), None);
        assert_eq!(checked_lreal_to_sint(128.0), None);
        assert_eq!(checked_lreal_to_lint(f64::INFINITY), None);
        assert_eq!(checked_lreal_to_lint(9.223372036854776e18), None);
    }

    #[test]
    fn to_real_rounds_and_checked_reports_inexact() {
        assert_eq!(dint_to_real(16_777_217), 16_777_216.0);
        assert_eq!(checked_dint_to_real(16_777_217), None);
        assert_eq!(checked_dint_to_real(16_777_216), Some(16_777_216.0));
        assert_eq!(checked_ulint_to_real(u64::MAX), None);
        assert_eq!(lreal_to_real(0.1), 0.1f32);
        assert_eq!(checked_lreal_to_real(0.1), None);
        assert_eq!(checked_lreal_to_real(0.5), Some(0.5));
        assert_eq!(lreal_to_real(1e300), f32::INFINITY);
        assert_eq!(real_to_lreal(1.5), 1.5);
    }

    #[test]
    fn bool_conversions() {
        assert_eq!(bool_to_int(true), 1);
        assert_eq!(bool_to_lreal(false), 0.0);
        assert!(dint_to_bool(-3));
        assert_eq!(checked_dint_to_bool(-3), None);
        assert_eq!(checked_byte_to_bool(1), Some(true));
        assert!(!real_to_bool(0.0));
    }
}
