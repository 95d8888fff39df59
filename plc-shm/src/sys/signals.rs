//! The one registration of SIGINT (Ctrl-C) and SIGTERM every process of plc-vars makes: the
//! runtime (its `StopHandle`) and the tools that write files as they go (`plc log`, `plc
//! trace`). It lives here, among the system calls, because both sides reach this crate.

use std::sync::Arc;
use std::sync::atomic::AtomicBool;

/// Makes SIGINT and SIGTERM set `stop` instead of ending the process at once, so the process
/// can finish cleanly (save, flush, release its I/O). A second signal while `stop` is still
/// set ends the process at once with exit code 1: the way out of a loop that never looks at
/// the flag again.
pub fn stop_on_signals(stop: &Arc<AtomicBool>) -> std::io::Result<()> {
    for sig in [signal_hook::consts::SIGINT, signal_hook::consts::SIGTERM] {
        // First the exit if a stop is already pending, then the flag: handlers of one signal
        // run in the order they were registered.
        signal_hook::flag::register_conditional_shutdown(sig, 1, stop.clone())?;
        signal_hook::flag::register(sig, stop.clone())?;
    }
    Ok(())
}
