//! Finding the one basic value a path names, in any description of the variables: the
//! derive's static `VarInfo` tables and a segment's descriptor both implement [`Node`], so a
//! program and a tool without its Rust types resolve every path the same way.
//!
//! A variable's basic values are numbered by its *leaves*: row-major over its array elements,
//! and inside a structure its members' leaves in declaration order. A scalar has one leaf, an
//! array of basic values one per element, `[Axis; 4]` four times an `Axis`'s leaves.

use super::{PathError, segments};
use crate::access::{Access, Direction};
use core::fmt;

/// One variable or member, as the path navigation needs to see it.
pub trait Node: Sized {
    /// Its symbol name.
    fn name(&self) -> &str;
    /// Array dimensions, outermost first; empty for a scalar.
    fn dims(&self) -> &[usize];
    /// Byte offset: in the image for a top-level variable, from the structure's start for a
    /// member.
    fn offset(&self) -> usize;
    /// Bytes of all its elements.
    fn size(&self) -> usize;
    /// A structure's members (empty for a basic type).
    fn members(&self) -> &[Self];
    /// Read-write or read-only.
    fn access(&self) -> Access;
    /// Its direction.
    fn direction(&self) -> Direction;
}

/// Basic values in `node`: its elements times the leaves of one element.
pub fn leaves<N: Node>(node: &N) -> usize {
    crate::access::elements(node.dims()).saturating_mul(element_leaves(node))
}

/// Basic values in one element of `node`: 1 for a basic type, else the sum of its members'.
pub fn element_leaves<N: Node>(node: &N) -> usize {
    if node.members().is_empty() {
        1
    } else {
        node.members()
            .iter()
            .fold(0usize, |n, m| n.saturating_add(leaves(m)))
    }
}

/// Whether tools may write a member of a structure: it is read-write. IN parameters
/// (`direction = "input"` inside a structure) are written by the caller of a function block,
/// so tools may set them as well; a physical input at the top level they may not.
pub const fn member_writable(access: Access) -> bool {
    matches!(access, Access::ReadWrite)
}

/// The basic value a path names.
#[derive(Debug, PartialEq)]
pub struct Found<'n, N> {
    /// Index of the top-level variable.
    pub index: usize,
    /// The value's leaf number within that variable.
    pub leaf: usize,
    /// The basic variable or member holding the value.
    pub node: &'n N,
    /// Element within `node` (0 for a scalar).
    pub element: usize,
    /// Byte offset of the value in the image.
    pub offset: usize,
    /// Whether tools may write it: the top-level variable and every member on the way are.
    pub writable: bool,
}

impl<N> Clone for Found<'_, N> {
    fn clone(&self) -> Self {
        *self
    }
}
impl<N> Copy for Found<'_, N> {}

/// Why a path names no basic value.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LocateError<'p> {
    /// The text is not a path.
    Syntax(PathError),
    /// No variable or member of this name at this level; `within` is the path before it ("" at
    /// the top level).
    NoSuchName {
        /// The name that was not found.
        name: &'p str,
        /// The path of the structure searched.
        within: &'p str,
    },
    /// The index does not fit the array named by `at`.
    Index {
        /// The path up to and including the array's name.
        at: &'p str,
        /// What is wrong with the index.
        error: PathError,
    },
    /// The path ends at an array: name one element (`grid[1,2]`).
    WholeArray {
        /// The path of the array.
        at: &'p str,
    },
    /// The path ends at a structure: name one of its members.
    WholeStructure {
        /// The path of the structure.
        at: &'p str,
    },
    /// A `.` after a basic value.
    NotAStructure {
        /// The path of the basic value.
        at: &'p str,
    },
}

impl fmt::Display for LocateError<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LocateError::Syntax(e) => write!(f, "not a path: {e}"),
            LocateError::NoSuchName { name, within: "" } => write!(f, "no variable `{name}`"),
            LocateError::NoSuchName { name, within } => {
                write!(f, "`{within}` has no member `{name}`")
            }
            LocateError::Index { at, error } => write!(f, "`{at}`: {error}"),
            LocateError::WholeArray { at } => {
                write!(f, "`{at}` is an array: name one element, such as `{at}[0]`")
            }
            LocateError::WholeStructure { at } => write!(
                f,
                "`{at}` is a structure: name one of its members, such as `{at}.<member>`"
            ),
            LocateError::NotAStructure { at } => {
                write!(f, "`{at}` is not a structure: it has no members")
            }
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for LocateError<'_> {}

/// The basic value `path` names among `vars` (case-insensitive names, 0-based indexes).
///
/// ```
/// # use plc_rules::path::{Node, locate};
/// # use plc_rules::{Access, Direction};
/// # struct V { name: &'static str, dims: Vec<usize>, offset: usize, size: usize, members: Vec<V> }
/// # impl Node for V {
/// #     fn name(&self) -> &str { self.name }
/// #     fn dims(&self) -> &[usize] { &self.dims }
/// #     fn offset(&self) -> usize { self.offset }
/// #     fn size(&self) -> usize { self.size }
/// #     fn members(&self) -> &[V] { &self.members }
/// #     fn access(&self) -> Access { Access::ReadWrite }
/// #     fn direction(&self) -> Direction { Direction::Internal }
/// # }
/// # let m = |name, offset, size| V { name, dims: vec![], offset, size, members: vec![] };
/// // axes: [Axis; 2] at offset 8, an Axis being { pos: f64, enable: bool } (9 bytes)
/// let vars = [m("count", 0, 8), V { name: "axes", dims: vec![2], offset: 8, size: 18,
///     members: vec![m("pos", 0, 8), m("enable", 8, 1)] }];
/// let found = locate(&vars, "AXES[1].enable").unwrap();
/// assert_eq!((found.index, found.leaf, found.offset), (1, 3, 8 + 9 + 8));
/// ```
pub fn locate<'n, 'p, N: Node>(
    vars: &'n [N],
    path: &'p str,
) -> Result<Found<'n, N>, LocateError<'p>> {
    let text = path.trim();
    let mut level: &'n [N] = vars;
    let mut found: Option<Found<'n, N>> = None;
    // Where the current segment ends in `text`, for naming the path walked so far.
    let mut consumed = 0usize;
    for segment in segments(text) {
        let segment = segment.map_err(LocateError::Syntax)?;
        let within = &text[..consumed.saturating_sub(1)];
        if let Some(f) = &found {
            if f.node.members().is_empty() {
                return Err(LocateError::NotAStructure { at: within });
            }
            if !f.node.dims().is_empty() && f.element_pending() {
                return Err(LocateError::WholeArray { at: within });
            }
        }
        let Some(pos) = level
            .iter()
            .position(|n| n.name().eq_ignore_ascii_case(segment.name))
        else {
            return Err(LocateError::NoSuchName {
                name: segment.name,
                within,
            });
        };
        let node = &level[pos];
        let mut step = match found {
            None => Found {
                index: pos,
                leaf: 0,
                node,
                element: 0,
                offset: node.offset(),
                writable: crate::access::writable_from_outside(node.access(), node.direction()),
            },
            Some(parent) => {
                let before = level[..pos]
                    .iter()
                    .fold(0usize, |n, m| n.saturating_add(leaves(m)));
                Found {
                    leaf: parent.leaf.saturating_add(before),
                    node,
                    element: 0,
                    offset: parent.offset.saturating_add(node.offset()),
                    writable: parent.writable && member_writable(node.access()),
                    ..parent
                }
            }
        };
        // The end of this segment in `text`: its name, then its index in brackets.
        consumed = segment_end(text, consumed, segment.name.len());
        match segment.index {
            Some(index) => {
                let at = &text[..consumed];
                let element = index
                    .flat(node.dims())
                    .map_err(|error| LocateError::Index { at, error })?;
                let elements = crate::access::elements(node.dims()).max(1);
                step.element = element;
                step.leaf = step
                    .leaf
                    .saturating_add(element.saturating_mul(element_leaves(node)));
                step.offset = step
                    .offset
                    .saturating_add(element.saturating_mul(node.size() / elements));
            }
            None if !node.dims().is_empty() => step.element = usize::MAX,
            None => {}
        }
        consumed += 1; // the `.` after it
        level = node.members();
        found = Some(step);
    }
    let at = &text[..consumed.saturating_sub(1).min(text.len())];
    let Some(f) = found else {
        return Err(LocateError::Syntax(PathError::MissingName));
    };
    if f.element_pending() {
        return Err(LocateError::WholeArray { at });
    }
    if !f.node.members().is_empty() {
        return Err(LocateError::WholeStructure { at });
    }
    Ok(f)
}

/// The basic value numbered `leaf` in variable `index` (the reverse of [`locate`]), or `None`
/// past the variable's leaves. Each level divides the number once, so the work is bounded by
/// the nesting depth.
pub fn leaf<N: Node>(vars: &[N], index: usize, leaf: usize) -> Option<Found<'_, N>> {
    let top = vars.get(index)?;
    if leaf >= leaves(top) {
        return None;
    }
    let mut found = Found {
        index,
        leaf,
        node: top,
        element: 0,
        offset: top.offset(),
        writable: crate::access::writable_from_outside(top.access(), top.direction()),
    };
    let mut rest = leaf;
    loop {
        let node = found.node;
        let per = element_leaves(node).max(1);
        let element = rest / per;
        rest %= per;
        let elements = crate::access::elements(node.dims()).max(1);
        found.offset = found
            .offset
            .saturating_add(element.saturating_mul(node.size() / elements));
        if node.members().is_empty() {
            found.element = element;
            return Some(found);
        }
        let mut before = 0usize;
        let member = node.members().iter().find(|m| {
            let n = leaves(*m);
            if rest < before.saturating_add(n) {
                true
            } else {
                before = before.saturating_add(n);
                false
            }
        })?;
        rest -= before;
        found = Found {
            node: member,
            offset: found.offset.saturating_add(member.offset()),
            writable: found.writable && member_writable(member.access()),
            ..found
        };
    }
}

impl<N> Found<'_, N> {
    /// An array was named without its index (kept as `usize::MAX` until the end, so the error
    /// can say which array).
    fn element_pending(&self) -> bool {
        self.element == usize::MAX
    }
}

/// Where a segment that starts at `start` with a name of `name_len` bytes ends: after its
/// bracketed index, if one follows.
fn segment_end(text: &str, start: usize, name_len: usize) -> usize {
    let after_name = start + name_len;
    if text.as_bytes().get(after_name) == Some(&b'[') {
        text[after_name..]
            .find(']')
            .map_or(text.len(), |i| after_name + i + 1)
    } else {
        after_name
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::access::{Access, Direction};
    use proptest::prelude::*;
    use std::string::{String, ToString};
    use std::vec::Vec;
    use std::{format, vec};

    #[derive(Clone, Debug)]
    struct V {
        name: String,
        dims: Vec<usize>,
        offset: usize,
        size: usize,
        members: Vec<V>,
        access: Access,
    }

    impl Node for V {
        fn name(&self) -> &str {
            &self.name
        }
        fn dims(&self) -> &[usize] {
            &self.dims
        }
        fn offset(&self) -> usize {
            self.offset
        }
        fn size(&self) -> usize {
            self.size
        }
        fn members(&self) -> &[V] {
            &self.members
        }
        fn access(&self) -> Access {
            self.access
        }
        fn direction(&self) -> Direction {
            Direction::Internal
        }
    }

    /// Lays out members one after the other from `shapes` (name, dims, scalar bytes or
    /// nested members), as the derive does.
    fn lay_out(vars: &mut [V]) -> usize {
        let mut at = 0;
        for v in vars.iter_mut() {
            let element = if v.members.is_empty() {
                v.size
            } else {
                lay_out(&mut v.members)
            };
            v.offset = at;
            v.size = element * crate::access::elements(&v.dims);
            at += v.size;
        }
        at
    }

    fn scalar(name: &str, bytes: usize) -> V {
        V {
            name: name.to_string(),
            dims: vec![],
            offset: 0,
            size: bytes,
            members: vec![],
            access: Access::ReadWrite,
        }
    }

    fn every_path(v: &V, prefix: String, out: &mut Vec<String>) {
        let elements = crate::access::elements(&v.dims);
        for e in 0..elements {
            let at = if v.dims.is_empty() {
                prefix.clone()
            } else {
                format!("{prefix}[{e}]")
            };
            if v.members.is_empty() {
                out.push(at);
            } else {
                for m in &v.members {
                    every_path(m, format!("{at}.{}", m.name), out);
                }
            }
        }
    }

    fn tree() -> impl Strategy<Value = Vec<V>> {
        let leaf =
            (1usize..9, proptest::collection::vec(1usize..4, 0..3)).prop_map(|(bytes, dims)| V {
                dims,
                ..scalar("x", bytes)
            });
        let node = leaf.prop_recursive(3, 24, 4, |inner| {
            (
                proptest::collection::vec(inner, 1..4),
                proptest::collection::vec(1usize..3, 0..2),
            )
                .prop_map(|(members, dims)| V {
                    dims,
                    members,
                    ..scalar("s", 0)
                })
        });
        proptest::collection::vec(node, 1..4)
    }

    /// Unique names per level, as the rules require.
    fn name_all(vars: &mut [V]) {
        for (i, v) in vars.iter_mut().enumerate() {
            v.name = format!("m{i}");
            name_all(&mut v.members);
        }
    }

    proptest! {
        #[test]
        fn locate_and_leaf_agree_on_every_value(mut vars in tree()) {
            name_all(&mut vars);
            let size = lay_out(&mut vars);
            for (index, v) in vars.iter().enumerate() {
                let mut paths = Vec::new();
                every_path(v, v.name.clone(), &mut paths);
                prop_assert_eq!(paths.len(), leaves(v));
                let mut last_end = v.offset;
                for (n, path) in paths.iter().enumerate() {
                    let f = locate(&vars, path).unwrap();
                    prop_assert_eq!((f.index, f.leaf), (index, n), "{}", path);
                    let back = leaf(&vars, index, n).unwrap();
                    prop_assert_eq!(back.offset, f.offset, "{}", path);
                    prop_assert_eq!(back.node.name(), f.node.name());
                    // Values follow one another in the image, without gaps or overlap.
                    let elements = crate::access::elements(f.node.dims()).max(1);
                    prop_assert_eq!(f.offset, last_end, "{}", path);
                    last_end = f.offset + f.node.size() / elements;
                    prop_assert!(last_end <= size);
                }
                prop_assert!(leaf(&vars, index, paths.len()).is_none());
            }
        }
    }

    #[test]
    fn errors_name_the_place() {
        let mut axis = V {
            dims: vec![2],
            members: vec![
                scalar("pos", 8),
                V {
                    access: Access::ReadOnly,
                    ..scalar("id", 2)
                },
            ],
            ..scalar("axes", 0)
        };
        axis.members[0].dims = vec![];
        let mut vars = vec![scalar("speed", 4), axis];
        lay_out(&mut vars);
        let err = |p: &'static str| locate(&vars, p).unwrap_err().to_string();
        assert_eq!(err("nope"), "no variable `nope`");
        assert_eq!(err("axes[0].nope"), "`axes[0]` has no member `nope`");
        assert_eq!(
            err("axes[2].pos"),
            "`axes[2]`: index 2 is out of range 0..2"
        );
        assert_eq!(
            err("axes"),
            "`axes` is an array: name one element, such as `axes[0]`"
        );
        assert_eq!(
            err("axes[1]"),
            "`axes[1]` is a structure: name one of its members, such as `axes[1].<member>`"
        );
        assert_eq!(
            err("speed.x"),
            "`speed` is not a structure: it has no members"
        );
        assert_eq!(
            err("speed[0]"),
            "`speed[0]`: not an array: remove the index"
        );
        assert!(err("axes[0]..pos").starts_with("not a path"));
        assert!(!locate(&vars, "axes[1].id").unwrap().writable);
        assert!(locate(&vars, "AXES[1].POS").unwrap().writable);
    }
}
