//! What an online change does to a program's values: the running program's last image read
//! into the new program's image, value by value, matched by path (as `plc get` names them), so
//! every value that still exists is kept. Planned from the two descriptors alone, off the cycle
//! thread; applied to an image between two cycles.
//!
//! For each basic value of the new program (each element of an array its own):
//! - **kept**: the running program has it, of the same type (a STRING of at least its length);
//! - **widened**: of a type IEC 61131-3 widens to the new one (`plc_core::convert::can_widen`:
//!   an integer to a wider integer or a real, REAL to LREAL);
//! - **narrowed**: going back to a previous program ([`Direction::Back`]), a value widened by
//!   the change narrows back if it fits, which only the value at the change can say:
//!   [`ChangePlan::apply`] refuses one that does not;
//! - **added**: a value the running program lacks starts from the new image's own (the new
//!   program's initial value, or going back, its value at the change);
//! - **reset**: a value named by a reset path (itself, or a structure or array holding it)
//!   starts from the new image's own too, whatever it was;
//! - anything else (a type the value cannot become) refuses the plan, naming the value.
//!
//! Values of the running program the new one lacks are **removed**.
//!
//! ```
//! use plc_core::GlobalMemory;
//! use plc_shm::LayoutDescriptor;
//! use plc_shm::change::{ChangePlan, Direction};
//!
//! #[derive(GlobalMemory, Clone, Debug)]
//! struct Before { count: i16, speed: f32 }
//! #[derive(GlobalMemory, Clone, Debug)]
//! struct After { count: i32, speed: f32, #[plc(initial = 7)] top_speed: u8 }
//!
//! let plan = ChangePlan::new(
//!     &LayoutDescriptor::of::<Before>(),
//!     &LayoutDescriptor::of::<After>(),
//!     &[],
//!     Direction::Forward,
//! )
//! .unwrap();
//! assert_eq!(plan.widened, ["count (INT to DINT)"]);
//! assert_eq!((plan.kept.len(), plan.added.as_slice()), (1, &["top_speed".to_string()][..]));
//! ```

use super::codec::{decode, encode};
use super::descriptor::{LayoutDescriptor, VarDescriptor};
use crate::naming::shown_in_log;
use plc_core::IecType;
use plc_core::convert::can_widen;
use plc_rules::access::elements;
use plc_rules::path::{Visit, coordinates, walk};
use std::collections::HashMap;

/// Which way a change goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Direction {
    /// To a new program: values only widen.
    Forward,
    /// Back to the program before the change: a widened value narrows back where it fits.
    Back,
}

/// One basic value of an image: where its bytes are and what they hold.
#[derive(Clone, Debug)]
struct Leaf {
    offset: usize,
    size: usize,
    ty: IecType,
    /// A STRING's length in bytes; 0 for the others.
    capacity: usize,
}

impl std::fmt::Display for Leaf {
    /// Its type as a declaration says it: `INT`, `STRING(20)`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.ty {
            IecType::String => write!(f, "STRING({})", self.capacity),
            ty => write!(f, "{ty}"),
        }
    }
}

/// How a value reaches the new image.
#[derive(Clone, Debug)]
enum Carry {
    /// The same bytes.
    Bytes { from: usize, to: usize, len: usize },
    /// Read as the old type, written as the new one (checked to fit when narrowing).
    Convert { path: String, from: Leaf, to: Leaf },
}

/// A value the plan or its application refuses, and why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Refused {
    /// The value's path.
    pub path: String,
    /// Why, in words a person reads after the path.
    pub why: String,
}

impl std::fmt::Display for Refused {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "`{}`: {}", self.path, self.why)
    }
}

/// An online change's conversion: what happens to each value, and how.
#[derive(Clone, Debug, Default)]
pub struct ChangePlan {
    /// Paths kept as they are.
    pub kept: Vec<String>,
    /// `path (OLD to NEW)` of each value widened.
    pub widened: Vec<String>,
    /// `path (OLD to NEW)` of each value narrowed back (going back only).
    pub narrowed: Vec<String>,
    /// Paths the running program lacks: they start from the new image.
    pub added: Vec<String>,
    /// Paths a reset named: they start from the new image.
    pub reset: Vec<String>,
    /// Paths of the running program the new one lacks.
    pub removed: Vec<String>,
    carries: Vec<Carry>,
    old_size: usize,
    new_size: usize,
}

/// Every basic value of `vars` by path (an array's elements each their own), in declaration
/// order, with where it lies.
fn leaves(vars: &[VarDescriptor]) -> Vec<(String, Leaf)> {
    let mut out = Vec::new();
    walk(vars, |visit| {
        let Visit::Basic(b) = visit else { return };
        let node = b.node;
        let size = node.element_size();
        let leaf = |k: usize| Leaf {
            offset: b.offset + k * size,
            size,
            ty: node.iec_type,
            capacity: if node.iec_type == IecType::String {
                node.string_capacity()
            } else {
                0
            },
        };
        if node.dims.is_empty() {
            out.push((b.path, leaf(0)));
        } else {
            for k in 0..elements(&node.dims) {
                out.push((
                    format!("{}[{}]", b.path, coordinates(k, &node.dims)),
                    leaf(k),
                ));
            }
        }
    });
    out
}

/// Whether `reset` names `path`: itself, or a structure or array that holds it.
fn names(reset: &str, path: &str) -> bool {
    path.strip_prefix(reset)
        .is_some_and(|rest| rest.is_empty() || rest.starts_with(['.', '[']))
}

impl ChangePlan {
    /// Plans the change from the running program's descriptor `old` to the new one's `new`,
    /// resetting the values `resets` name. Refused (every value that cannot be carried, and
    /// every reset path that names no value of the new program) if a value can be neither
    /// kept nor converted nor reset.
    pub fn new(
        old: &LayoutDescriptor,
        new: &LayoutDescriptor,
        resets: &[String],
        direction: Direction,
    ) -> Result<ChangePlan, Vec<Refused>> {
        let before: HashMap<String, Leaf> = leaves(&old.variables).into_iter().collect();
        let after = leaves(&new.variables);
        let mut plan = ChangePlan {
            old_size: old.image_size,
            new_size: new.image_size,
            ..ChangePlan::default()
        };
        let mut refused: Vec<Refused> = (resets.iter())
            .filter(|r| !after.iter().any(|(path, _)| names(r, path)))
            .map(|r| Refused {
                path: r.clone(),
                why: "a reset names no value of the new program".into(),
            })
            .collect();
        for (path, to) in &after {
            let Some(from) = before.get(path) else {
                plan.added.push(path.clone());
                continue;
            };
            if resets.iter().any(|r| names(r, path)) {
                plan.reset.push(path.clone());
                continue;
            }
            let types = format!("{path} ({from} to {to})");
            let same = from.ty == to.ty;
            if same && from.size == to.size {
                plan.kept.push(path.clone());
                plan.carries.push(Carry::Bytes {
                    from: from.offset,
                    to: to.offset,
                    len: to.size,
                });
                continue;
            }
            let carry = Carry::Convert {
                path: path.clone(),
                from: from.clone(),
                to: to.clone(),
            };
            // A longer STRING takes the text whole (its new bytes zeroed by the conversion).
            if (!same && can_widen(from.ty, to.ty)) || (same && from.size < to.size) {
                plan.widened.push(types);
                plan.carries.push(carry);
            } else if direction == Direction::Back && (same || can_widen(to.ty, from.ty)) {
                // A shorter STRING, or a type the change widened: back if the value fits.
                plan.narrowed.push(types);
                plan.carries.push(carry);
            } else {
                refused.push(Refused {
                    path: path.clone(),
                    why: format!(
                        "is {from} in the running program and {to} in the new one, which IEC \
                         61131-3 does not widen it to: reset it (`--reset {path}`) to start \
                         from the new program's value"
                    ),
                });
            }
        }
        let kept: std::collections::HashSet<&String> = after.iter().map(|(p, _)| p).collect();
        let mut removed: Vec<(usize, String)> = (before.iter())
            .filter(|(path, _)| !kept.contains(path))
            .map(|(path, leaf)| (leaf.offset, path.clone()))
            .collect();
        removed.sort();
        plan.removed = removed.into_iter().map(|(_, p)| p).collect();
        if refused.is_empty() {
            Ok(plan)
        } else {
            Err(refused)
        }
    }

    /// Whether the change keeps every value as it is: nothing widened, narrowed, added, reset
    /// or removed.
    pub fn changes_nothing(&self) -> bool {
        self.widened.is_empty()
            && self.narrowed.is_empty()
            && self.added.is_empty()
            && self.reset.is_empty()
            && self.removed.is_empty()
    }

    /// The new image: `base` (the new program's initial image, or going back, the previous
    /// program's image at the change) with every value carried from `old` (the running
    /// program's last image). All or nothing: a value that does not fit (narrowing back) is
    /// refused, naming it, and no image is made. The images must be the sizes the plan's
    /// descriptors give.
    pub fn apply(&self, old: &[u8], base: &[u8]) -> Result<Vec<u8>, Vec<Refused>> {
        let wrong_size = |what: &str, got: usize, want: usize| Refused {
            path: what.into(),
            why: format!("is {got} bytes where its descriptor says {want}"),
        };
        if old.len() != self.old_size || base.len() != self.new_size {
            return Err(vec![
                wrong_size("the running image", old.len(), self.old_size),
                wrong_size("the new image", base.len(), self.new_size),
            ]);
        }
        let mut image = base.to_vec();
        let mut refused = Vec::new();
        for carry in &self.carries {
            match carry {
                Carry::Bytes { from, to, len } => {
                    image[*to..*to + *len].copy_from_slice(&old[*from..*from + *len]);
                }
                Carry::Convert { path, from, to } => {
                    let value = decode(from.ty, &old[from.offset..from.offset + from.size]);
                    let bytes = &mut image[to.offset..to.offset + to.size];
                    match value.fit(to.ty, to.capacity) {
                        Ok(v) if encode(to.ty, &v, bytes) => {}
                        Ok(_) | Err(_) => refused.push(Refused {
                            path: path.clone(),
                            why: format!(
                                "holds {}, which does not fit its {to} in the program going back: \
                                 reset it (`--reset {path}`) to take that program's value",
                                shown_in_log(&value),
                            ),
                        }),
                    }
                }
            }
        }
        if refused.is_empty() {
            Ok(image)
        } else {
            Err(refused)
        }
    }
}

#[cfg(test)]
#[path = "change_tests.rs"]
mod tests;
