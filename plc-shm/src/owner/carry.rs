//! Forces across an online change: the owner of the old layout says which it holds, by path,
//! and the owner of the new one holds again each whose path the new program still has, with
//! the same value, for the same user. The others are released, and named.

use super::ShmOwner;
use crate::sys::clock::utc_ns;
use plc_core::Value;
use plc_core::memory::Memory;
use plc_core::write::{Write, check_force};

/// A force as it crosses a change: the value's path, the forced value and who forced it.
#[derive(Clone, Debug, PartialEq)]
pub struct HeldForce {
    /// The value's path (`speed`, `axes[1].pos`).
    pub path: String,
    /// The value it is held at.
    pub value: Value,
    /// Who forced it.
    pub uid: u32,
}

impl<T: Memory> ShmOwner<T> {
    /// The forces held, by path.
    pub fn held_forces(&self) -> Vec<HeldForce> {
        self.inbox.forces.borrow().held()
    }

    /// Holds `forces` again in `gm` where its program has each path and the value fits; the
    /// paths of the others, which are released.
    pub fn carry_forces(&self, gm: &mut T, forces: Vec<HeldForce>) -> Vec<String> {
        let vars = gm.schema().variables;
        let mut released = Vec::new();
        let mut table = self.inbox.forces.borrow_mut();
        for f in forces {
            let held = plc_rules::path::locate(vars, &f.path)
                .ok()
                .and_then(|at| {
                    let write = Write {
                        index: at.index,
                        leaf: at.leaf,
                        value: f.value,
                    };
                    check_force(vars, write).ok()
                })
                .is_some_and(|checked| table.force(gm, vec![checked], f.uid, utc_ns()).is_ok());
            if !held {
                released.push(f.path);
            }
        }
        table.publish(&self.base, &self.off);
        released
    }
}
