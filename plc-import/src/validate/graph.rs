//! The graph of the types: their dependency order, nesting depths and image sizes, the cycles
//! among them, and the nesting limit.

use super::outcome::{CheckedType, Group, ListAt, Problem};
use super::wording::ListWording;
use plc_rules::capacity::MAX_STRUCT_DEPTH;
use plc_rules::decl::Wording;
use std::borrow::Cow;

/// What the walk over the types works out.
pub(super) struct TypeGraph {
    /// Dependency order: each type after the types its members use.
    pub(super) order: Vec<usize>,
    /// Levels of structures in each type (1 for a type of basic members only).
    pub(super) depth: Vec<usize>,
    /// Bytes of each type's image (saturating).
    pub(super) size: Vec<u64>,
}

/// Bytes of one declaration's image (saturating), given the sizes of the types so far.
pub(super) fn group_size(group: &Group, size: &[u64]) -> u64 {
    let vars = group.decl.vars.iter().zip(&group.structured);
    vars.take(group.declared)
        .map(|(v, s)| match (s, v.ty.value.known()) {
            (Some(s), _) => elements(&s.dims).saturating_mul(size[s.ty]),
            (None, Some(k)) => {
                let one = k.capacity.unwrap_or(k.iec.image_size() as u64);
                elements(&k.dims).saturating_mul(one)
            }
            (None, None) => 0,
        })
        .fold(0u64, u64::saturating_add)
}

fn elements(dims: &[u64]) -> u64 {
    dims.iter().fold(1u64, |a, &d| a.saturating_mul(d))
}

/// Walks the types depth first without recursion (a hostile list may chain thousands), in
/// file order: reports every cycle at the member that closes it, naming the cycle, and works
/// out the dependency order, depths and sizes.
pub(super) fn walk_types(types: &[CheckedType], errors: &mut Vec<Problem>) -> TypeGraph {
    const NEW: u8 = 0;
    const OPEN: u8 = 1;
    const DONE: u8 = 2;
    let n = types.len();
    let mut state = vec![NEW; n];
    let mut graph = TypeGraph {
        order: Vec::with_capacity(n),
        depth: vec![0; n],
        size: vec![0; n],
    };
    let uses = |t: usize, i: usize| {
        let g = &types[t].group;
        (i < g.declared).then(|| g.structured[i].as_ref().map(|s| s.ty))
    };
    for root in 0..n {
        if state[root] != NEW {
            continue;
        }
        // (type, the next member to follow)
        let mut stack = vec![(root, 0usize)];
        state[root] = OPEN;
        while let Some(top) = stack.last_mut() {
            let (t, i) = *top;
            match uses(t, i) {
                Some(used) => {
                    top.1 += 1;
                    match used.map(|u| (u, state[u])) {
                        Some((u, NEW)) => {
                            state[u] = OPEN;
                            stack.push((u, 0));
                        }
                        Some((u, OPEN)) => errors.push(cycle(types, &stack, u)),
                        _ => {}
                    }
                }
                None => {
                    stack.pop();
                    state[t] = DONE;
                    let g = &types[t].group;
                    let deepest = g.structured[..g.declared]
                        .iter()
                        .flatten()
                        .map(|s| graph.depth[s.ty])
                        .max()
                        .unwrap_or(0);
                    graph.depth[t] = deepest.saturating_add(1);
                    graph.size[t] = group_size(g, &graph.size);
                    graph.order.push(t);
                }
            }
        }
    }
    graph
}

/// The error of a cycle: `stack` is the walk's path, whose last member leads back to `to`.
fn cycle(types: &[CheckedType], stack: &[(usize, usize)], to: usize) -> Problem {
    let from = stack.iter().rposition(|&(t, _)| t == to).unwrap_or(0);
    let path: Vec<String> = stack[from..]
        .iter()
        .map(|&(t, next)| {
            let member = &types[t].group.decl.vars[next - 1].name.value;
            format!("{}.{member}", types[t].name)
        })
        .chain([types[to].name.clone()])
        .collect();
    let &(t, next) = stack.last().unwrap_or(&(to, 1));
    Problem {
        at: ListAt {
            ty: Some(t),
            var: next - 1,
            field: Some(Cow::Borrowed("type")),
        },
        message: format!(
            "the type {:?} contains itself: {}; a structure cannot hold itself, directly or \
             through its members (hold the other part in a variable of its own)",
            types[to].name,
            path.join(" -> ")
        ),
        kind: None,
    }
}

/// The nesting limit, at every member or variable whose type nests too deep, in the derive's
/// words: a program's variable may have a type of 8 levels, a member one of 7.
pub(super) fn nesting(
    group: &Group,
    depth: &[usize],
    wording: &ListWording,
    errors: &mut Vec<Problem>,
) {
    let levels = match group.decl.structure {
        true => MAX_STRUCT_DEPTH - 1,
        false => MAX_STRUCT_DEPTH,
    };
    let vars = group.decl.vars.iter().zip(&group.structured);
    for (v, s) in vars.take(group.declared) {
        if let Some(s) = s
            && depth[s.ty] > levels
        {
            errors.push(Problem {
                at: v.ty.at.clone(),
                message: format!(
                    "the type of {} nests structures too deep: at most {MAX_STRUCT_DEPTH} \
                     levels of structures in one another",
                    wording.name(&v.name.value)
                ),
                kind: None,
            });
        }
    }
}
