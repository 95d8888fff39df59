//! A segment's address space: one object for the program, one variable node per path under it.
//!
//! Today's descriptor holds basic variables and arrays of basic types, so every path is a
//! top-level name; a structure level adds objects between the program and its members, each
//! node still named by its path (`axes[1].pos`), so [`Layout::by_node`] stays the one lookup.

use crate::mapping;
use opcua::nodes::{ObjectBuilder, VariableBuilder};
use opcua::server::address_space::AddressSpace;
use opcua::types::{LocalizedText, NodeId, ObjectId, ObjectTypeId, QualifiedName, VariableTypeId};
use plc_io::shm::{LayoutDescriptor, VarDescriptor};
use std::collections::HashMap;
use std::time::Duration;

/// One node of a variable: the descriptor's variable index (an element range comes with
/// structured paths).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct VarNode {
    /// Index into the descriptor's variables.
    pub index: usize,
}

/// The address space's view of one layout of a segment.
#[derive(Debug)]
pub struct Layout {
    /// The segment's descriptor this layout was built from.
    pub desc: LayoutDescriptor,
    /// The namespace index of the segment.
    pub ns: u16,
    /// Every variable node by its NodeId.
    pub by_node: HashMap<NodeId, VarNode>,
}

impl Layout {
    /// The layout of `desc` in namespace `ns`.
    pub fn new(desc: LayoutDescriptor, ns: u16) -> Layout {
        let by_node = desc
            .variables
            .iter()
            .enumerate()
            .map(|(index, v)| (mapping::variable_node_id(ns, &v.name), VarNode { index }))
            .collect();
        Layout { desc, ns, by_node }
    }

    /// The variable a node stands for.
    pub fn var(&self, node: &NodeId) -> Option<(VarNode, &VarDescriptor)> {
        let n = *self.by_node.get(node)?;
        Some((n, self.desc.variables.get(n.index)?))
    }

    /// Whether `other` would give the same nodes (same variables, types and access).
    pub fn same_nodes(&self, other: &LayoutDescriptor) -> bool {
        self.desc.variables == other.variables
    }

    /// The program object's NodeId.
    pub fn program_node(&self) -> NodeId {
        NodeId::new(self.ns, mapping::PROGRAM_OBJECT_ID)
    }

    /// Adds the program object under Objects and a node per variable under it.
    pub fn insert_into(&self, space: &mut AddressSpace, segment: &str, period: Duration) {
        let program = self.program_node();
        ObjectBuilder::new(&program, QualifiedName::new(self.ns, segment), segment)
            .description(format!(
                "The variables of the plc-vars program of segment `{segment}`"
            ))
            .organized_by(ObjectId::ObjectsFolder)
            .has_type_definition(ObjectTypeId::BaseObjectType)
            .insert(space);
        let sampling_ms = period.as_secs_f64() * 1000.0;
        for var in &self.desc.variables {
            let id = mapping::variable_node_id(self.ns, &var.name);
            let level = mapping::access_level(var);
            let (rank, dims) = mapping::value_rank(var);
            let browse_name = QualifiedName::new(self.ns, var.name.as_str());
            let mut builder = VariableBuilder::new(&id, browse_name, var.name.as_str())
                .description(LocalizedText::from(var.description.as_str()))
                .data_type(mapping::data_type(var.iec_type))
                .value_rank(rank)
                .access_level(level)
                .user_access_level(level)
                .minimum_sampling_interval(sampling_ms)
                .has_type_definition(VariableTypeId::BaseDataVariableType)
                .component_of(program.clone());
            if let Some(dims) = dims {
                builder = builder.array_dimensions(&dims);
            }
            builder.insert(space);
        }
    }

    /// Removes every node [`insert_into`](Self::insert_into) added.
    pub fn remove_from(&self, space: &mut AddressSpace) {
        for id in self.by_node.keys() {
            space.delete(id, true);
        }
        space.delete(&self.program_node(), true);
    }
}
