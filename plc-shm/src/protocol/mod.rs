//! The messages on a segment's socket, as bytes, and their decoders. The socket is
//! `SOCK_SEQPACKET`: the kernel keeps each message whole, so a message is one datagram and
//! nothing here reassembles a stream.
//!
//! Every number is little endian. The decoders read bytes from another process: they check
//! every length before using it, never allocate more than the message they were given holds,
//! and refuse anything left over, so that a message has exactly one meaning.
//!
//! ```text
//! greeting (owner -> tool, with the segment's memfd attached):
//!     "PLCW"  version u16  may_write u8
//! write request (tool -> owner):
//!     1u8  id u64  count u16 (1..=MAX_WRITES)  then count times:
//!     index u32  element u32  kind u8  payload
//!         kind 0 bool (u8 0/1), 1 int (i64), 2 uint (u64), 3 real (f64 bits),
//!         4 text (len u8, then len bytes of UTF-8), 5 duration (i64 nanoseconds)
//! reply (owner -> tool; a trace's carries the trace's memfd):
//!     2u8  id u64  code u8  which u16  len u16  then len bytes of UTF-8 (the reason)
//! force (tool -> owner), as a write request with tag 3
//! release (tool -> owner):
//!     4u8  id u64  flags u8 (1 restore, 2 all)  count u16 (0..=MAX_WRITES, 0 only with all)
//!     then count times:  index u32  element u32
//! trace (tool -> owner):
//!     5u8  id u64  every u32 (>= 1)  count u16 (1..=MAX_TRACED)
//!     then count times:  index u32  element u32
//! alarm action (tool -> owner):
//!     6u8  id u64  action u8  flags u8 (1 all)  shelve for i64 (ns)
//!     comment len u8 + UTF-8  on behalf of len u8 + UTF-8  count u16  then count times: alarm u32
//! ```

mod alarm_actions;
mod answer;
mod commands;
mod decode_error;
mod greeting;
mod reader;
mod tags;
#[cfg(test)]
mod tests;
mod writes;

pub use crate::limits::{MAX_MESSAGE, MAX_TRACED, MAX_WRITES};
pub use alarm_actions::{AlarmAction, AlarmRequest, cut, encode_alarm};
pub use answer::{Code, Reply, Ticket, WriteOutcome, decode_reply, encode_reply};
pub use commands::{
    Release, Request, TraceRequest, decode, decode_request, encode_release, encode_trace,
};
pub use decode_error::DecodeError;
pub use greeting::{Greeting, VERSION, decode_greeting, encode_greeting};
pub use writes::{WriteRequest, encode_force, encode_request, request_len};
