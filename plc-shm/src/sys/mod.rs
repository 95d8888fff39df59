//! The bottom layer: the system calls under a segment (its memory file, the SIGBUS guard, the
//! Unix socket, the runtime directory and its lock, user and group ids, clocks, scheduling, the stop signals),
//! each wrapped once. Nothing here knows a segment's format or either side of its socket.

pub mod base;
pub mod clock;
pub mod guard;
pub mod ids;
pub mod memfd;
pub mod priority;
pub mod rundir;
pub mod signals;
pub mod unix;
