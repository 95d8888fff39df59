//! Forces, as TwinCAT and CODESYS force: values the owner holds at both of the cycle's
//! boundaries until they are released or the program stops. The cycle thread keeps the table
//! (it applies forces and refuses writes to forced values, so nothing races it) and publishes
//! it in the segment for tools. Its forces and releases go to the server's thread as plain
//! events ([`ForceLog`]), formatted there, so a flood of forces costs the cycle no text; the
//! held forces are indexed by value, so a request costs the cycle about what a write of as
//! many values does.

use super::force_log::{ForceEvent, ForceLog};
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
use std::collections::{HashMap, HashSet};

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

/// The bytes that hold a forced value where it lies in `T`, or `None` if `T` does not say.
type Placed<T> = Option<Vec<PlacedBytes<T>>>;

/// The forces the cycle thread holds.
pub(crate) struct ForceTable<T> {
    held: Vec<Force<T>>,
    /// Where each held value (variable, leaf) is in `held`: a lookup per value, not a search.
    at: HashMap<(usize, usize), usize>,
    /// What applying them writes, rebuilt when they change: every force's placed bytes, in
    /// the order held (a later force wins where two write the same bytes) ...
    stores: HeldBytes<T>,
    /// ... and the forces `T` does not place, set through `set` after the stores (a type
    /// places all its values or, written by hand, none: the two never hold the same bytes).
    unplaced: Vec<Checked>,
    vars: &'static [VarInfo],
    /// Events for the log, formatted by the server's accepting thread.
    log: ForceLog,
}

impl<T: GlobalMemory> ForceTable<T> {
    pub fn new(vars: &'static [VarInfo], log: ForceLog) -> Self {
        ForceTable {
            held: Vec::new(),
            at: HashMap::with_capacity(MAX_FORCES),
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
        self.at.get(&(index, leaf)).copied()
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
        // The values not held yet, each once (a value named twice in a request is one
        // force); a flood of re-forces adds none here.
        let mut new = HashSet::new();
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
        // Each value's place, its value from before and its bytes as `set` wrote them
        // (captured at once: a later value of the request that shares its bytes does not
        // change what this force holds).
        let mut undo: Vec<(usize, usize, Option<Value>, Placed<T>)> =
            Vec::with_capacity(writes.len());
        for (k, checked) in writes.iter().enumerate() {
            let w = checked.write();
            let before = gm.try_get(w.index, w.leaf);
            if let Err(e) = gm.set(w.index, w.leaf, w.value) {
                for (index, leaf, old, _) in undo.into_iter().rev() {
                    if let Some(old) = old {
                        let _ = gm.set(index, leaf, old);
                    }
                }
                return Err(Refused::rejected(
                    k,
                    format!("`{}`: {e}", self.path(w.index, w.leaf)),
                ));
            }
            undo.push((w.index, w.leaf, before, placed(gm, w.index, w.leaf)));
        }
        for (checked, (index, leaf, before, placed)) in writes.iter().zip(undo) {
            let force = Force {
                write: *checked,
                uid,
                since_utc_ns: now_utc_ns,
                before,
                placed,
            };
            match self.find(index, leaf) {
                Some(k) => {
                    let first = self.held[k].before;
                    self.held[k] = Force {
                        before: first,
                        ..force
                    };
                }
                None => {
                    self.at.insert((index, leaf), self.held.len());
                    self.held.push(force);
                }
            }
            self.log.send(ForceEvent::Forced {
                uid,
                index,
                leaf,
                value: checked.write().value,
                at_utc_ns: now_utc_ns,
            });
        }
        self.rebuild();
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
            self.log.send(ForceEvent::Released {
                uid,
                index: w.index,
                leaf: w.leaf,
                forced_by: f.uid,
                restored,
                at_utc_ns: now_utc_ns,
            });
        }
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

/// The bytes that hold value `leaf` of variable `index` where it lies in `gm`, which holds
/// its forced value; `None` if `T` does not say where it lies.
fn placed<T: GlobalMemory>(gm: &T, index: usize, leaf: usize) -> Placed<T> {
    let mut stores = Vec::new();
    place::capture(gm, index, leaf, |s| stores.push(s)).then_some(stores)
}

#[cfg(test)]
mod tests {
    use super::super::force_log::ForceLogReader;
    use super::*;
    use crate::limits::{FORCE_LOG_LINES, MAX_WRITES};
    use plc_core::write::{Write, check_force};

    #[derive(plc_core::GlobalMemory, Debug, Clone)]
    struct Gm {
        speed: i32,
        values: [i32; 256],
    }

    const SPEED: usize = 0;
    const VALUES: usize = 1;

    fn table() -> (ForceTable<Gm>, ForceLogReader) {
        let (log, reader) = ForceLog::channel(FORCE_LOG_LINES);
        (ForceTable::new(Gm::VARIABLES, log), reader)
    }

    fn forced(index: usize, leaf: usize, v: i64) -> Checked {
        let write = Write {
            index,
            leaf,
            value: Value::Int(v),
        };
        check_force(Gm::VARIABLES, write).unwrap()
    }

    fn release(values: &[(usize, usize)], restore: bool) -> Release {
        Release {
            id: 1,
            restore,
            all: false,
            values: values.to_vec(),
        }
    }

    #[test]
    fn a_re_force_keeps_the_first_before_and_refusals_name_who_forced() {
        let (mut forces, _log) = table();
        let mut gm = Gm {
            speed: 3,
            ..Gm::default()
        };
        forces
            .force(&mut gm, &[forced(SPEED, 0, 7)], 1000, 0)
            .unwrap();
        forces
            .force(&mut gm, &[forced(SPEED, 0, 9)], 1001, 0)
            .unwrap();
        assert_eq!((forces.len(), gm.speed), (1, 9), "one force, the new value");
        let why = forces.refusal(SPEED, 0).unwrap();
        assert!(
            why.starts_with("`speed` is forced (by uid 1001 since "),
            "{why}"
        );
        assert_eq!(
            forces.refusal(VALUES, 0),
            None,
            "only the forced value is refused"
        );
        gm.speed = 100;
        forces.apply(&mut gm);
        assert_eq!(gm.speed, 9, "held at both boundaries");
        forces
            .release(&mut gm, &release(&[(SPEED, 0)], true), 1000, 0)
            .unwrap();
        assert_eq!(
            (forces.len(), gm.speed),
            (0, 3),
            "restored to before the first"
        );
        assert_eq!(forces.refusal(SPEED, 0), None);
    }

    #[test]
    fn a_release_of_a_value_not_forced_is_refused_naming_it_and_ends_nothing() {
        let (mut forces, _log) = table();
        let mut gm = Gm::default();
        let writes = [
            forced(VALUES, 4, 1),
            forced(VALUES, 5, 2),
            forced(SPEED, 0, 3),
        ];
        forces.force(&mut gm, &writes, 1000, 0).unwrap();
        let named = release(&[(VALUES, 5), (VALUES, 6)], false);
        let refused = forces.release(&mut gm, &named, 1000, 0).unwrap_err();
        assert_eq!(refused.which, 1);
        assert!(
            refused.why.starts_with("`values[6]` is not forced"),
            "{}",
            refused.why
        );
        assert_eq!(forces.len(), 3, "all or none");
        // Values the program does not have, as a hostile tool may name them.
        for (index, leaf) in [(u32::MAX as usize, 0), (VALUES, 9999), (SPEED, 1)] {
            let named = release(&[(SPEED, 0), (index, leaf)], false);
            let refused = forces.release(&mut gm, &named, 1000, 0).unwrap_err();
            assert_eq!(refused.which, 1);
            assert_eq!(
                refused.why,
                format!("no value {index}/{leaf}: the program has none")
            );
        }
        assert_eq!(forces.len(), 3, "all or none");
        // A value named twice is released once; the others keep their places in the index.
        let twice = release(&[(VALUES, 5), (VALUES, 5)], false);
        // One more than the limit is refused, whole, saying how many it adds.
        let over: Vec<Checked> = (0..256)
            .filter(|k| ![4, 5].contains(k))
            .map(|k| forced(VALUES, k, 1))
            .collect();
        let refused = forces.force(&mut gm, &over, 1000, 0).unwrap_err();
        assert!(
            refused
                .why
                .starts_with("3 forces are held and this request adds 254"),
            "{}",
            refused.why
        );
        assert_eq!((forces.len(), gm.values[7]), (3, 0));
        assert_eq!(
            MAX_FORCES, 256,
            "the count above is 3 + 254 = MAX_FORCES + 1"
        );
        forces.release(&mut gm, &twice, 1000, 0).unwrap();
        assert_eq!(forces.len(), 2);
        assert!(forces.refusal(VALUES, 5).is_none());
        assert!(forces.refusal(VALUES, 4).is_some() && forces.refusal(SPEED, 0).is_some());
        (gm.values[4], gm.speed) = (0, 0);
        forces.apply(&mut gm);
        assert_eq!((gm.values[4], gm.speed), (1, 3));
    }

    #[test]
    fn a_flood_of_re_forces_sends_plain_events_and_counts_what_did_not_fit() {
        let (mut forces, mut log) = table();
        let mut gm = Gm::default();
        // 257 copies of one value are one force: not above the limit.
        let copies = vec![forced(VALUES, 0, 1); 257];
        forces.force(&mut gm, &copies, 1000, 5).unwrap();
        assert_eq!(forces.len(), 1);
        let (events, dropped) = log.take_events();
        assert_eq!((events.len(), dropped), (257, 0));
        let all: Vec<Checked> = (0..256).map(|k| forced(VALUES, k, 1)).collect();
        forces.force(&mut gm, &all, 1000, 5).unwrap();
        let (events, dropped) = log.take_events();
        assert_eq!((events.len(), dropped), (256, 0));
        // One request of 1,024 re-forces of the 256 held values: the channel holds
        // FORCE_LOG_LINES events, and every one that does not fit is counted.
        forces.force(&mut gm, &all, 1000, 5).unwrap();
        let again: Vec<Checked> = (0..MAX_WRITES)
            .map(|k| forced(VALUES, k % 256, 2))
            .collect();
        forces.force(&mut gm, &again, 1001, 6).unwrap();
        assert_eq!(forces.len(), 256, "re-forces add nothing");
        let (events, dropped) = log.take_events();
        assert_eq!(events.len(), FORCE_LOG_LINES);
        assert_eq!(dropped as usize, 256 + MAX_WRITES - FORCE_LOG_LINES);
        // The last that fit: the 768th of the second request.
        assert_eq!(
            events.last(),
            Some(&ForceEvent::Forced {
                uid: 1001,
                index: VALUES,
                leaf: 767 % 256,
                value: Value::Int(2),
                at_utc_ns: 6,
            })
        );
        assert!(
            events
                .iter()
                .all(|e| matches!(e, ForceEvent::Forced { .. }))
        );
        // Released with restore, each value goes back to 0, from before the first force.
        let every = Release {
            id: 2,
            restore: true,
            all: true,
            values: Vec::new(),
        };
        forces.release(&mut gm, &every, 1000, 7).unwrap();
        assert!(gm.values.iter().all(|&v| v == 0));
        let (events, dropped) = log.take_events();
        assert_eq!((events.len(), dropped), (256, 0));
        assert_eq!(
            events[3],
            ForceEvent::Released {
                uid: 1000,
                index: VALUES,
                leaf: 3,
                forced_by: 1001,
                restored: Some(Value::Int(0)),
                at_utc_ns: 7,
            }
        );
    }
}
