//! Forces, as TwinCAT and CODESYS force: values the owner holds at both of the cycle's
//! boundaries until they are released or the program stops. The cycle thread keeps the table
//! (it applies forces and refuses writes to forced values, so nothing races it) and publishes
//! it in the segment for tools; the lines it logs go to the server's thread, which writes
//! them, so a release of every force costs the cycle no terminal output.

use super::refused::Refused;
use crate::calendar::utc_text;
use crate::format::force_table::{self, ForceInfo};
use crate::format::layout::Offsets;
use crate::limits::MAX_FORCES;
use crate::naming::{path_of, shown_in_log};
use crate::protocol::Release;
use crate::sys::base::Base;
use plc_core::place::{self, HeldBytes, PlacedBytes};
use plc_core::write::Checked;
use plc_core::{GlobalMemory, Value, VarInfo};
use std::sync::mpsc::SyncSender;

/// One force held.
#[derive(Clone, Debug)]
struct Force<T> {
    write: Checked,
    uid: u32,
    since_utc_ns: u64,
    /// The value before the force, for a release with restore.
    before: Option<Value>,
    /// The bytes that hold the value where it lies in `T`, captured when it was forced;
    /// `None` if `T` does not say where it lies (then `set` holds it).
    placed: Option<Vec<PlacedBytes<T>>>,
}

/// The forces the cycle thread holds.
pub(crate) struct ForceTable<T> {
    held: Vec<Force<T>>,
    /// What applying them writes, rebuilt when they change: every force's placed bytes, in
    /// the order held (a later force wins where two write the same bytes) ...
    stores: HeldBytes<T>,
    /// ... and the forces `T` does not place, set through `set` after the stores (a type
    /// places all its values or, written by hand, none: the two never hold the same bytes).
    unplaced: Vec<Checked>,
    vars: &'static [VarInfo],
    /// Lines for the log, written by the server's accepting thread.
    log: SyncSender<String>,
}

impl<T: GlobalMemory> ForceTable<T> {
    pub fn new(vars: &'static [VarInfo], log: SyncSender<String>) -> Self {
        ForceTable {
            held: Vec::new(),
            stores: HeldBytes::default(),
            unplaced: Vec::new(),
            vars,
            log,
        }
    }

    /// How many forces are held.
    pub fn len(&self) -> usize {
        self.held.len()
    }

    /// Sets every forced value in `gm`: its bytes where it lies (see [`plc_core::place`]),
    /// as `set` wrote them when it was forced. Nearly every cycle holds none: a few length
    /// checks.
    #[inline]
    pub fn apply(&self, gm: &mut T) {
        self.stores.write(gm);
        for checked in &self.unplaced {
            let w = checked.write();
            // The value was set once when it was forced: `set` accepts it.
            let _ = gm.set(w.index, w.leaf, w.value);
        }
    }

    /// The stores and the unplaced forces from the forces held, in their order.
    fn rebuild(&mut self) {
        let placed = self.held.iter().filter_map(|f| f.placed.as_deref());
        self.stores = HeldBytes::new(placed.flatten().copied());
        self.unplaced = (self.held.iter())
            .filter(|f| f.placed.is_none())
            .map(|f| f.write)
            .collect();
    }

    /// Why a write to `index`/`leaf` is refused, if that value is forced.
    pub fn refusal(&self, index: usize, leaf: usize) -> Option<String> {
        let f = self.find(index, leaf).map(|k| &self.held[k])?;
        Some(format!(
            "`{}` is forced (by uid {} since {}): release it first (`plc unforce`)",
            self.path(index, leaf),
            f.uid,
            utc_text(f.since_utc_ns)
        ))
    }

    fn find(&self, index: usize, leaf: usize) -> Option<usize> {
        self.held.iter().position(|f| {
            let w = f.write.write();
            w.index == index && w.leaf == leaf
        })
    }

    /// The value's path, as tools name it (an array's element included).
    pub fn path(&self, index: usize, leaf: usize) -> String {
        path_of(self.vars, index, leaf)
    }

    /// Forces `writes` (checked by [`plc_core::write::check_force`]) for `uid`, all or none: each is set
    /// in `gm` now, and held from then on; a value forced already takes the new value and
    /// keeps the one from before its first force.
    pub fn force(
        &mut self,
        gm: &mut T,
        writes: &[Checked],
        uid: u32,
        now_utc_ns: u64,
    ) -> Result<(), Refused> {
        let new = writes
            .iter()
            .filter(|w| self.find(w.write().index, w.write().leaf).is_none())
            .count();
        if self.held.len() + new > MAX_FORCES {
            return Err(Refused::rejected(
                0,
                format!(
                    "{} forces are held and this request adds {new}: at most {MAX_FORCES} are \
                     held at once; release some first (`plc unforce SEGMENT --all`)",
                    self.held.len()
                ),
            ));
        }
        let mut undo: Vec<(usize, usize, Option<Value>)> = Vec::with_capacity(writes.len());
        for (k, checked) in writes.iter().enumerate() {
            let w = checked.write();
            let before = gm.try_get(w.index, w.leaf);
            if let Err(e) = gm.set(w.index, w.leaf, w.value) {
                for (index, leaf, old) in undo.into_iter().rev() {
                    if let Some(old) = old {
                        let _ = gm.set(index, leaf, old);
                    }
                }
                return Err(Refused::rejected(
                    k,
                    format!("`{}`: {e}", self.path(w.index, w.leaf)),
                ));
            }
            undo.push((w.index, w.leaf, before));
        }
        for (checked, (index, leaf, before)) in writes.iter().zip(undo) {
            let line = format!(
                "uid {uid} forces `{}` = {}",
                self.path(index, leaf),
                shown_in_log(&checked.write().value)
            );
            let force = Force {
                write: *checked,
                uid,
                since_utc_ns: now_utc_ns,
                before,
                placed: placed(gm, index, leaf),
            };
            match self.find(index, leaf) {
                Some(k) => {
                    let first = self.held[k].before;
                    self.held[k] = Force {
                        before: first,
                        ..force
                    };
                }
                None => self.held.push(force),
            }
            self.say(line);
        }
        self.rebuild();
        Ok(())
    }

    /// Ends the forces `release` names (each must be held: all or none), or all of them;
    /// with `restore`, each value is set back to what it was before its force.
    pub fn release(&mut self, gm: &mut T, release: &Release, uid: u32) -> Result<(), Refused> {
        let ended: Vec<usize> = if release.all {
            (0..self.held.len()).collect()
        } else {
            let mut ended = Vec::with_capacity(release.values.len());
            for (k, &(index, leaf)) in release.values.iter().enumerate() {
                match self.find(index, leaf) {
                    Some(at) if !ended.contains(&at) => ended.push(at),
                    Some(_) => {}
                    None => {
                        return Err(Refused::rejected(
                            k,
                            format!(
                                "`{}` is not forced (`plc forces` lists what is)",
                                self.path(index, leaf)
                            ),
                        ));
                    }
                }
            }
            ended
        };
        for &at in &ended {
            let f = &self.held[at];
            let w = f.write.write();
            let restored = match (release.restore, f.before) {
                (true, Some(before)) => {
                    let _ = gm.set(w.index, w.leaf, before);
                    format!(", {} restored", shown_in_log(&before))
                }
                _ => String::new(),
            };
            let line = format!(
                "uid {uid} releases `{}` (forced by uid {}{restored})",
                self.path(w.index, w.leaf),
                f.uid
            );
            self.say(line);
        }
        let mut at = 0;
        self.held.retain(|_| {
            at += 1;
            !ended.contains(&(at - 1))
        });
        self.rebuild();
        Ok(())
    }

    /// The forces still held when the program stops, one line each (for its log).
    pub fn held_lines(&self) -> Vec<String> {
        self.held
            .iter()
            .map(|f| {
                let w = f.write.write();
                format!(
                    "`{}` = {} (by uid {} since {})",
                    self.path(w.index, w.leaf),
                    shown_in_log(&w.value),
                    f.uid,
                    utc_text(f.since_utc_ns)
                )
            })
            .collect()
    }

    /// Stores the table in the segment for tools.
    pub fn publish(&self, base: &Base, off: &Offsets) {
        force_table::store(
            base,
            off,
            self.held.iter().map(|f| {
                let w = f.write.write();
                ForceInfo {
                    index: w.index,
                    leaf: w.leaf,
                    uid: f.uid,
                    since_utc_ns: f.since_utc_ns,
                }
            }),
        );
    }

    fn say(&self, line: String) {
        // Full only if thousands of lines wait: the log then misses some, the table not.
        let _ = self.log.try_send(line);
    }
}

/// The bytes that hold value `leaf` of variable `index` where it lies in `gm`, which holds
/// its forced value; `None` if `T` does not say where it lies.
fn placed<T: GlobalMemory>(gm: &T, index: usize, leaf: usize) -> Option<Vec<PlacedBytes<T>>> {
    let mut stores = Vec::new();
    place::capture(gm, index, leaf, |s| stores.push(s)).then_some(stores)
}
