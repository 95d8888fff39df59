//! A segment's address space: one object for the program, one variable node per basic
//! variable or member under it, and an object per structure (and per element of an array of
//! structures, `axes[0]`) between them. Every node is named by its path (`axes[1].pos`), so
//! [`Layout::by_node`] is the one lookup.

use crate::mapping;
use opcua::nodes::{ObjectBuilder, VariableBuilder};
use opcua::server::address_space::AddressSpace;
use opcua::types::{LocalizedText, NodeId, ObjectId, ObjectTypeId, QualifiedName, VariableTypeId};
use plc_shm::{LayoutDescriptor, VarDescriptor};
use std::collections::HashMap;
use std::time::Duration;

/// One variable node: a basic variable, or a member of a structure (with its elements, if it
/// is an array of basic values).
#[derive(Clone, Debug, PartialEq)]
pub struct VarNode {
    /// Index into the descriptor's variables of the top-level variable it is in.
    pub index: usize,
    /// Its first element's number among that variable's basic values (0 for a top-level
    /// variable); its elements follow.
    pub first_leaf: usize,
    /// The variable or member, its offset made absolute in the image.
    pub var: VarDescriptor,
    /// Whether a tool may write it (the variable and every structure on the way).
    pub writable: bool,
    /// Its path, as `plc get` takes it.
    pub path: String,
}

/// A structure's object: the one for a structured variable, or for one element of an array of
/// structures.
#[derive(Clone, Debug, PartialEq)]
struct ObjectNode {
    id: NodeId,
    name: String,
    description: String,
    parent: NodeId,
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
    /// Variable nodes in declaration order, with the node each belongs to.
    order: Vec<(NodeId, NodeId)>,
    /// Structure objects, parents before children.
    objects: Vec<ObjectNode>,
}

/// How deep a descriptor may nest (it was checked when the segment was attached; this bounds
/// the walk whatever it holds).
const MAX_DEPTH: usize = plc_core::rules::capacity::MAX_STRUCT_DEPTH + 1;

impl Layout {
    /// The layout of `desc` in namespace `ns`.
    pub fn new(desc: LayoutDescriptor, ns: u16) -> Layout {
        let mut layout = Layout {
            desc,
            ns,
            by_node: HashMap::new(),
            order: Vec::new(),
            objects: Vec::new(),
        };
        let program = layout.program_node();
        let vars = layout.desc.variables.clone();
        for (index, v) in vars.iter().enumerate() {
            let writable = v.writable_from_outside();
            layout.add(v, v.name.clone(), index, 0, v.offset, writable, &program, 0);
        }
        layout
    }

    /// Adds `v` (at `path`, its first leaf `leaf`, at `offset`) under `parent`: a variable
    /// node, or objects for a structure and its elements and their members below them.
    #[allow(clippy::too_many_arguments)]
    fn add(
        &mut self,
        v: &VarDescriptor,
        path: String,
        index: usize,
        leaf: usize,
        offset: usize,
        writable: bool,
        parent: &NodeId,
        depth: usize,
    ) {
        let id = mapping::variable_node_id(self.ns, &path);
        if v.members.is_empty() {
            let var = VarDescriptor {
                offset,
                members: Vec::new(),
                ..v.clone()
            };
            let node = VarNode {
                index,
                first_leaf: leaf,
                var,
                writable,
                path,
            };
            self.by_node.insert(id.clone(), node);
            self.order.push((id, parent.clone()));
            return;
        }
        if depth >= MAX_DEPTH {
            return;
        }
        let elements = plc_core::rules::access::elements(&v.dims);
        let element_size = v.element_size();
        let per_element = plc_core::rules::path::element_leaves(v);
        for e in 0..elements {
            let (at, name) = if v.dims.is_empty() {
                (path.clone(), v.name.clone())
            } else {
                let c = plc_core::rules::path::coordinates(e, &v.dims);
                (format!("{path}[{c}]"), format!("{}[{c}]", v.name))
            };
            let object = mapping::variable_node_id(self.ns, &at);
            self.objects.push(ObjectNode {
                id: object.clone(),
                name,
                description: v.description.clone(),
                parent: parent.clone(),
            });
            let base = offset + e * element_size;
            let mut member_leaf = leaf + e * per_element;
            for m in &v.members {
                let member_writable = writable && plc_core::rules::path::member_writable(m.access);
                self.add(
                    m,
                    format!("{at}.{}", m.name),
                    index,
                    member_leaf,
                    base + m.offset,
                    member_writable,
                    &object,
                    depth + 1,
                );
                member_leaf += plc_core::rules::path::leaves(m);
            }
        }
    }

    /// The variable node a NodeId stands for.
    pub fn var(&self, node: &NodeId) -> Option<&VarNode> {
        self.by_node.get(node)
    }

    /// Whether `other` would give the same nodes (same variables, types and access).
    pub fn same_nodes(&self, other: &LayoutDescriptor) -> bool {
        self.desc.variables == other.variables
    }

    /// The program object's NodeId.
    pub fn program_node(&self) -> NodeId {
        NodeId::new(self.ns, mapping::PROGRAM_OBJECT_ID)
    }

    /// Adds the program object under Objects, the structures' objects, and a node per basic
    /// variable or member.
    pub fn insert_into(&self, space: &mut AddressSpace, segment: &str, period: Duration) {
        let program = self.program_node();
        ObjectBuilder::new(&program, QualifiedName::new(self.ns, segment), segment)
            .description(format!(
                "The variables of the plc-vars program of segment `{segment}`"
            ))
            .organized_by(ObjectId::ObjectsFolder)
            .has_type_definition(ObjectTypeId::BaseObjectType)
            .insert(space);
        for o in &self.objects {
            ObjectBuilder::new(
                &o.id,
                QualifiedName::new(self.ns, o.name.as_str()),
                o.name.as_str(),
            )
            .description(LocalizedText::from(o.description.as_str()))
            .component_of(o.parent.clone())
            .has_type_definition(ObjectTypeId::BaseObjectType)
            .insert(space);
        }
        let sampling_ms = period.as_secs_f64() * 1000.0;
        for (id, parent) in &self.order {
            let node = &self.by_node[id];
            let var = &node.var;
            let level = mapping::access_level_for(node.writable);
            let (rank, dims) = mapping::value_rank(var);
            let browse_name = QualifiedName::new(self.ns, var.name.as_str());
            let mut builder = VariableBuilder::new(id, browse_name, var.name.as_str())
                .description(LocalizedText::from(var.description.as_str()))
                .data_type(mapping::data_type(var.iec_type))
                .value_rank(rank)
                .access_level(level)
                .user_access_level(level)
                .minimum_sampling_interval(sampling_ms)
                .has_type_definition(VariableTypeId::BaseDataVariableType)
                .component_of(parent.clone());
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
        for o in self.objects.iter().rev() {
            space.delete(&o.id, true);
        }
        space.delete(&self.program_node(), true);
    }
}
