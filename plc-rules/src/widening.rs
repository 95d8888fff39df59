//! Implicit widening, as the IEC 61131-3 type hierarchy lays it out (as IronPLC documents it).
//!
//! The three matrices are written here as they appear there (rows: source, columns:
//! target), so a reader can compare them cell by cell. On top of them, as plc-vars defines it: a type
//! widens to itself; `REAL` widens to `LREAL` (the widening rule itself: every `REAL` is exactly
//! representable as an `LREAL`); `BOOL` never widens; real to integer and integer to bit string
//! are never implicit. IEC 61131-3's cross-family table (bit string to integer) is a vendor
//! extension, off unless [`WideningOptions::cross_family`] is set.
//!
//! Note: `LINT`/`ULINT` to `LREAL` is allowed because the matrix says so, though an `f64`
//! holds 53 significant bits: values beyond 2^53 are rounded.
//!
//! ```
//! use plc_rules::IecType::*;
//! use plc_rules::widening::{can_widen, can_widen_with, WideningOptions};
//! assert!(can_widen(Int, Dint));
//! assert!(!can_widen(Dint, Real));
//! assert!(!can_widen(Byte, Int));
//! assert!(can_widen_with(Byte, Int, WideningOptions { cross_family: true }));
//! ```

use crate::IecType::{self, *};

/// Options of [`can_widen_with`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WideningOptions {
    /// Allow the cross-family widening: a bit string to an integer of strictly greater
    /// width (IronPLC's `--allow-cross-family-widening`).
    pub cross_family: bool,
}

const Y: bool = true;
const N: bool = false;

/// Order of rows and columns of the integer matrices.
pub const INTEGER_ORDER: [IecType; 8] = [Sint, Int, Dint, Lint, Usint, Uint, Udint, Ulint];
/// Order of rows and columns of the bit-string matrix (and rows of the cross-family one).
pub const BIT_STRING_ORDER: [IecType; 4] = [Byte, Word, Dword, Lword];
/// Order of the columns of the integer-to-real matrix.
pub const REAL_ORDER: [IecType; 2] = [Real, Lreal];

/// IEC 61131-3, "Implicit integer widening matrix" (`=` written as Yes).
pub const INTEGER_MATRIX: [[bool; 8]; 8] = [
    //      SINT INT DINT LINT USINT UINT UDINT ULINT
    /* SINT  */
    [Y, Y, Y, Y, N, N, N, N],
    /* INT   */ [N, Y, Y, Y, N, N, N, N],
    /* DINT  */ [N, N, Y, Y, N, N, N, N],
    /* LINT  */ [N, N, N, Y, N, N, N, N],
    /* USINT */ [N, Y, Y, Y, Y, Y, Y, Y],
    /* UINT  */ [N, N, Y, Y, N, Y, Y, Y],
    /* UDINT */ [N, N, N, Y, N, N, Y, Y],
    /* ULINT */ [N, N, N, N, N, N, N, Y],
];

/// IEC 61131-3, "Implicit integer to real widening matrix".
pub const INTEGER_TO_REAL_MATRIX: [[bool; 2]; 8] = [
    //       REAL LREAL
    /* SINT  */ [Y, Y],
    /* INT   */ [Y, Y],
    /* DINT  */ [N, Y],
    /* LINT  */ [N, Y],
    /* USINT */ [Y, Y],
    /* UINT  */ [Y, Y],
    /* UDINT */ [N, Y],
    /* ULINT */ [N, Y],
];

/// IEC 61131-3, "Implicit bit-string widening matrix".
pub const BIT_STRING_MATRIX: [[bool; 4]; 4] = [
    //      BYTE WORD DWORD LWORD
    /* BYTE  */ [Y, Y, Y, Y],
    /* WORD  */ [N, Y, Y, Y],
    /* DWORD */ [N, N, Y, Y],
    /* LWORD */ [N, N, N, Y],
];

/// IEC 61131-3, "Cross-family widening: bit-string to integer" (needs the option).
pub const CROSS_FAMILY_MATRIX: [[bool; 8]; 4] = [
    //      SINT INT DINT LINT USINT UINT UDINT ULINT
    /* BYTE  */
    [N, Y, Y, Y, N, Y, Y, Y],
    /* WORD  */ [N, N, Y, Y, N, N, Y, Y],
    /* DWORD */ [N, N, N, Y, N, N, N, Y],
    /* LWORD */ [N, N, N, N, N, N, N, N],
];

const fn position(order: &[IecType], t: IecType) -> Option<usize> {
    let mut i = 0;
    while i < order.len() {
        if order[i] as u8 == t as u8 {
            return Some(i);
        }
        i += 1;
    }
    None
}

/// Whether a value of `from` may implicitly become a `to` (IEC 61131-3, cross-family off).
pub const fn can_widen(from: IecType, to: IecType) -> bool {
    can_widen_with(
        from,
        to,
        WideningOptions {
            cross_family: false,
        },
    )
}

/// Whether a value of `from` may implicitly become a `to`, with the given options.
pub const fn can_widen_with(from: IecType, to: IecType, options: WideningOptions) -> bool {
    if matches!(from, Bool) || matches!(to, Bool) {
        // BOOL has boolean semantics; it is no numeric bit container (IEC 61131-3).
        return from as u8 == to as u8;
    }
    if from as u8 == to as u8 {
        return true;
    }
    let int_from = position(&INTEGER_ORDER, from);
    let bits_from = position(&BIT_STRING_ORDER, from);
    if let (Some(f), Some(t)) = (int_from, position(&INTEGER_ORDER, to)) {
        return INTEGER_MATRIX[f][t];
    }
    if let (Some(f), Some(t)) = (int_from, position(&REAL_ORDER, to)) {
        return INTEGER_TO_REAL_MATRIX[f][t];
    }
    if let (Some(f), Some(t)) = (bits_from, position(&BIT_STRING_ORDER, to)) {
        return BIT_STRING_MATRIX[f][t];
    }
    if let (Some(f), Some(t)) = (bits_from, position(&INTEGER_ORDER, to)) {
        return options.cross_family && CROSS_FAMILY_MATRIX[f][t];
    }
    // REAL -> LREAL: the full range of REAL is exactly representable in LREAL.
    matches!(from, Real) && matches!(to, Lreal)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The matrices as text, copied cell by cell, so a typo in the tables above is caught
    /// by a second, independent transcription.
    const MATRIX_INTEGER: &str = "
        SINT  = Yes Yes Yes No No No No
        INT   No = Yes Yes No No No No
        DINT  No No = Yes No No No No
        LINT  No No No = No No No No
        USINT No Yes Yes Yes = Yes Yes Yes
        UINT  No No Yes Yes No = Yes Yes
        UDINT No No No Yes No No = Yes
        ULINT No No No No No No No =";
    const MATRIX_INT_REAL: &str = "
        SINT Yes Yes
        INT Yes Yes
        DINT No Yes
        LINT No Yes
        USINT Yes Yes
        UINT Yes Yes
        UDINT No Yes
        ULINT No Yes";
    const MATRIX_BITS: &str = "
        BYTE = Yes Yes Yes
        WORD No = Yes Yes
        DWORD No No = Yes
        LWORD No No No =";
    const MATRIX_CROSS: &str = "
        BYTE No Yes Yes Yes No Yes Yes Yes
        WORD No No Yes Yes No No Yes Yes
        DWORD No No No Yes No No No Yes
        LWORD No No No No No No No No";

    fn check(matrix: &str, columns: &[IecType], options: WideningOptions) -> usize {
        let mut cells = 0;
        for line in matrix.lines().filter(|l| !l.trim().is_empty()) {
            let mut words = line.split_whitespace();
            let from: IecType = words.next().unwrap().parse().unwrap();
            for (cell, &to) in words.zip(columns) {
                let expected = cell != "No";
                assert_eq!(
                    can_widen_with(from, to, options),
                    expected,
                    "{from} -> {to}"
                );
                cells += 1;
            }
        }
        cells
    }

    #[test]
    fn every_cell_of_the_three_matrices_holds() {
        let off = WideningOptions::default();
        assert_eq!(check(MATRIX_INTEGER, &INTEGER_ORDER, off), 64);
        assert_eq!(check(MATRIX_INT_REAL, &REAL_ORDER, off), 16);
        assert_eq!(check(MATRIX_BITS, &BIT_STRING_ORDER, off), 16);
    }

    #[test]
    fn cross_family_cells_hold_only_with_the_option() {
        let on = WideningOptions { cross_family: true };
        assert_eq!(check(MATRIX_CROSS, &INTEGER_ORDER, on), 32);
        for b in BIT_STRING_ORDER {
            for i in INTEGER_ORDER {
                assert!(!can_widen(b, i), "{b} -> {i} must need the option");
            }
        }
    }

    #[test]
    fn rules_beyond_the_matrices() {
        for t in IecType::ALL {
            assert!(can_widen(t, t), "{t} to itself");
            if t != Bool {
                assert!(
                    !can_widen(Bool, t) && !can_widen(t, Bool),
                    "BOOL never widens: {t}"
                );
            }
        }
        assert!(can_widen(Real, Lreal));
        assert!(!can_widen(Lreal, Real));
        for i in INTEGER_ORDER {
            for r in REAL_ORDER {
                assert!(!can_widen(r, i), "real to integer is never implicit");
            }
            for b in BIT_STRING_ORDER {
                let on = WideningOptions { cross_family: true };
                assert!(
                    !can_widen_with(i, b, on),
                    "integer to bit string is never implicit"
                );
            }
        }
        for b in BIT_STRING_ORDER {
            assert!(!can_widen(b, Real) && !can_widen(b, Lreal));
        }
        assert!(!can_widen(String, Lreal) && !can_widen(Lreal, String));
    }
}
