//! The table of alarm states in a segment, after the descriptor: a sequence word (odd while
//! the owner changes the table), then per alarm, in the descriptor's order, three words:
//!
//! ```text
//! word 0   state (bits 0..8), level (bits 8..16), waiting for an acknowledgement (bit 16)
//! word 1   since when, UTC ns (i64)
//! word 2   shelved until, UTC ns (i64; 0 while not shelved)
//! ```
//!
//! The owner stores the alarms that changed after each cycle's evaluation; tools (`plc
//! alarms`, `plc watch`, the OPC UA server, the Sparkplug node) read it whole. All words zero
//! is an alarm that is normal and was never raised, as a new segment's table is. A state
//! or level code no release knows is a damaged table, reported, never guessed at.

use super::alarm_descriptor::AlarmDescriptor;
use crate::calendar::utc_text;
use crate::sys::base::Base;
use plc_core::alarm::{AlarmState, Level};
use std::sync::atomic::{Ordering, fence};

/// Words of one alarm.
const WORDS: usize = 3;

/// Where the table lies and how many alarms it holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct AlarmTable {
    /// Byte offset of the sequence word.
    pub offset: usize,
    /// Alarms.
    pub count: usize,
}

impl AlarmTable {
    /// The table of `count` alarms after a descriptor that ends at byte `descriptor_end`.
    pub const fn after(descriptor_end: usize, count: usize) -> AlarmTable {
        AlarmTable {
            offset: super::layout::pad8(descriptor_end),
            count,
        }
    }

    /// The first byte after the table, or `None` if that is beyond the address space (a
    /// count read from another process).
    pub fn end(&self) -> Option<usize> {
        self.count
            .checked_mul(WORDS * 8)
            .and_then(|n| n.checked_add(8))
            .and_then(|n| n.checked_add(self.offset))
    }

    fn word(&self, alarm: usize, word: usize) -> usize {
        self.offset + 8 + 8 * (alarm * WORDS + word)
    }
}

/// One alarm's state as the table holds it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct AlarmEntry {
    /// Its state, as IEC 62682 names it.
    pub state: AlarmState,
    /// The level annunciated (`normal` while not active; kept while shelved or suppressed).
    pub level: Level,
    /// Whether nothing waits for an acknowledgement (kept while shelved or suppressed).
    pub acknowledged: bool,
    /// When it last changed state, UTC nanoseconds.
    pub since_ns: i64,
    /// While shelved: when it comes back by itself, UTC nanoseconds.
    pub shelved_until_ns: Option<i64>,
}

impl AlarmEntry {
    /// Normal, never changed: what a new table holds.
    pub const NORMAL: AlarmEntry = AlarmEntry {
        state: AlarmState::Normal,
        level: Level::Normal,
        acknowledged: true,
        since_ns: 0,
        shelved_until_ns: None,
    };

    /// Whether it is active: raised, or latched and waiting for its reset.
    pub fn active(&self) -> bool {
        self.level != Level::Normal
    }

    /// Its state as tools show it: `high-high, active unacknowledged` (a limit alarm's level
    /// first), `active acknowledged`, `shelved until 2026-12-05 15:00:00 UTC`.
    pub fn state_text(&self, alarm: &AlarmDescriptor) -> String {
        let state = match (self.state, self.shelved_until_ns) {
            (AlarmState::Shelved, Some(until)) => {
                format!("shelved until {}", utc_text(until.max(0) as u64))
            }
            (state, _) => state.name().to_string(),
        };
        if alarm.is_limit() && self.active() {
            format!("{}, {state}", self.level)
        } else {
            state
        }
    }

    fn encode(&self) -> [u64; WORDS] {
        let state = STATES.iter().position(|s| *s == self.state).unwrap_or(0) as u64;
        let level = LEVELS.iter().position(|l| *l == self.level).unwrap_or(0) as u64;
        [
            state | (level << 8) | (u64::from(!self.acknowledged) << 16),
            self.since_ns as u64,
            self.shelved_until_ns.unwrap_or(0) as u64,
        ]
    }

    fn decode(w: [u64; WORDS]) -> Option<AlarmEntry> {
        if w[0] >> 17 != 0 {
            return None;
        }
        let state = *STATES.get((w[0] & 0xff) as usize)?;
        let level = *LEVELS.get(((w[0] >> 8) & 0xff) as usize)?;
        let until = w[2] as i64;
        Some(AlarmEntry {
            state,
            level,
            acknowledged: w[0] & (1 << 16) == 0,
            since_ns: w[1] as i64,
            shelved_until_ns: (state == AlarmState::Shelved).then_some(until),
        })
    }
}

/// The states by their code on the wire.
const STATES: [AlarmState; 8] = [
    AlarmState::Normal,
    AlarmState::ActiveUnacknowledged,
    AlarmState::ActiveAcknowledged,
    AlarmState::ReturnedUnacknowledged,
    AlarmState::Latched {
        acknowledged: false,
    },
    AlarmState::Latched { acknowledged: true },
    AlarmState::Shelved,
    AlarmState::SuppressedByDesign,
];

/// The levels by their code on the wire.
const LEVELS: [Level; 6] = Level::ALL;

/// Stores `changed` alarms (number, entry) under the table's sequence word; numbers beyond
/// the table are skipped.
pub fn store(base: &Base, table: &AlarmTable, changed: impl Iterator<Item = (usize, AlarmEntry)>) {
    let seq = base.word(table.offset);
    let s = seq.load(Ordering::Relaxed);
    seq.store(s.wrapping_add(1), Ordering::Relaxed);
    fence(Ordering::Release);
    for (n, entry) in changed.filter(|(n, _)| *n < table.count) {
        for (k, v) in entry.encode().into_iter().enumerate() {
            base.store(table.word(n, k), v);
        }
    }
    seq.store(s.wrapping_add(2), Ordering::Release);
}

/// Why the table could not be read.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum TableError {
    /// The owner kept changing it through every try.
    Busy,
    /// Alarm `alarm`'s words hold a code no release writes.
    Damaged {
        /// Its number.
        alarm: usize,
    },
}

/// Reads every alarm's entry, retrying while the owner changes the table; the table's place
/// was checked against the mapping when the segment was attached.
pub fn read(base: &Base, table: &AlarmTable) -> Result<Vec<AlarmEntry>, TableError> {
    let seq = base.word(table.offset);
    let mut out = Vec::with_capacity(table.count);
    for _ in 0..1000 {
        let s1 = seq.load(Ordering::Acquire);
        if s1 % 2 == 1 {
            std::hint::spin_loop();
            continue;
        }
        out.clear();
        let mut damaged = None;
        for n in 0..table.count {
            let w = [0, 1, 2].map(|k| base.load(table.word(n, k)));
            match AlarmEntry::decode(w) {
                Some(e) => out.push(e),
                None => {
                    damaged.get_or_insert(n);
                    out.push(AlarmEntry::NORMAL);
                }
            }
        }
        fence(Ordering::Acquire);
        if seq.load(Ordering::Relaxed) == s1 {
            return match damaged {
                Some(alarm) => Err(TableError::Damaged { alarm }),
                None => Ok(out),
            };
        }
    }
    Err(TableError::Busy)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table(words: &mut [u64], count: usize) -> (Base, AlarmTable) {
        // SAFETY: the slice's u64s are 8-byte aligned, `len` bytes long, and outlive `base`
        // in each test.
        let base = unsafe { Base::new(words.as_mut_ptr().cast(), words.len() * 8) };
        (base, AlarmTable::after(3, count))
    }

    #[test]
    fn every_state_and_level_reads_back_as_stored_and_a_new_table_is_all_normal() {
        let mut words = vec![0u64; 1 + 1 + 3 * STATES.len()];
        let (base, t) = table(&mut words, STATES.len());
        assert_eq!(t.offset, 8);
        assert_eq!(read(&base, &t), Ok(vec![AlarmEntry::NORMAL; STATES.len()]));
        let entries: Vec<AlarmEntry> = STATES
            .iter()
            .enumerate()
            .map(|(n, &state)| AlarmEntry {
                state,
                level: LEVELS[n % LEVELS.len()],
                acknowledged: n % 2 == 0,
                since_ns: -(n as i64),
                shelved_until_ns: (state == AlarmState::Shelved).then_some(77),
            })
            .collect();
        store(&base, &t, entries.iter().copied().enumerate());
        assert_eq!(read(&base, &t), Ok(entries));
        assert_eq!(base.load(8), 2, "the sequence word moved on by two");
    }

    #[test]
    fn a_code_no_release_writes_is_damage_naming_the_alarm_and_a_table_changing_is_busy() {
        let mut words = vec![0u64; 1 + 1 + 3 * 2];
        let (base, t) = table(&mut words, 2);
        base.store(t.word(1, 0), 9);
        assert_eq!(read(&base, &t), Err(TableError::Damaged { alarm: 1 }));
        base.store(t.word(1, 0), 1 << 20);
        assert_eq!(read(&base, &t), Err(TableError::Damaged { alarm: 1 }));
        base.store(t.word(1, 0), 0);
        base.store(t.offset, 1);
        assert_eq!(read(&base, &t), Err(TableError::Busy));
        assert_eq!(AlarmTable::after(0, usize::MAX).end(), None);
    }
}
