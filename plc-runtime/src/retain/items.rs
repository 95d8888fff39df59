//! What a retain file holds: one item per nonvolatile variable, and one per nonvolatile member
//! of a structure, named by its path with each array of structures' element by coordinates
//! (`axes[1].cycles`). Matching items by path keeps a member's value when members are added,
//! removed or retyped around it, and an array of structures grown or shrunk keeps the elements
//! it still has.

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

/// Every retained item of a program's variables, in declaration order.
pub(super) fn items(vars: &'static [VarInfo]) -> Vec<Item> {
    let mut out = Vec::new();
    for (index, v) in vars.iter().enumerate() {
        walk(v, v.name.to_string(), index, 0, &mut out);
    }
    out
}

/// The items inside `v` (path `path`, starting at leaf `first` of variable `index`).
fn walk(v: &'static VarInfo, path: String, index: usize, first: usize, out: &mut Vec<Item>) {
    if !v.is_structured() {
        if v.nonvolatile {
            out.push(Item {
                path,
                iec_type: v.iec_type,
                index,
                first_leaf: first,
                elements: v.elements(),
            });
        }
        return;
    }
    let per_element = plc_rules::path::element_leaves(v);
    for element in 0..v.elements() {
        let base = first + element * per_element;
        let at = if v.dims.is_empty() {
            path.clone()
        } else {
            format!("{path}[{}]", plc_rules::path::coordinates(element, v.dims))
        };
        let mut leaf = base;
        for m in v.members() {
            walk(m, format!("{at}.{}", m.name), index, leaf, out);
            leaf += m.leaves();
        }
    }
}
