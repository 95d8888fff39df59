//! The standard function blocks (`TON`, ...) as checked declarations, which a list uses
//! without declaring them.

use super::outcome::{Group, ListAt};
use plc_rules::decl::{self, Decl, DeclType, KnownType, Located};

/// The members of a standard function block as a checked group: known to be valid (their IEC
/// names include some a list may not declare, such as `R`), so not checked again.
pub(super) fn standard_group(ty: usize, block: &crate::standard::StandardBlock) -> Group {
    let vars = block
        .members
        .iter()
        .enumerate()
        .map(|(var, m)| {
            let at = ListAt {
                ty: Some(ty),
                var,
                field: None,
            };
            let known = KnownType {
                iec: m.iec_type,
                capacity: None,
                dims: m.dims.iter().map(|&d| d as u64).collect(),
            };
            decl::Var::new(
                Located::new(m.name.to_string(), at.clone()),
                m.name,
                Located::new(DeclType::Known(known), at),
            )
        })
        .collect();
    Group {
        decl: Decl {
            structure: true,
            vars,
            unaligned: false,
        },
        declared: block.members.len(),
        structured: vec![None; block.members.len()],
    }
}
