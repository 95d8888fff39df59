//! Paths into a running program's variables (`axes[1].pos`, `grid[1,2]`, `press.delay.ET`),
//! resolved against the segment's descriptor the way the program's own
//! `GlobalMemory::find` resolves them, so a tool without the Rust types reaches every member.

use super::dynamic::DynSegment;
use crate::error::ShmError;
use crate::format::descriptor::VarDescriptor;

/// One basic value of a segment, found by its path: read it with
/// [`var.value_in`](VarDescriptor::value_in), write it as the
/// [`Write`](plc_core::write::Write) of its `index` and `leaf`
/// ([`DynSegment::check_write`], [`DynSegment::write_checked`]).
#[derive(Clone, Debug, PartialEq)]
pub struct PathLocation {
    /// The path, as given.
    pub path: String,
    /// Index of the top-level variable.
    pub index: usize,
    /// The value's leaf number within it (what the owner's `set` takes as the element).
    pub leaf: usize,
    /// The basic variable or member that holds it, as one scalar at the value's place in the
    /// image (its offset absolute, no dimensions).
    pub var: VarDescriptor,
    /// Whether tools may write it.
    pub writable: bool,
}

/// What a path names: one basic value, or a group of them (a structure, or an array) with the
/// paths one level further down.
#[derive(Clone, Debug, PartialEq)]
pub enum PathTarget {
    /// One basic value.
    Value(Box<PathLocation>),
    /// A structure (its members' paths) or an array (its elements' paths, by coordinates).
    Group(Vec<String>),
}

impl DynSegment {
    /// What `path` names: a basic value, or a structure or array whose members or elements a
    /// tool shows one level at a time (`plc watch`'s tree, `plc get lift`).
    pub fn resolve_path(&self, path: &str) -> Result<PathTarget, ShmError> {
        let text = path.trim();
        match plc_rules::path::locate(&self.descriptor().variables, text) {
            Ok(_) => return self.locate(text).map(|at| PathTarget::Value(Box::new(at))),
            Err(plc_rules::path::LocateError::WholeArray { at }) if at == text => {
                if let Some(node) = self.node_at(text) {
                    let elements = plc_rules::access::elements(&node.dims);
                    let children = (0..elements)
                        .map(|e| format!("{text}[{}]", plc_rules::path::coordinates(e, &node.dims)))
                        .collect();
                    return Ok(PathTarget::Group(children));
                }
            }
            Err(plc_rules::path::LocateError::WholeStructure { at }) if at == text => {
                if let Some(node) = self.node_at(text) {
                    let children = node
                        .members
                        .iter()
                        .map(|m| format!("{text}.{}", m.name))
                        .collect();
                    return Ok(PathTarget::Group(children));
                }
            }
            Err(_) => {}
        }
        // The error, in the words `locate` gives it.
        self.locate(text).map(|at| PathTarget::Value(Box::new(at)))
    }

    /// The variable or member the names of `path` lead to (its indexes aside): what a tool
    /// shows as the type of a group `resolve_path` gives.
    pub fn node_at(&self, path: &str) -> Option<&VarDescriptor> {
        let mut level = &self.descriptor().variables;
        let mut node = None;
        for segment in plc_rules::path::segments(path) {
            let s = segment.ok()?;
            let n = level.iter().find(|v| v.name.eq_ignore_ascii_case(s.name))?;
            level = &n.members;
            node = Some(n);
        }
        node
    }

    /// The basic value `path` names, or why it names none.
    pub fn locate(&self, path: &str) -> Result<PathLocation, ShmError> {
        let found = plc_rules::path::locate(&self.descriptor().variables, path).map_err(|e| {
            ShmError::BadPath {
                name: self.name().to_string(),
                path: path.to_string(),
                reason: e.to_string(),
            }
        })?;
        let node = found.node;
        let mut var = VarDescriptor {
            offset: found.offset,
            size: node.element_size(),
            dims: Vec::new(),
            members: Vec::new(),
            ..node.clone()
        };
        var.name = path.trim().to_string();
        Ok(PathLocation {
            path: var.name.clone(),
            index: found.index,
            leaf: found.leaf,
            var,
            writable: found.writable,
        })
    }
}
