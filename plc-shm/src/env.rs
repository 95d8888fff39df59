//! The environment variables plc-shm reads.

/// The environment variable that names the runtime directory (tests, several instances,
/// tools reading another user's programs).
pub const RUNTIME_DIR_ENV: &str = "PLC_VARS_RUNTIME_DIR";
