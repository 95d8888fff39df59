//! What the workspace's tests share to run other processes.
//!
//! - [`SpawnGuarded`]: every child a test starts ends with the test, whatever happens: a
//!   [`ChildGuard`] kills and reaps it (and what it started in its process group) when dropped,
//!   so a failed assertion leaves nothing running, and the kernel kills it
//!   (`PR_SET_PDEATHSIG`) when the thread that started it ends, so a test binary killed by a
//!   timeout leaves nothing either.
//! - [`install_executable`]: a copy of a binary another user may run, written by a process of
//!   its own so that no child forked meanwhile holds it open for writing (which makes running
//!   it fail with `Text file busy`).
//! - [`TmuxSession`]: a terminal program under a tmux server of the test's own, which ends
//!   with the session.

mod child;
mod executable;
mod tmux;

pub use child::{ChildGuard, SpawnGuarded};
pub use executable::install_executable;
pub use tmux::TmuxSession;
