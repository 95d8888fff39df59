//! How a record reads to people (`plc alarms --history`, a log line): its UTC time, number,
//! alarm and what happened, with who did it and what they wrote.

use super::record::{Entry, Operator, Record};
use std::fmt;

/// Text from the file as a terminal may show it: its control characters (which a file
/// written by hand could hold, to move the cursor or clear the screen) made `?`.
struct Clean<'a>(&'a str);

impl fmt::Display for Clean<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for c in self.0.chars() {
            let c = if c.is_control() { '?' } else { c };
            fmt::Write::write_char(f, c)?;
        }
        Ok(())
    }
}

impl fmt::Display for Operator {
    /// `anna (uid 1000): "pump checked"`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.user.is_empty() {
            f.write_str("an operator not named")?;
        } else {
            write!(f, "{}", Clean(&self.user))?;
        }
        if let Some(uid) = self.uid {
            write!(f, " (uid {uid})")?;
        }
        if let Some(c) = &self.comment {
            write!(f, ": {c:?}")?;
        }
        Ok(())
    }
}

fn value(v: &Option<f64>) -> String {
    v.map_or_else(String::new, |v| format!(" at {v}"))
}

impl fmt::Display for Entry {
    /// `raised high-high at 96.5`, `acknowledged by anna (uid 1000)`, ...
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Entry::Raised { level, value: v } => write!(f, "raised {level}{}", value(v)),
            Entry::LevelChanged { from, to, value: v } => {
                write!(f, "level {from} to {to}{}", value(v))
            }
            Entry::Cleared { from, value: v } => {
                write!(f, "returned to normal from {from}{}", value(v))
            }
            Entry::ConditionCleared { level, value: v } => write!(
                f,
                "condition cleared{}, latched at {level} until reset",
                value(v)
            ),
            Entry::Acknowledged { by } => write!(f, "acknowledged by {by}"),
            Entry::Reset { by } => write!(f, "reset by {by}"),
            Entry::Shelved { by, until_ns } => write!(
                f,
                "shelved until {} by {by}",
                plc_shm::utc_text(u64::try_from(*until_ns).unwrap_or(0))
            ),
            Entry::Unshelved { by: Some(by) } => write!(f, "unshelved by {by}"),
            Entry::Unshelved { by: None } => f.write_str("unshelved: the shelf expired"),
            Entry::Suppressed => f.write_str("suppressed by design"),
            Entry::Unsuppressed => f.write_str("no longer suppressed"),
            Entry::Summarised {
                transitions,
                actions,
            } => write!(
                f,
                "{transitions} transitions and {actions} operator actions not recorded one by \
                 one (a flood, or the journal could not write them)"
            ),
        }
    }
}

impl fmt::Display for Record {
    /// `2026-12-05 18:06:27 UTC #1251 door: raised active at 1`.
    ///
    /// ```
    /// use plc_runtime::alarm_journal::{Entry, Operator, Record};
    /// let r = Record {
    ///     seq: 1252,
    ///     time_ns: 1_764_950_405_000_000_000,
    ///     path: "door".into(),
    ///     entry: Entry::Acknowledged { by: Operator::new(Some(1000), "anna").with_comment("checked") },
    /// };
    /// assert_eq!(
    ///     r.to_string(),
    ///     r#"2025-12-05 16:00:05 UTC #1252 door: acknowledged by anna (uid 1000): "checked""#
    /// );
    /// ```
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let time = plc_shm::utc_text(u64::try_from(self.time_ns).unwrap_or(0));
        if self.path.is_empty() {
            write!(f, "{time} #{} {}", self.seq, self.entry)
        } else {
            write!(
                f,
                "{time} #{} {}: {}",
                self.seq,
                Clean(&self.path),
                self.entry
            )
        }
    }
}
