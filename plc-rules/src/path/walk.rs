//! The one walk over a declaration's values: every structure (and each element of an array of
//! structures) before its members, and every basic variable or member with its path, the
//! basic values it holds, its byte offset in the image and whether tools may write it. The
//! retained values, the OPC UA address space, the `plc` commands and the benchmarks all see a
//! program's variables through it, from the derive's tables and a segment's descriptor alike.
//!
//! ```
//! # use plc_rules::access::{Access, Direction};
//! # use plc_rules::path::Node;
//! # struct V { name: &'static str, dims: Vec<usize>, offset: usize, size: usize, members: Vec<V> }
//! # impl Node for V {
//! #     fn name(&self) -> &str { self.name }
//! #     fn dims(&self) -> &[usize] { &self.dims }
//! #     fn offset(&self) -> usize { self.offset }
//! #     fn size(&self) -> usize { self.size }
//! #     fn members(&self) -> &[V] { &self.members }
//! #     fn access(&self) -> Access { Access::ReadWrite }
//! #     fn direction(&self) -> Direction { Direction::Internal }
//! # }
//! # let basic = |name, offset, size| V { name, dims: vec![], offset, size, members: vec![] };
//! use plc_rules::path::{Visit, walk};
//! // `speed: f32` at 0, then `axes: [Axis; 2]` at 4, an Axis being `pos: f64` and `on: bool`.
//! let axis = |name| V { name, dims: vec![2], offset: 4, size: 32,
//!     members: vec![basic("pos", 0, 8), basic("on", 8, 1)] };
//! let vars = [basic("speed", 0, 4), axis("axes")];
//! let mut seen = Vec::new();
//! walk(&vars, |visit| match visit {
//!     Visit::Structure(s) => seen.push(format!("{} {{", s.path)),
//!     Visit::Basic(b) => seen.push(format!("{} @{} leaf {}", b.path, b.offset, b.first_leaf)),
//! });
//! assert_eq!(seen, [
//!     "speed @0 leaf 0",
//!     "axes[0] {", "axes[0].pos @4 leaf 0", "axes[0].on @12 leaf 1",
//!     "axes[1] {", "axes[1].pos @20 leaf 2", "axes[1].on @28 leaf 3",
//! ]);
//! ```

use super::{Node, coordinates, element_leaves, leaves, member_writable};
use crate::access::writable_from_outside;
use crate::capacity::MAX_STRUCT_DEPTH;
use std::format;
use std::string::{String, ToString};

/// A structure the walk enters: a structured variable or member, or one element of an array
/// of them. Its members follow it.
#[derive(Debug)]
pub struct Structure<'n, N> {
    /// Its path: `axis`, `axes[1]`, `line.axes[0,1]`.
    pub path: String,
    /// Its own name as a child of its parent: `axis`, `axes[1]`.
    pub name: String,
    /// The path of the structure it is in; `None` at the top level.
    pub parent: Option<String>,
    /// The variable or member.
    pub node: &'n N,
}

/// A basic variable or member: one value, or an array of basic values whole.
#[derive(Debug)]
pub struct Basic<'n, N> {
    /// Index of the top-level variable it is in.
    pub index: usize,
    /// Its first basic value among that variable's leaves; its elements follow.
    pub first_leaf: usize,
    /// The variable or member.
    pub node: &'n N,
    /// Its path, as `plc get` takes it.
    pub path: String,
    /// The path of the structure it is in; `None` at the top level.
    pub parent: Option<String>,
    /// Byte offset of its first element in the image.
    pub offset: usize,
    /// Whether tools may write it: the variable and every member on the way are writable.
    pub writable: bool,
}

/// What [`walk`] meets.
#[derive(Debug)]
pub enum Visit<'n, N> {
    /// A structure, before its members.
    Structure(Structure<'n, N>),
    /// A basic variable or member.
    Basic(Basic<'n, N>),
}

/// Calls `visit` with every structure and basic value of `vars`, in declaration order. A
/// description nested deeper than a declaration can be (one read from another process) is
/// walked no deeper: the walk is bounded whatever it is given.
pub fn walk<'n, N: Node>(vars: &'n [N], mut visit: impl FnMut(Visit<'n, N>)) {
    for (index, var) in vars.iter().enumerate() {
        let at = At {
            index,
            first_leaf: 0,
            offset: var.offset(),
            writable: writable_from_outside(var.access(), var.direction()),
            parent: None,
        };
        visit_node(var, var.name().to_string(), at, 0, &mut visit);
    }
}

/// Where a node sits, as the walk carries it down.
struct At {
    index: usize,
    first_leaf: usize,
    offset: usize,
    writable: bool,
    parent: Option<String>,
}

fn visit_node<'n, N: Node>(
    node: &'n N,
    path: String,
    at: At,
    depth: usize,
    visit: &mut impl FnMut(Visit<'n, N>),
) {
    if node.members().is_empty() {
        visit(Visit::Basic(Basic {
            index: at.index,
            first_leaf: at.first_leaf,
            node,
            path,
            parent: at.parent,
            offset: at.offset,
            writable: at.writable,
        }));
        return;
    }
    if depth > MAX_STRUCT_DEPTH {
        return;
    }
    let elements = crate::access::elements(node.dims());
    let element_size = node.size().checked_div(elements).unwrap_or(0);
    let per_element = element_leaves(node);
    for e in 0..elements {
        let (here, name) = if node.dims().is_empty() {
            (path.clone(), node.name().to_string())
        } else {
            let c = coordinates(e, node.dims());
            (format!("{path}[{c}]"), format!("{}[{c}]", node.name()))
        };
        visit(Visit::Structure(Structure {
            path: here.clone(),
            name,
            parent: at.parent.clone(),
            node,
        }));
        let base = at.offset.saturating_add(e.saturating_mul(element_size));
        let mut leaf = at.first_leaf.saturating_add(e.saturating_mul(per_element));
        for m in node.members() {
            let inner = At {
                index: at.index,
                first_leaf: leaf,
                offset: base.saturating_add(m.offset()),
                writable: at.writable && member_writable(m.access()),
                parent: Some(here.clone()),
            };
            visit_node(m, format!("{here}.{}", m.name()), inner, depth + 1, visit);
            leaf = leaf.saturating_add(leaves(m));
        }
    }
}
