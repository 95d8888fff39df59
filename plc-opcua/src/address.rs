//! A segment's address space: one object for the program, one variable node per basic
//! variable or member under it, and an object per structure (and per element of an array of
//! structures, `axes[0]`) between them. Every node is named by its path (`axes[1].pos`), so
//! [`Layout::by_node`] is the one lookup.

use crate::mapping;
use opcua::nodes::{ObjectBuilder, VariableBuilder};
use opcua::server::address_space::{AddressSpace, EventNotifier};
use opcua::types::{LocalizedText, NodeId, ObjectId, ObjectTypeId, QualifiedName, VariableTypeId};
use plc_core::rules::path::{Visit, walk};
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

impl Layout {
    /// The layout of `desc` in namespace `ns`: its nodes from the one walk over the
    /// declaration (bounded in depth whatever the descriptor holds).
    pub fn new(desc: LayoutDescriptor, ns: u16) -> Layout {
        let program = NodeId::new(ns, mapping::PROGRAM_OBJECT_ID);
        let parent_of = |parent: &Option<String>| {
            parent
                .as_deref()
                .map_or_else(|| program.clone(), |p| mapping::variable_node_id(ns, p))
        };
        let (mut by_node, mut order, mut objects) = (HashMap::new(), Vec::new(), Vec::new());
        walk(&desc.variables, |visit| match visit {
            Visit::Structure(s) => objects.push(ObjectNode {
                id: mapping::variable_node_id(ns, &s.path),
                name: s.name,
                description: s.node.description.clone(),
                parent: parent_of(&s.parent),
            }),
            Visit::Basic(b) => {
                let id = mapping::variable_node_id(ns, &b.path);
                order.push((id.clone(), parent_of(&b.parent)));
                let var = VarDescriptor {
                    offset: b.offset,
                    members: Vec::new(),
                    ..b.node.clone()
                };
                let node = VarNode {
                    index: b.index,
                    first_leaf: b.first_leaf,
                    var,
                    writable: b.writable,
                    path: b.path,
                };
                by_node.insert(id, node);
            }
        });
        Layout {
            desc,
            ns,
            by_node,
            order,
            objects,
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
            // Its alarms' events: subscribe here for one program's, on Server for all.
            .event_notifier(EventNotifier::SUBSCRIBE_TO_EVENTS)
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
