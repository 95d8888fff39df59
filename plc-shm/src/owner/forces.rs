//! Forces, as TwinCAT and CODESYS force: values the owner holds at both of the cycle's
//! boundaries until they are released or the program stops. The cycle thread keeps the table
//! (it applies forces and refuses writes to forced values, so nothing races it) and publishes
//! it in the segment for tools. Its forces and releases go to the server's thread as plain
//! events ([`ForceLog`]), formatted there, so a flood of forces costs the cycle no text; the
//! held forces are indexed by value, so a request costs the cycle about what a write of as
//! many values does.

use super::by_value::{ByValue, ValueSet};
use super::force_log::{Ended, ForceEvent, ForceLog};
use super::placed::Placed;
use super::refused::Refused;
use crate::calendar::utc_text;
use crate::format::force_table::{self, ForceInfo};
use crate::format::layout::Offsets;
use crate::limits::MAX_FORCES;
use crate::naming::{path_of, shown_in_log};
use crate::protocol::Release;
use crate::sys::base::Base;
use plc_core::memory::Memory;
use plc_core::place::HeldBytes;
use plc_core::write::Checked;
use plc_core::{Value, VarInfo};

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
    placed: Placed<T>,
}

/// The forces the cycle thread holds.
pub(crate) struct ForceTable<T> {
    held: Vec<Force<T>>,
    /// Where each held value (variable, leaf) is in `held`: a lookup per value, not a search.
    at: ByValue<usize>,
    /// What applying them writes, rebuilt when they change: every force's placed bytes, in
    /// the order held (a later force wins where two write the same bytes) ...
    stores: HeldBytes<T>,
    /// ... and the forces `T` does not place, set through `set` after the stores (a type
    /// places all its values or, written by hand, none: the two never hold the same bytes).
    unplaced: Vec<Checked>,
    vars: &'static [VarInfo],
    /// Events for the log, formatted by the server's accepting thread.
    log: ForceLog,
    /// The places of a request's values while it is applied, kept between requests so a
    /// flood of them allocates nothing for it.
    scratch: Vec<(Option<usize>, Placed<T>)>,
}

impl<T: Memory> ForceTable<T> {
    pub fn new(vars: &'static [VarInfo], log: ForceLog) -> Self {
        ForceTable {
            held: Vec::new(),
            at: ByValue::with_capacity_and_hasher(MAX_FORCES, Default::default()),
            stores: HeldBytes::default(),
            unplaced: Vec::new(),
            vars,
            log,
            scratch: Vec::new(),
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
        let placed = self.held.iter().flat_map(|f| f.placed.stores());
        self.stores = HeldBytes::new(placed.copied());
        self.unplaced = (self.held.iter())
            .filter(|f| !f.placed.is_placed())
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
        self.at.get(&(index, leaf)).copied()
    }

    /// The value's path, as tools name it (an array's element included).
    pub fn path(&self, index: usize, leaf: usize) -> String {
        path_of(self.vars, index, leaf)
    }

    /// Forces `writes` (checked by [`plc_core::write::check_force`]) for `uid`, all or none:
    /// each is set in `gm` now, and held from then on; a value forced already takes the new
    /// value and keeps the one from before its first force. The request's values go to the
    /// log if forced, to be freed off the cycle thread if not.
    pub fn force(
        &mut self,
        gm: &mut T,
        writes: Vec<Checked>,
        uid: u32,
        now_utc_ns: u64,
    ) -> Result<(), Refused> {
        let done = self.force_all(gm, &writes, uid, now_utc_ns);
        match done {
            Ok(()) => self.log.send(ForceEvent::Forced {
                uid,
                writes,
                at_utc_ns: now_utc_ns,
            }),
            Err(_) => self.log.leave(writes),
        }
        done
    }

    /// [`force`](Self::force) but for the log.
    fn force_all(
        &mut self,
        gm: &mut T,
        writes: &[Checked],
        uid: u32,
        now_utc_ns: u64,
    ) -> Result<(), Refused> {
        // The values not held yet, each once (a value named twice in a request is one
        // force); a flood of re-forces adds none here.
        let mut new = ValueSet::default();
        for w in writes.iter().map(Checked::write) {
            if self.find(w.index, w.leaf).is_none() {
                new.insert((w.index, w.leaf));
            }
        }
        let new = new.len();
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
        // Each value's place in the table if held (a value held already keeps the value
        // from before its first force: not read again; the others' go to `befores`, in
        // order) and its bytes as `set` wrote them (captured at once: a later value of the
        // request that shares its bytes does not change what this force holds).
        let mut undo = std::mem::take(&mut self.scratch);
        undo.clear();
        let mut befores: Vec<Option<Value>> = Vec::with_capacity(new);
        for (k, checked) in writes.iter().enumerate() {
            let w = checked.write();
            let held = self.find(w.index, w.leaf);
            if held.is_none() {
                befores.push(gm.try_get(w.index, w.leaf));
            }
            if let Err(e) = gm.set(w.index, w.leaf, w.value) {
                // Back as it was, last first: a value held at its forced value, any other at
                // its own.
                for ((held, _), done) in undo.iter().zip(&writes[..undo.len()]).rev() {
                    let d = done.write();
                    let old = match held {
                        Some(h) => Some(self.held[*h].write.write().value),
                        None => befores.pop().flatten(),
                    };
                    if let Some(old) = old {
                        let _ = gm.set(d.index, d.leaf, old);
                    }
                }
                return Err(Refused::rejected(
                    k,
                    format!("`{}`: {e}", self.path(w.index, w.leaf)),
                ));
            }
            undo.push((held, Placed::capture(gm, w.index, w.leaf)));
        }
        let mut befores = befores.into_iter();
        // Whether what the cycle writes changed: a flood of re-forces to the values held
        // does not rebuild it.
        let mut changed = false;
        for (checked, (held, placed)) in writes.iter().zip(undo.drain(..)) {
            let w = checked.write();
            let before = if held.is_none() {
                befores.next().flatten()
            } else {
                None
            };
            // `held` was looked up before this request added any: a value new to the table
            // and named twice is found the second time.
            match held.or_else(|| self.find(w.index, w.leaf)) {
                Some(k) => {
                    // A re-force: the new value, who and when; the value from before the
                    // first force stays.
                    let f = &mut self.held[k];
                    (f.uid, f.since_utc_ns) = (uid, now_utc_ns);
                    // The same bytes at the same place are the same value: nothing to copy
                    // (a flood of re-forces copies no values). An unplaced value is set by
                    // the cycle from its write.
                    if f.placed != placed || !placed.is_placed() {
                        changed = true;
                        (f.write, f.placed) = (*checked, placed);
                    }
                }
                None => {
                    changed = true;
                    self.at.insert((w.index, w.leaf), self.held.len());
                    self.held.push(Force {
                        write: *checked,
                        uid,
                        since_utc_ns: now_utc_ns,
                        before,
                        placed,
                    });
                }
            }
        }
        self.scratch = undo;
        if changed {
            self.rebuild();
        }
        Ok(())
    }

    /// Ends the forces `release` names (each must be held: all or none), or all of them;
    /// with `restore`, each value is set back to what it was before its force.
    pub fn release(
        &mut self,
        gm: &mut T,
        release: &Release,
        uid: u32,
        now_utc_ns: u64,
    ) -> Result<(), Refused> {
        // Which held forces end, in the order named (each once: a value named twice is
        // released once).
        let mut ending = vec![release.all; self.held.len()];
        let ended: Vec<usize> = if release.all {
            (0..self.held.len()).collect()
        } else {
            let mut ended = Vec::with_capacity(release.values.len().min(self.held.len()));
            for (k, &(index, leaf)) in release.values.iter().enumerate() {
                // Named by a tool that may skip its checks: a value the program does not have
                // is said as such, never as another value's path or an empty one.
                if plc_rules::path::leaf(self.vars, index, leaf).is_none() {
                    return Err(Refused::rejected(
                        k,
                        format!("no value {index}/{leaf}: the program has none"),
                    ));
                }
                let Some(at) = self.find(index, leaf) else {
                    return Err(Refused::rejected(
                        k,
                        format!(
                            "`{}` is not forced (`plc forces` lists what is)",
                            self.path(index, leaf)
                        ),
                    ));
                };
                if !std::mem::replace(&mut ending[at], true) {
                    ended.push(at);
                }
            }
            ended
        };
        let mut log = Vec::with_capacity(ended.len());
        for &at in &ended {
            let f = &self.held[at];
            let w = f.write.write();
            let restored = match (release.restore, f.before) {
                (true, Some(before)) => {
                    let _ = gm.set(w.index, w.leaf, before);
                    Some(before)
                }
                _ => None,
            };
            log.push(Ended {
                index: w.index,
                leaf: w.leaf,
                forced_by: f.uid,
                restored,
            });
        }
        self.log.send(ForceEvent::Released {
            uid,
            ended: log,
            at_utc_ns: now_utc_ns,
        });
        let mut k = 0;
        self.held.retain(|_| {
            k += 1;
            !ending[k - 1]
        });
        self.at.clear();
        for (k, f) in self.held.iter().enumerate() {
            let w = f.write.write();
            self.at.insert((w.index, w.leaf), k);
        }
        self.rebuild();
        Ok(())
    }

    /// The forces held, by path.
    pub fn held(&self) -> Vec<super::carry::HeldForce> {
        self.held
            .iter()
            .map(|f| {
                let w = f.write.write();
                super::carry::HeldForce {
                    path: self.path(w.index, w.leaf),
                    value: w.value,
                    uid: f.uid,
                }
            })
            .collect()
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
}

#[cfg(test)]
#[path = "forces_tests.rs"]
mod tests;
