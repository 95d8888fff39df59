//! The force log, an audit of every force and release: the cycle thread sends each as a plain
//! event (numbers and the value, nothing formatted: a flood of forces costs the cycle no
//! text), and the server's accepting thread turns them into lines. The lines are bounded:
//! per uid at most [`LINES`] every [`WINDOW`], then one line that says how many were not
//! shown; and when the channel is full the cycle counts the events it could not send, which
//! the log then reports. Nothing is lost without a line that says so.

use super::spent::{Spent, SpentTx};
use crate::calendar::utc_text;
use crate::log_limit::{LINES, WINDOW, Window};
use crate::naming::{path_of, shown_in_log};
use plc_core::write::Checked;
use plc_core::{Value, VarInfo};
use std::collections::HashMap;
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::sync::mpsc::{Receiver, SyncSender, TryRecvError, TrySendError};
use std::time::Instant;

/// Uids whose windows are kept at once: more (thousands of users forcing) and the oldest
/// quiet ones are forgotten after their held-back lines are reported.
const MAX_UIDS: usize = 64;

/// A force request or a release, as the cycle thread saw it.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum ForceEvent {
    /// `uid` forced each value of `writes` (the request's own values, moved, not copied: a
    /// flood of forces costs the cycle one send per request).
    Forced {
        uid: u32,
        writes: Vec<Checked>,
        at_utc_ns: u64,
    },
    /// `uid` released the forces `ended` names, in one request.
    Released {
        uid: u32,
        ended: Vec<Ended>,
        at_utc_ns: u64,
    },
}

/// A force a release ended: the one `forced_by` held, with the value set back if the release
/// asked for it.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Ended {
    pub index: usize,
    pub leaf: usize,
    pub forced_by: u32,
    pub restored: Option<Value>,
}

impl ForceEvent {
    fn uid(&self) -> u32 {
        match *self {
            ForceEvent::Forced { uid, .. } | ForceEvent::Released { uid, .. } => uid,
        }
    }

    /// The values it names, each a line of the log.
    pub fn values(&self) -> usize {
        match self {
            ForceEvent::Forced { writes, .. } => writes.len(),
            ForceEvent::Released { ended, .. } => ended.len(),
        }
    }

    /// The line for value `k` of it, values named as tools name them.
    fn line(&self, k: usize, vars: &[VarInfo]) -> String {
        match self {
            ForceEvent::Forced {
                uid,
                writes,
                at_utc_ns,
            } => {
                let w = writes[k].write();
                format!(
                    "uid {uid} forces `{}` = {} at {}",
                    path_of(vars, w.index, w.leaf),
                    shown_in_log(&w.value),
                    utc_text(*at_utc_ns)
                )
            }
            ForceEvent::Released {
                uid,
                ended,
                at_utc_ns,
            } => {
                let e = &ended[k];
                let restored = e
                    .restored
                    .map(|v| format!(", {} restored", shown_in_log(&v)))
                    .unwrap_or_default();
                format!(
                    "uid {uid} releases `{}` (forced by uid {}{restored}) at {}",
                    path_of(vars, e.index, e.leaf),
                    e.forced_by,
                    utc_text(*at_utc_ns)
                )
            }
        }
    }
}

/// The cycle thread's end: sends without waiting, counts what did not fit.
pub(crate) struct ForceLog {
    tx: SyncSender<ForceEvent>,
    /// Values sent and not yet logged: at most `capacity` ([`FORCE_LOG_LINES`] for an
    /// owner's log).
    waiting: Arc<AtomicU64>,
    capacity: u64,
    dropped: Arc<AtomicU64>,
    /// Where the values of a request the log could not take go to be freed.
    spent: SpentTx,
}

impl ForceLog {
    /// A log that holds at most `capacity` values waiting; what it cannot take goes to
    /// `spent`.
    pub fn channel(capacity: usize, spent: SpentTx) -> (ForceLog, ForceLogReader) {
        let (tx, rx) = std::sync::mpsc::sync_channel(capacity);
        let dropped = Arc::new(AtomicU64::new(0));
        let waiting = Arc::new(AtomicU64::new(0));
        let reader = ForceLogReader {
            rx,
            waiting: waiting.clone(),
            dropped: dropped.clone(),
            windows: HashMap::new(),
        };
        let log = ForceLog {
            tx,
            waiting,
            dropped,
            capacity: capacity as u64,
            spent,
        };
        (log, reader)
    }

    /// Sends `event`, or counts its values if the log holds too many waiting (the server fell
    /// behind).
    #[inline]
    pub fn send(&self, event: ForceEvent) {
        let n = event.values() as u64;
        // Only this thread adds: the reader only takes away, so the check holds.
        if self.waiting.load(Relaxed) + n > self.capacity {
            self.dropped.fetch_add(n, Relaxed);
            self.left_unlogged(event);
            return;
        }
        self.waiting.fetch_add(n, Relaxed);
        if let Err(TrySendError::Full(event) | TrySendError::Disconnected(event)) =
            self.tx.try_send(event)
        {
            self.waiting.fetch_sub(n, Relaxed);
            self.dropped.fetch_add(n, Relaxed);
            self.left_unlogged(event);
        }
    }

    /// Hands the values of a request that was not forced to be freed off the cycle thread.
    pub fn leave(&self, writes: Vec<Checked>) {
        self.spent.leave(Spent::Values(writes));
    }

    /// An event counted but not logged: its values are freed off the cycle thread.
    fn left_unlogged(&self, event: ForceEvent) {
        if let ForceEvent::Forced { writes, .. } = event {
            self.leave(writes);
        }
    }
}

/// The server's end: formats the events into lines at a bounded rate.
pub(crate) struct ForceLogReader {
    rx: Receiver<ForceEvent>,
    waiting: Arc<AtomicU64>,
    dropped: Arc<AtomicU64>,
    /// Each forcing uid's window of lines.
    windows: HashMap<u32, Window>,
}

/// How a line is logged.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Level {
    /// A force or a release.
    Info,
    /// What was not shown or not logged.
    Warn,
}

impl ForceLogReader {
    /// Takes up to `max` waiting events and hands `out` the lines for them at `now`: each
    /// event's, up to [`LINES`] per uid per [`WINDOW`], then (once the window ended) one line
    /// of how many were not shown; and one of how many the cycle could not send. With `now`
    /// `None` (the log closes) every count still held back is reported.
    pub fn drain(
        &mut self,
        vars: &[VarInfo],
        now: Option<Instant>,
        max: usize,
        out: &mut impl FnMut(Level, String),
    ) {
        let at = now.unwrap_or_else(Instant::now);
        for _ in 0..max {
            let event = match self.rx.try_recv() {
                Ok(event) => event,
                Err(TryRecvError::Empty | TryRecvError::Disconnected) => break,
            };
            let uid = event.uid();
            if !self.windows.contains_key(&uid) && self.windows.len() >= MAX_UIDS {
                self.forget_one(out);
            }
            let window = self.windows.entry(uid).or_default();
            for k in 0..event.values() {
                if let Some(before) = window.admit(at) {
                    if before > 0 {
                        out(Level::Warn, not_shown(before, uid));
                    }
                    out(Level::Info, event.line(k, vars));
                }
            }
            self.waiting.fetch_sub(event.values() as u64, Relaxed);
        }
        for (&uid, window) in &mut self.windows {
            let held = window.take_ended(now);
            if held > 0 {
                out(Level::Warn, not_shown(held, uid));
            }
        }
        let dropped = self.dropped.swap(0, Relaxed);
        if dropped > 0 {
            out(
                Level::Warn,
                format!("{dropped} force/release events were not logged: the log fell behind"),
            );
        }
    }

    /// The events waiting and the count the cycle could not send, taken (for tests of what
    /// the cycle sends).
    #[cfg(test)]
    pub fn take_events(&mut self) -> (Vec<ForceEvent>, u64) {
        let events: Vec<ForceEvent> = self.rx.try_iter().collect();
        let values = events.iter().map(ForceEvent::values).sum::<usize>();
        self.waiting.fetch_sub(values as u64, Relaxed);
        (events, self.dropped.swap(0, Relaxed))
    }

    /// Forgets one uid's window, saying first what it held back.
    fn forget_one(&mut self, out: &mut impl FnMut(Level, String)) {
        let Some(&uid) = self.windows.keys().next() else {
            return;
        };
        if let Some(mut window) = self.windows.remove(&uid) {
            let held = window.take_ended(None);
            if held > 0 {
                out(Level::Warn, not_shown(held, uid));
            }
        }
    }
}

fn not_shown(n: u64, uid: u32) -> String {
    format!(
        "{n} more forces and releases by uid {uid} not shown (at most {LINES} lines every \
         {WINDOW:?})"
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::Duration;

    fn forced(uid: u32, leaf: usize) -> ForceEvent {
        let write = plc_core::write::Write {
            index: 0,
            leaf,
            value: Value::Int(leaf as i64),
        };
        ForceEvent::Forced {
            uid,
            // A log checks nothing: any value formats.
            writes: vec![Checked::__unchecked(write)],
            at_utc_ns: 0,
        }
    }

    fn lines(reader: &mut ForceLogReader, now: Option<Instant>) -> Vec<(Level, String)> {
        let mut got = Vec::new();
        reader.drain(&[], now, usize::MAX, &mut |level, line| {
            got.push((level, line))
        });
        got
    }

    #[test]
    fn a_full_channel_counts_what_it_dropped_and_the_log_says_so() {
        let (log, mut reader) = ForceLog::channel(4, SpentTx::channel(1).0);
        for leaf in 0..10 {
            log.send(forced(7, leaf));
        }
        let t = Instant::now();
        let got = lines(&mut reader, Some(t));
        let info = got.iter().filter(|(l, _)| *l == Level::Info).count();
        assert_eq!(info, 4, "the four that fit are shown: {got:?}");
        assert_eq!(
            got.last().unwrap(),
            &(
                Level::Warn,
                "6 force/release events were not logged: the log fell behind".to_string()
            )
        );
        // Counted once: a second look has nothing to say.
        assert!(lines(&mut reader, Some(t)).is_empty());
    }

    #[test]
    fn a_flood_is_shown_at_a_bounded_rate_and_the_rest_counted_per_uid() {
        let (log, mut reader) = ForceLog::channel(100, SpentTx::channel(1).0);
        for leaf in 0..30 {
            log.send(forced(7, leaf));
        }
        log.send(forced(8, 0));
        let t = Instant::now();
        let got = lines(&mut reader, Some(t));
        assert_eq!(got.len(), LINES as usize + 1, "{got:?}");
        assert!(got.iter().all(|(l, _)| *l == Level::Info));
        assert!(got.iter().any(|(_, line)| line.starts_with("uid 8 forces")));
        // When uid 7's window ends, one line says how many of its events were not shown.
        let later = lines(&mut reader, Some(t + WINDOW + Duration::from_millis(1)));
        assert_eq!(
            later,
            [(
                Level::Warn,
                format!(
                    "20 more forces and releases by uid 7 not shown (at most {LINES} lines \
                     every {WINDOW:?})"
                )
            )]
        );
        // When the log closes, what is still held back is reported too.
        for leaf in 0..11 {
            log.send(forced(9, leaf));
        }
        let closing = lines(&mut reader, None);
        assert!(
            closing
                .last()
                .unwrap()
                .1
                .starts_with("1 more forces and releases by uid 9")
        );
    }
}
