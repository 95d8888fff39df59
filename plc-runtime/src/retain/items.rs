//! What a retain file holds: one item per nonvolatile variable, and one per nonvolatile member
//! of a structure, named by its path with each array of structures' element by coordinates
//! (`axes[1].cycles`). Matching items by path keeps a member's value when members are added,
//! removed or retyped around it, and an array of structures grown or shrunk keeps the elements
//! it still has.

use plc_core::rules::path::{Visit, walk};
use plc_core::{IecType, VarInfo};

/// One retained variable or member.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Item {
    /// Its path, as `plc get` takes it.
    pub path: String,
    /// Its IEC type (of one element).
    pub iec_type: IecType,
    /// The top-level variable it is in.
    pub index: usize,
    /// Its first basic value among that variable's leaves; its elements follow.
    pub first_leaf: usize,
    /// Its elements (1 for a scalar).
    pub elements: usize,
}

/// Every retained item of a program's variables, in declaration order: the nonvolatile basic
/// values of the one walk over the declaration.
pub(super) fn items(vars: &'static [VarInfo]) -> Vec<Item> {
    let mut out = Vec::new();
    walk(vars, |visit| {
        if let Visit::Basic(b) = visit
            && b.node.nonvolatile
        {
            out.push(Item {
                iec_type: b.node.iec_type,
                index: b.index,
                first_leaf: b.first_leaf,
                elements: b.node.elements(),
                path: b.path,
            });
        }
    });
    out
}
