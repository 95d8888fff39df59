//! A terminal program run under tmux, as a person would see it.

use std::io;
use std::process::{Command, Output};

use crate::SpawnGuarded;

/// The longest a program under tmux may live: tmux's server leaves the test's process tree,
/// so if the test is killed (a timeout) nothing else would end it.
const LONGEST_LIFE_S: u32 = 600;

/// One tmux session on a tmux server of its own (`tmux -L`), so that the test neither sees nor
/// disturbs anyone else's sessions. Dropping it kills that server and the program in it.
///
/// ```no_run
/// let watch = plc_test_support::TmuxSession::start("demo", 80, 24, "top").unwrap();
/// assert!(watch.screen().contains("load average"));
/// watch.send_keys(&["q"]);
/// ```
#[derive(Debug)]
pub struct TmuxSession {
    server: String,
    name: String,
}

impl TmuxSession {
    /// Whether tmux can be run here.
    pub fn available() -> bool {
        Command::new("tmux").arg("-V").output_guarded().is_ok()
    }

    /// Starts `command` (a shell command line) in a detached `width` x `height` window. The
    /// program is ended after 10 minutes whatever happens to the test.
    pub fn start(name: &str, width: u16, height: u16, command: &str) -> io::Result<TmuxSession> {
        let session = TmuxSession {
            server: format!("{name}-{}", std::process::id()),
            name: name.to_owned(),
        };
        let bounded = format!("exec timeout --foreground -k 5 {LONGEST_LIFE_S} {command}");
        let (w, h) = (width.to_string(), height.to_string());
        let out = session.run(&[
            "new-session",
            "-d",
            "-s",
            name,
            "-x",
            &w,
            "-y",
            &h,
            &bounded,
        ])?;
        if !out.status.success() {
            return Err(io::Error::other(format!(
                "tmux new-session: {}",
                String::from_utf8_lossy(&out.stderr).trim()
            )));
        }
        Ok(session)
    }

    /// What the window shows now.
    pub fn screen(&self) -> String {
        self.run(&["capture-pane", "-p", "-t", &self.name])
            .map(|o| String::from_utf8_lossy(&o.stdout).into_owned())
            .unwrap_or_default()
    }

    /// Types `keys` (tmux key names such as `Enter`, `Down`, or text).
    pub fn send_keys(&self, keys: &[&str]) {
        let mut args = vec!["send-keys", "-t", &self.name];
        args.extend_from_slice(keys);
        let _ = self.run(&args);
    }

    /// Whether the session still runs (its program has not quit).
    pub fn is_running(&self) -> bool {
        self.run(&["has-session", "-t", &self.name])
            .is_ok_and(|o| o.status.success())
    }

    fn run(&self, args: &[&str]) -> io::Result<Output> {
        Command::new("tmux")
            .args(["-L", &self.server])
            .args(args)
            .output_guarded()
    }
}

impl Drop for TmuxSession {
    fn drop(&mut self) {
        let _ = self.run(&["kill-server"]);
    }
}
