//! The first byte of every message but the greeting: what the message is.

/// A write request (tool -> owner).
pub const TAG_WRITE: u8 = 1;
/// A reply (owner -> tool).
pub const TAG_REPLY: u8 = 2;
/// A force (tool -> owner).
pub const TAG_FORCE: u8 = 3;
/// A release of forces (tool -> owner).
pub const TAG_RELEASE: u8 = 4;
/// A trace to start (tool -> owner).
pub const TAG_TRACE: u8 = 5;
/// An operator's action on alarms (tool -> owner).
pub const TAG_ALARM: u8 = 6;
