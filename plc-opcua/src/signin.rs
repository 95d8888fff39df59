//! Sign-ins under a flood. A password check is argon2: tens of milliseconds of a core and about
//! 19 MiB on purpose, so that a stolen users file is slow to guess. Unbounded, the same cost
//! lets anyone who can reach the port take every core and gigabytes of the PLC's host with
//! sign-ins of a known name. Here the checks run a few at a time (the rest wait their turn,
//! holding nothing but their request), and a name that failed waits longer before each next
//! check (doubling from a quarter of a second up to five seconds, forgotten after ten quiet
//! minutes), which costs a guesser time without costing the server anything.

use crate::users::{Users, valid_name};
use std::collections::HashMap;
use std::sync::{Arc, Mutex, PoisonError};
use std::time::{Duration, Instant};
use tokio::sync::Semaphore;

/// Password checks that run at once, at most.
pub const CHECKS_AT_ONCE: usize = 2;
/// The wait after a name's first failure; it doubles with each further one.
const FIRST_DELAY: Duration = Duration::from_millis(250);
/// The longest wait.
const MAX_DELAY: Duration = Duration::from_secs(5);
/// A name's failures are forgotten after this long without one.
const FORGET_AFTER: Duration = Duration::from_secs(600);
/// Names whose failures are remembered, at most (the oldest is forgotten first).
const MAX_NAMES: usize = 4096;

/// The sign-in checks of one server.
pub struct SignIns {
    checks: Semaphore,
    failures: Mutex<HashMap<String, Failures>>,
}

#[derive(Clone, Copy, Debug)]
struct Failures {
    count: u32,
    last: Instant,
}

impl Default for SignIns {
    fn default() -> Self {
        SignIns {
            checks: Semaphore::new(CHECKS_AT_ONCE),
            failures: Mutex::default(),
        }
    }
}

/// The key a name's failures are counted under: a name the users file could not hold (nothing
/// to guess) shares one key, so random junk cannot fill the table.
fn key(name: &str) -> &str {
    if valid_name(name) { name } else { "?" }
}

/// The wait before the next check of a name that failed `count` times.
fn delay(count: u32) -> Duration {
    match count {
        0 => Duration::ZERO,
        n => FIRST_DELAY
            .saturating_mul(1 << (n - 1).min(16))
            .min(MAX_DELAY),
    }
}

impl SignIns {
    /// Whether `password` is `name`'s in `users`: after the name's wait, in its turn among the
    /// checks, off the async threads.
    pub async fn check(&self, users: Arc<Users>, name: &str, password: String) -> bool {
        let wait = self.wait_of(name, Instant::now());
        if !wait.is_zero() {
            tokio::time::sleep(wait).await;
        }
        let Ok(_turn) = self.checks.acquire().await else {
            return false;
        };
        let who = name.to_string();
        let ok = tokio::task::spawn_blocking(move || users.verify(&who, &password))
            .await
            .unwrap_or(false);
        self.record(name, ok, Instant::now());
        ok
    }

    /// How long `name` waits before its next check at `now`.
    fn wait_of(&self, name: &str, now: Instant) -> Duration {
        let table = self.failures.lock().unwrap_or_else(PoisonError::into_inner);
        match table.get(key(name)) {
            Some(f) if now.duration_since(f.last) < FORGET_AFTER => delay(f.count),
            _ => Duration::ZERO,
        }
    }

    /// Counts a failure of `name` at `now`, or forgets its failures after a success.
    fn record(&self, name: &str, ok: bool, now: Instant) {
        let mut table = self.failures.lock().unwrap_or_else(PoisonError::into_inner);
        if ok {
            table.remove(key(name));
            return;
        }
        if table.len() >= MAX_NAMES && !table.contains_key(key(name)) {
            table.retain(|_, f| now.duration_since(f.last) < FORGET_AFTER);
            if table.len() >= MAX_NAMES
                && let Some(oldest) = table
                    .iter()
                    .min_by_key(|(_, f)| f.last)
                    .map(|(k, _)| k.clone())
            {
                table.remove(&oldest);
            }
        }
        let entry = table.entry(key(name).to_string()).or_insert(Failures {
            count: 0,
            last: now,
        });
        if now.duration_since(entry.last) >= FORGET_AFTER {
            entry.count = 0;
        }
        entry.count = entry.count.saturating_add(1);
        entry.last = now;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_wait_doubles_from_a_quarter_second_up_to_five_seconds() {
        let waits: Vec<u128> = (0..8).map(|n| delay(n).as_millis()).collect();
        assert_eq!(waits, [0, 250, 500, 1000, 2000, 4000, 5000, 5000]);
        assert_eq!(delay(u32::MAX), MAX_DELAY);
    }

    #[test]
    fn a_failed_name_waits_a_success_forgets_and_ten_quiet_minutes_forget() {
        let s = SignIns::default();
        let t = Instant::now();
        assert_eq!(s.wait_of("operator", t), Duration::ZERO);
        s.record("operator", false, t);
        s.record("operator", false, t);
        assert_eq!(s.wait_of("operator", t), Duration::from_millis(500));
        assert_eq!(s.wait_of("other", t), Duration::ZERO, "names wait alone");
        assert_eq!(s.wait_of("operator", t + FORGET_AFTER), Duration::ZERO);
        s.record("operator", true, t);
        assert_eq!(s.wait_of("operator", t), Duration::ZERO);
    }

    #[test]
    fn junk_names_share_one_key_and_the_table_stays_bounded() {
        let s = SignIns::default();
        let t = Instant::now();
        s.record("bad name\n", false, t);
        s.record("\u{1b}[2J", false, t);
        assert_eq!(s.wait_of("other junk!", t), Duration::from_millis(500));
        for n in 0..(MAX_NAMES + 100) {
            s.record(
                &format!("user{n}"),
                false,
                t + Duration::from_millis(n as u64),
            );
        }
        let len = s.failures.lock().unwrap().len();
        assert!(len <= MAX_NAMES, "{len} names remembered");
        assert!(s.wait_of(&format!("user{}", MAX_NAMES + 99), t) > Duration::ZERO);
    }
}
