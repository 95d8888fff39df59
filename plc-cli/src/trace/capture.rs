//! `--pre N --post N` around the trigger: which of the drained rows the trace keeps.
//!
//! Without a trigger every row is kept as it comes. With one, the capture holds the last `pre`
//! rows in a ring and arms the trigger only once the ring is full, so exactly `pre` rows
//! precede the trigger row; then it emits those rows, the trigger row and exactly `post` more,
//! and is done.
//!
//! Rows the transport lost (the tool drained too slowly) are reported with
//! [`Capture::push_gap`]. Before the trigger, a gap empties the ring and forgets the trigger's
//! previous row: the rows before the trigger would not be contiguous, and an edge inside the
//! lost rows was not seen, so the capture starts over. After the trigger the rows go on, and the
//! gap is listed for the caller to report with the result.

use super::Row;
use super::trigger::Trigger;
use std::collections::VecDeque;
use std::fmt;

/// Cycles the transport lost, both ends included.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Gap {
    /// The first cycle lost.
    pub first_lost: u64,
    /// The last cycle lost.
    pub last_lost: u64,
}

impl fmt::Display for Gap {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "cycles {} to {} lost", self.first_lost, self.last_lost)
    }
}

/// How a capture ended, for the caller to report.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Summary {
    /// The trigger row's cycle; `None` if there is a trigger and it never fired.
    pub triggered_at: Option<u64>,
    /// Rows of `--post` not recorded because the trace ended first.
    pub post_missing: usize,
    /// Gaps inside the rows emitted.
    pub gaps: Vec<Gap>,
}

/// The trigger row: its cycle and time.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Fired {
    cycle: u64,
    time_ns: u64,
}

/// Chooses the rows of a trace: see the [module documentation](self).
#[derive(Debug)]
pub struct Capture {
    pre: usize,
    post: usize,
    trigger: Option<Trigger>,
    /// The last rows before the trigger, at most `pre`.
    ring: VecDeque<Row>,
    fired: Option<Fired>,
    /// Rows still to emit after the trigger row.
    post_left: usize,
    gaps: Vec<Gap>,
}

impl Capture {
    /// A capture keeping `pre` rows before the trigger and `post` after it; without a trigger
    /// it keeps every row and ignores `pre` and `post`.
    pub fn new(pre: usize, post: usize, trigger: Option<Trigger>) -> Capture {
        Capture {
            pre,
            post,
            trigger,
            // Not preallocated: `pre` is what the user typed, and the trace may end first.
            ring: VecDeque::new(),
            fired: None,
            post_left: 0,
            gaps: Vec::new(),
        }
    }

    /// Takes the next row and returns the rows to write now, oldest first: nothing while
    /// waiting for the trigger or once done, the held rows and the trigger row when it fires.
    pub fn push(&mut self, row: Row) -> Vec<Row> {
        let Some(trigger) = &mut self.trigger else {
            return vec![row];
        };
        if self.fired.is_some() {
            if self.post_left == 0 {
                return Vec::new();
            }
            self.post_left -= 1;
            return vec![row];
        }
        // Every row goes through the trigger, so it knows the row before the first armed one.
        let edge = trigger.fires(&row);
        let armed = self.ring.len() == self.pre;
        if edge && armed {
            self.fired = Some(Fired {
                cycle: row.cycle,
                time_ns: row.time_ns,
            });
            self.post_left = self.post;
            let mut out: Vec<Row> = self.ring.drain(..).collect();
            out.push(row);
            return out;
        }
        if self.pre > 0 {
            if armed {
                self.ring.pop_front();
            }
            self.ring.push_back(row);
        }
        Vec::new()
    }

    /// Reports that cycles `first_lost..=last_lost` were lost: before the trigger the capture
    /// starts over, after it the gap is listed (see the [module documentation](self)).
    pub fn push_gap(&mut self, first_lost: u64, last_lost: u64) {
        let gap = Gap {
            first_lost,
            last_lost,
        };
        if self.is_done() {
            return;
        }
        match (&mut self.trigger, self.fired) {
            (Some(trigger), None) => {
                self.ring.clear();
                trigger.reset();
            }
            // Without a trigger every row is written, so the gap is inside the output.
            _ => self.gaps.push(gap),
        }
    }

    /// The trigger row's cycle, once it fired.
    pub fn triggered_at(&self) -> Option<u64> {
        self.fired.map(|f| f.cycle)
    }

    /// The trigger row's time (ns since the program started), once it fired: time zero of the
    /// CSV and the picture.
    pub fn trigger_time_ns(&self) -> Option<u64> {
        self.fired.map(|f| f.time_ns)
    }

    /// Whether the trigger fired and all `post` rows were emitted: the trace can stop.
    pub fn is_done(&self) -> bool {
        self.fired.is_some() && self.post_left == 0
    }

    /// Ends the capture. Rows still held for a trigger that never fired are dropped: without a
    /// trigger row they have no time zero, and the summary says the trigger did not fire.
    pub fn finish(self) -> Summary {
        Summary {
            triggered_at: self.triggered_at(),
            post_missing: self.post_left,
            gaps: self.gaps,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use plc_core::{IecType, Value};

    /// Rows of one BOOL column, cycle = index, 1 ms apart.
    fn rows(bits: &str) -> Vec<Row> {
        bits.chars()
            .enumerate()
            .map(|(i, c)| Row {
                cycle: i as u64,
                time_ns: i as u64 * 1_000_000,
                values: vec![Value::Bool(c == '1')],
            })
            .collect()
    }

    fn rising() -> Trigger {
        Trigger::parse("b rising")
            .unwrap()
            .bind(0, IecType::Bool)
            .unwrap()
    }

    /// The cycles emitted for `bits`.
    fn emitted(capture: &mut Capture, bits: &str) -> Vec<u64> {
        rows(bits)
            .into_iter()
            .flat_map(|r| capture.push(r))
            .map(|r| r.cycle)
            .collect()
    }

    #[test]
    fn without_a_trigger_every_row_passes_through() {
        let mut c = Capture::new(2, 2, None);
        assert_eq!(emitted(&mut c, "0101"), [0, 1, 2, 3]);
        assert!(!c.is_done());
        assert_eq!(c.finish().triggered_at, None);
    }

    #[test]
    fn emits_exactly_pre_rows_the_trigger_row_and_post_rows() {
        let mut c = Capture::new(3, 2, Some(rising()));
        assert_eq!(emitted(&mut c, "000001000000"), [2, 3, 4, 5, 6, 7]);
        assert_eq!(c.triggered_at(), Some(5));
        assert_eq!(c.trigger_time_ns(), Some(5_000_000));
        assert!(c.is_done());
        let s = c.finish();
        assert_eq!((s.triggered_at, s.post_missing), (Some(5), 0));
    }

    #[test]
    fn an_edge_before_pre_rows_are_held_does_not_fire() {
        // The edge at cycle 1 comes with one row held of three; the next is at 6.
        let mut c = Capture::new(3, 1, Some(rising()));
        assert_eq!(emitted(&mut c, "01000011"), [3, 4, 5, 6, 7]);
        assert_eq!(c.triggered_at(), Some(6));
    }

    #[test]
    fn the_row_before_arming_counts_for_the_edge() {
        // Three rows held, all false: the fourth row rising is an edge.
        let mut c = Capture::new(3, 0, Some(rising()));
        assert_eq!(emitted(&mut c, "0001"), [0, 1, 2, 3]);
        assert!(c.is_done());
    }

    #[test]
    fn no_pre_rows_arms_at_once_but_still_needs_an_edge() {
        let mut c = Capture::new(0, 1, Some(rising()));
        assert_eq!(emitted(&mut c, "1101100"), [3, 4]);
    }

    #[test]
    fn a_trace_ending_early_reports_the_missing_post_rows() {
        let mut c = Capture::new(1, 5, Some(rising()));
        assert_eq!(emitted(&mut c, "0110"), [0, 1, 2, 3]);
        assert!(!c.is_done());
        assert_eq!(c.finish().post_missing, 3);
        let mut c = Capture::new(1, 5, Some(rising()));
        assert_eq!(emitted(&mut c, "0000"), [] as [u64; 0]);
        let s = c.finish();
        assert_eq!((s.triggered_at, s.post_missing), (None, 0));
    }

    #[test]
    fn a_gap_before_the_trigger_starts_the_pre_rows_over() {
        let mut c = Capture::new(2, 0, Some(rising()));
        let r = rows("0001");
        c.push(r[0].clone());
        c.push(r[1].clone());
        c.push_gap(2, 2);
        // The ring is empty again and the trigger has no row before cycle 3: no edge.
        assert!(c.push(r[3].clone()).is_empty());
        assert_eq!(c.triggered_at(), None);
        assert!(c.finish().gaps.is_empty());
    }

    #[test]
    fn a_gap_forgets_the_previous_row_of_the_trigger() {
        let mut c = Capture::new(0, 0, Some(rising()));
        let r = rows("01");
        c.push(r[0].clone());
        c.push_gap(5, 9);
        assert!(
            c.push(r[1].clone()).is_empty(),
            "the edge was in the lost rows"
        );
    }

    #[test]
    fn gaps_after_the_trigger_are_listed_until_done() {
        let mut c = Capture::new(0, 2, Some(rising()));
        assert_eq!(emitted(&mut c, "01"), [1]);
        c.push_gap(2, 4);
        let later = Row {
            cycle: 5,
            ..rows("1")[0].clone()
        };
        assert_eq!(c.push(later.clone()).len(), 1);
        assert_eq!(c.push(later).len(), 1);
        assert!(c.is_done());
        c.push_gap(6, 7);
        let gap = Gap {
            first_lost: 2,
            last_lost: 4,
        };
        assert_eq!(c.finish().gaps, [gap]);
        assert_eq!(gap.to_string(), "cycles 2 to 4 lost");
    }

    #[test]
    fn without_a_trigger_gaps_are_listed() {
        let mut c = Capture::new(0, 0, None);
        c.push_gap(1, 3);
        assert_eq!(c.finish().gaps.len(), 1);
    }
}
