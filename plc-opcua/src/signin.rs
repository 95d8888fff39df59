//! Sign-ins under a flood. A password check is argon2: tens of milliseconds of a core and about
//! 19 MiB on purpose, so that a stolen users file is slow to guess. Unbounded, the same cost
//! lets anyone who can reach the port take every core and gigabytes of the PLC's host with
//! sign-ins of a known name. Here the checks run a few at a time (the rest wait their turn,
//! holding nothing but their request), and a name that failed waits longer before each next
//! check (doubling from a quarter of a second up to five seconds, forgotten after ten quiet
//! minutes), which costs a guesser time without costing the server anything. The checks run on
//! threads of their own: on the runtime's pool of blocking threads, each of up to hundreds of
//! threads kept its own 19 MiB in the allocator after its check (200 failed sign-ins took the
//! server's peak memory from 76 to 570 MB).

use crate::users::{Users, valid_name};
use std::collections::HashMap;
use std::sync::mpsc::{Receiver, Sender, channel};
use std::sync::{Arc, Mutex, PoisonError};
use std::time::{Duration, Instant};
use tokio::sync::oneshot;

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

/// A password to check: the users, the name, the password, where the answer goes.
type Job = (Arc<Users>, String, String, oneshot::Sender<bool>);

/// The sign-in checks of one server.
pub struct SignIns {
    /// To the checking threads (started at the first sign-in).
    checks: Mutex<Option<Sender<Job>>>,
    failures: Mutex<HashMap<String, Failures>>,
}

#[derive(Clone, Copy, Debug)]
struct Failures {
    count: u32,
    last: Instant,
}

#[allow(clippy::derivable_impls)]
impl Default for SignIns {
    fn default() -> Self {
        SignIns {
            checks: Mutex::default(),
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
        let (reply, answer) = oneshot::channel();
        let sent = self
            .checker()
            .is_some_and(|c| c.send((users, name.to_string(), password, reply)).is_ok());
        let ok = sent && answer.await.unwrap_or(false);
        self.record(name, ok, Instant::now());
        ok
    }

    /// The checking threads' queue, the threads started if they are not yet.
    fn checker(&self) -> Option<Sender<Job>> {
        let mut checks = self.checks.lock().unwrap_or_else(PoisonError::into_inner);
        if checks.is_none() {
            let (tx, rx) = channel::<Job>();
            let rx = Arc::new(Mutex::new(rx));
            for n in 0..CHECKS_AT_ONCE {
                let rx = rx.clone();
                std::thread::Builder::new()
                    .name(format!("opcua-signin-{n}"))
                    .spawn(move || check_passwords(&rx))
                    .ok()?;
            }
            *checks = Some(tx);
        }
        checks.clone()
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

/// A checking thread: checks passwords until the server is gone.
fn check_passwords(jobs: &Mutex<Receiver<Job>>) {
    loop {
        let job = jobs.lock().unwrap_or_else(PoisonError::into_inner).recv();
        let Ok((users, name, password, reply)) = job else {
            return;
        };
        let _ = reply.send(users.verify(&name, &password));
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
