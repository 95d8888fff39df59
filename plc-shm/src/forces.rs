//! Forces, as TwinCAT and CODESYS force: values the owner holds at both of the cycle's
//! boundaries until they are released or the program stops. The cycle thread keeps the table
//! (it applies forces and refuses writes to forced values, so nothing races it) and publishes
//! it in the segment for tools; the lines it logs go to the server's thread, which writes
//! them, so a release of 256 forces costs the cycle no terminal output.

use super::layout::{Base, MAX_FORCES, Offsets};
use super::protocol::Release;
use plc_core::place::{self, HeldBytes, PlacedBytes};
use plc_core::write::{self, Checked};
use plc_core::{GlobalMemory, Value, VarInfo};
use std::sync::atomic::{Ordering, fence};
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

/// A force as tools read it from the segment; its value is the image's, which holds it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ForceInfo {
    /// Index of the top-level variable.
    pub index: usize,
    /// The basic value within it.
    pub leaf: usize,
    /// Who forced it.
    pub uid: u32,
    /// When, in nanoseconds since the Unix epoch (UTC).
    pub since_utc_ns: u64,
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

/// Why a force or release was refused: which value of the request, and why.
pub(crate) type Refused = (usize, String);

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

    /// Forces `writes` (checked by [`write::check_force`]) for `uid`, all or none: each is set
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
            return Err((
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
                return Err((k, format!("`{}`: {e}", self.path(w.index, w.leaf))));
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
                        return Err((
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

    /// Stores the table in the segment under its own sequence word (odd while it changes).
    pub fn publish(&self, base: &Base, off: &Offsets) {
        let seq = base.word(off.f_seq());
        let s = seq.load(Ordering::Relaxed);
        seq.store(s.wrapping_add(1), Ordering::Relaxed);
        fence(Ordering::Release);
        base.store(off.f_count(), self.held.len() as u64);
        for (n, f) in self.held.iter().enumerate() {
            let w = f.write.write();
            let words = [
                w.index as u64,
                w.leaf as u64,
                u64::from(f.uid),
                f.since_utc_ns,
            ];
            for (k, v) in words.into_iter().enumerate() {
                base.store(off.f_entry(n, k), v);
            }
        }
        seq.store(s.wrapping_add(2), Ordering::Release);
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

/// Reads the table of forces a segment holds, retrying while its owner changes it. The words
/// come from another process: the count is bounded and a table still changing after many tries
/// is reported as none rather than waited for.
pub(crate) fn read(base: &Base, off: &Offsets) -> Option<Vec<ForceInfo>> {
    let seq = base.word(off.f_seq());
    for _ in 0..1000 {
        let s1 = seq.load(Ordering::Acquire);
        if s1 % 2 == 1 {
            std::hint::spin_loop();
            continue;
        }
        let count = (base.load(off.f_count()) as usize).min(MAX_FORCES);
        let mut out = Vec::with_capacity(count);
        for n in 0..count {
            let w = |k| base.load(off.f_entry(n, k));
            out.push(ForceInfo {
                index: usize::try_from(w(0)).unwrap_or(usize::MAX),
                leaf: usize::try_from(w(1)).unwrap_or(usize::MAX),
                uid: u32::try_from(w(2)).unwrap_or(u32::MAX),
                since_utc_ns: w(3),
            });
        }
        fence(Ordering::Acquire);
        if seq.load(Ordering::Relaxed) == s1 {
            return Some(out);
        }
    }
    None
}

/// The path of basic value `leaf` of variable `index`: the variable or member's path, with
/// the element of an array of basic values (`speeds[2]`, `axes[1].pos`).
pub fn path_of<N: plc_rules::path::Node>(vars: &[N], index: usize, leaf: usize) -> String {
    let mut text = write::label(vars, index, leaf).to_string();
    if let Some(found) = plc_rules::path::leaf(vars, index, leaf)
        && !found.node.dims().is_empty()
    {
        let coords = plc_rules::path::coordinates(found.element, found.node.dims());
        text.push_str(&format!("[{coords}]"));
    }
    text
}

/// A value in a log line: text quoted with its control characters escaped, so a value cannot
/// forge lines or drive a terminal.
///
/// ```
/// use plc_core::{FixedString, Value};
/// let text = Value::Text(FixedString::from_str_truncate("ok\n\u{1b}[2J"));
/// assert_eq!(plc_shm::shown_in_log(&text), r#""ok\n\u{1b}[2J""#);
/// assert_eq!(plc_shm::shown_in_log(&Value::Int(-3)), "-3");
/// ```
pub fn shown_in_log(value: &Value) -> String {
    match value {
        Value::Text(t) => format!("{:?}", t.as_str()),
        other => other.to_string(),
    }
}

/// `2026-12-03 21:14:03 UTC` for nanoseconds since the Unix epoch.
pub fn utc_text(ns: u64) -> String {
    let secs = ns / 1_000_000_000;
    let (days, rest) = (secs / 86_400, secs % 86_400);
    let (y, m, d) = civil_from_days(days as i64);
    format!(
        "{y:04}-{m:02}-{d:02} {:02}:{:02}:{:02} UTC",
        rest / 3600,
        rest / 60 % 60,
        rest % 60
    )
}

/// The proleptic Gregorian date of a day count since 1970-01-01 (the era arithmetic of
/// Howard Hinnant's `civil_from_days`, written out here).
fn civil_from_days(z: i64) -> (i64, u32, u32) {
    let z = z + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let m = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    let y = yoe + era * 400 + i64::from(m <= 2);
    (y, m, d)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn utc_times_read_as_calendar_dates() {
        assert_eq!(utc_text(0), "1970-01-01 00:00:00 UTC");
        // 2026-12-03 21:14:03 UTC
        assert_eq!(
            utc_text(1_796_332_443 * 1_000_000_000),
            "2026-12-03 21:14:03 UTC"
        );
        assert_eq!(
            utc_text(951_782_400 * 1_000_000_000),
            "2000-02-29 00:00:00 UTC"
        );
    }
}
