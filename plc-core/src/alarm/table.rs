//! The derive's flat alarm tables, built at compile time. A structure's table
//! (`PlcType::ALARMS`) counts leaves from the structure's start; each instance of it in a
//! program, or in another structure, gets a copy moved to its own leaves, so the evaluator
//! reads one flat table without following structures at run time.
//!
//! The derive sizes the table with [`count`] in a `const` of its own and fills it with
//! [`flatten`]; both run in the compiler.

use super::decl::{AlarmDecl, SuppressWhen};

/// A run of alarms of one field: its own alarm (once per element of an array of bools), or
/// the alarms of its structure type (once per element of an array of structures).
#[derive(Clone, Copy)]
pub struct Part {
    /// The field's variable index in the table being built (a member's index in a
    /// structure's table).
    pub index: usize,
    /// The field's first leaf in the table's leaf numbering (0 in a program's table; the
    /// member's first leaf in a structure's).
    pub base: usize,
    /// The alarms of one element.
    pub table: &'static [AlarmDecl],
    /// Elements: 1 for a scalar or structure, the product of the dimensions for an array.
    pub elements: usize,
    /// Leaves of one element.
    pub stride: usize,
    /// Whether `table` is a structure type's: its leaves and its suppressing bools count
    /// from the structure's start, so they move with the instance.
    pub nested: bool,
}

/// Alarms in all parts.
pub const fn count(parts: &[Part]) -> usize {
    let mut n = 0;
    let mut i = 0;
    while i < parts.len() {
        n += parts[i].table.len() * parts[i].elements;
        i += 1;
    }
    n
}

/// Leaves of one element of a type of `leaves` leaves in `elements` elements.
pub const fn stride(leaves: usize, elements: usize) -> usize {
    match leaves.checked_div(elements) {
        Some(n) => n,
        None => 0,
    }
}

/// The part of a field of a structure type (`leaves` and `elements` its type's): `table`,
/// the structure's alarms, once per element.
pub const fn nested(
    table: &'static [AlarmDecl],
    leaves: usize,
    elements: usize,
    index: usize,
    base: usize,
) -> Part {
    Part {
        index,
        base,
        table,
        elements,
        stride: stride(leaves, elements),
        nested: true,
    }
}

/// The table of `parts`, in order; `N` is [`count`] of them.
pub const fn flatten<const N: usize>(parts: &[Part]) -> [AlarmDecl; N] {
    const EMPTY: AlarmDecl = AlarmDecl::new(0, 0, "", super::decl::Condition::discrete(true));
    let mut out = [EMPTY; N];
    let mut n = 0;
    let mut p = 0;
    while p < parts.len() {
        let part = &parts[p];
        let mut e = 0;
        while e < part.elements {
            let first = part.base + e * part.stride;
            let mut a = 0;
            while a < part.table.len() {
                let mut d = part.table[a];
                d.index = part.index;
                d.leaf += first;
                if part.nested
                    && let SuppressWhen::At { leaf, .. } = d.suppress_when
                {
                    d.suppress_when = SuppressWhen::At {
                        index: part.index,
                        leaf: leaf + first,
                    };
                }
                out[n] = d;
                n += 1;
                a += 1;
            }
            e += 1;
        }
        p += 1;
    }
    out
}
