//! Every bound of plc-shm in one place: what a message, a request, a queue, a trace and a
//! connection may hold at most. Each is checked where it is enforced; tools read the ones they
//! keep to from here (`plc_shm::limits`), so a changed bound changes everywhere at once.

use std::time::Duration;

/// Writes in one request (a request is checked whole and applied in one cycle): an array of
/// up to 1,024 elements written whole lands in one cycle. Forces and releases per request too.
pub const MAX_WRITES: usize = 1024;
/// The largest message either side sends or reads: [`MAX_WRITES`] numbers fit (about 17 KiB),
/// and 247 texts of 255 bytes; a request of longer texts is refused before it is sent
/// ([`request_len`](crate::protocol::request_len)).
pub const MAX_MESSAGE: usize = 64 << 10;
/// The longest reason a reply carries, in bytes.
pub const MAX_REASON: usize = 1024;

/// Values a trace records at most (a row of the ring holds this many words at most).
pub const MAX_TRACED: usize = 64;
/// Rows a trace's ring holds at least (a slow program's two seconds are fewer).
pub const MIN_TRACE_ROWS: u64 = 1024;
/// Rows a trace's ring holds at most (a fast program's two seconds are more): 8.8 MB at
/// [`MAX_TRACED`] values.
pub const MAX_TRACE_ROWS: u64 = 16_384;
/// Traces recorded at once (each costs the cycle a row's copy).
pub const MAX_TRACES: usize = 4;

/// Forces held at once, at most.
pub const MAX_FORCES: usize = 256;

/// Connections at once.
pub const MAX_CONNECTIONS: usize = 64;
/// Of those, the places kept for tools that may write (the owner's uid, the write group):
/// readers of other uids cannot lock out `plc set` or the OPC UA server.
pub const RESERVED_FOR_WRITERS: usize = 8;
/// Connections of one user at once: one user cannot take every place.
pub const MAX_PER_UID: usize = 32;
/// Connections the kernel holds for the owner before it accepts them.
pub const LISTEN_BACKLOG: i32 = 64;
/// How long a tool has to take its greeting (and the segment with it): a connection that
/// holds no segment after that is closed, so idle connections cannot keep places.
pub const GREETING_GRACE: Duration = Duration::from_secs(5);

/// Requests of one connection waiting for the cycle thread.
pub const MAX_OUTSTANDING: usize = 64;
/// Requests waiting for the cycle thread, from all connections.
pub const MAX_QUEUED: usize = 1024;
/// Writes (and forces and releases) that may wait for the cycle thread in all: about 4.5 MiB
/// of queued values, 16 requests of [`MAX_WRITES`].
pub const MAX_WAITING_WRITES: u64 = 16 * MAX_WRITES as u64;
/// How many requests one cycle applies at most; the rest wait for the next cycle.
pub const PER_CYCLE: usize = 256;
/// How many writes one cycle applies at most (a request is never split: one larger than the
/// rest of this budget waits for the next cycle, and the first request of a cycle is always
/// taken). A force or release of a value counts as the few writes it costs the cycle.
pub const PER_CYCLE_WRITES: u64 = 4096;
/// Forced and released values waiting for the server's thread to log them, at most (a
/// request is sent whole or not at all: a release of every force is [`MAX_FORCES`] values, a
/// force request at most [`MAX_WRITES`]); the cycle counts the values that do not fit, and the
/// log says how many.
pub const FORCE_LOG_LINES: usize = 1024;

/// The largest descriptor a tool reads. A program with thousands of variables has a
/// descriptor of a few megabytes; a larger length is taken to be damage, not read, so another
/// process cannot make a tool allocate what it likes.
pub const MAX_DESCRIPTOR: usize = 64 << 20;
/// The largest image a tool copies, for the same reason (process images are kilobytes).
pub const MAX_IMAGE: usize = 256 << 20;
/// The most supplementary groups read from a peer (Linux allows 65536; a process in more than
/// this many is checked against the first ones only).
pub const MAX_PEER_GROUPS: usize = 1024;
