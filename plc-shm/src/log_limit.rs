//! Refusals logged at a bounded rate: a process that sends thousands of refused requests a
//! second must not fill the owner's log (or its disk), and must not hide either: the line
//! after a quiet spell says how many were not logged.

use std::sync::Mutex;
use std::time::{Duration, Instant};

/// Lines per window at most.
pub(crate) const LINES: u32 = 10;
/// The window.
pub(crate) const WINDOW: Duration = Duration::from_secs(10);

/// Lets through at most ten lines every ten seconds, counting the rest.
///
/// ```
/// static REFUSALS: plc_shm::LogLimit = plc_shm::LogLimit::new("my_server");
/// for _ in 0..1000 {
///     // Ten lines are logged; the first after ten quiet seconds says how many were not.
///     REFUSALS.warn(|| "a request was refused".to_string());
/// }
/// ```
#[derive(Debug)]
pub struct LogLimit {
    target: &'static str,
    state: Mutex<Window>,
}

impl Default for LogLimit {
    fn default() -> Self {
        LogLimit::new("plc_io::shm")
    }
}

/// One window's count: the lines let through since it began and the lines held back. The
/// force log keeps one per uid.
#[derive(Debug, Default)]
pub(crate) struct Window {
    since: Option<Instant>,
    lines: u32,
    suppressed: u64,
}

impl Window {
    /// Whether a line may be logged at `now`: `Some` with how many lines were held back
    /// before it (counted once), or `None` (then it is counted as held back).
    pub(crate) fn admit(&mut self, now: Instant) -> Option<u64> {
        if self.since.is_none_or(|t| now.duration_since(t) >= WINDOW) {
            self.since = Some(now);
            self.lines = 0;
        }
        if self.lines >= LINES {
            self.suppressed += 1;
            return None;
        }
        self.lines += 1;
        Some(std::mem::take(&mut self.suppressed))
    }

    /// The lines held back, taken, once the window has ended at `now` (or at once with
    /// `now` `None`, as when the log closes): a quiet spell after a flood still says what it
    /// held back.
    pub(crate) fn take_ended(&mut self, now: Option<Instant>) -> u64 {
        let ended = match (now, self.since) {
            (Some(now), Some(t)) => now.duration_since(t) >= WINDOW,
            _ => true,
        };
        if ended {
            std::mem::take(&mut self.suppressed)
        } else {
            0
        }
    }
}

impl LogLimit {
    /// A limit for lines logged under the log target `target`.
    pub const fn new(target: &'static str) -> LogLimit {
        LogLimit {
            target,
            state: Mutex::new(Window {
                since: None,
                lines: 0,
                suppressed: 0,
            }),
        }
    }

    /// Logs `line` (built only if it will be logged) as a warning, or counts it.
    pub fn warn(&self, line: impl FnOnce() -> String) {
        if let Some(note) = self.allow(Instant::now()) {
            log::warn!(target: self.target, "{}{note}", line());
        }
    }

    /// Whether a line may be logged at `now`: `Some` with a note of the lines suppressed
    /// before it (empty if none), or `None`.
    fn allow(&self, now: Instant) -> Option<String> {
        let mut s = self.state.lock().unwrap_or_else(|p| p.into_inner());
        Some(match s.admit(now)? {
            0 => String::new(),
            n => format!(" ({n} more like it were not logged in the last {WINDOW:?})"),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ten_lines_a_window_and_the_next_says_how_many_were_not_logged() {
        let limit = LogLimit::default();
        let t = Instant::now();
        for _ in 0..10 {
            assert_eq!(limit.allow(t).as_deref(), Some(""));
        }
        for _ in 0..500 {
            assert_eq!(limit.allow(t + Duration::from_secs(1)), None);
        }
        let next = limit.allow(t + WINDOW).unwrap();
        assert!(next.contains("500 more like it"), "{next}");
        assert_eq!(limit.allow(t + WINDOW).as_deref(), Some(""));
    }
}
