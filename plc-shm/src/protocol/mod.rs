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
//! ```

mod commands;

pub use commands::{MAX_TRACED, Release, Request, Trace, decode, encode_release, encode_trace};

use plc_core::write::Write;
use plc_core::{FixedString, Value};

/// Protocol version, in the greeting: a tool and an owner of another version refuse each other.
/// Version 2 added forces and traces (and the segment's table of forces).
pub const VERSION: u16 = 2;
/// The greeting's first bytes.
const GREETING_MAGIC: &[u8; 4] = b"PLCW";
/// Writes in one request (a request is checked whole and applied in one cycle): an array of
/// up to 1,024 elements written whole lands in one cycle.
pub const MAX_WRITES: usize = 1024;
/// The largest message either side sends or reads: [`MAX_WRITES`] numbers fit (about 17 KiB),
/// and 247 texts of 255 bytes; a request of longer texts is refused before it is sent
/// ([`request_len`]).
pub const MAX_MESSAGE: usize = 64 << 10;
/// The longest reason a reply carries.
const MAX_REASON: usize = 1024;

const TAG_WRITE: u8 = 1;
const TAG_REPLY: u8 = 2;
const TAG_FORCE: u8 = 3;
const TAG_RELEASE: u8 = 4;
const TAG_TRACE: u8 = 5;

/// A request: writes checked whole and applied in one cycle, all or none.
#[derive(Clone, Debug, PartialEq)]
pub struct WriteRequest {
    /// The writer's number for it, echoed in the reply.
    pub id: u64,
    /// The writes, in order.
    pub writes: Vec<Write>,
}

/// What the owner did with a request.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Code {
    /// Applied, every write of it, at the start of a cycle.
    Applied = 0,
    /// Refused by the program's declaration or its `set` (`which` write, and why): nothing of
    /// the request was applied.
    Rejected = 1,
    /// The writer may not write this program (the policy's rule is the reason).
    Refused = 2,
    /// The message was not a valid request.
    Malformed = 3,
    /// Too many requests are waiting already: try again.
    Busy = 4,
    /// The owner stopped before it applied the request.
    Stopped = 5,
    /// A write to a value that is forced: nothing of the request was applied (`which` write,
    /// and who forced it).
    Forced = 6,
}

impl Code {
    fn from_byte(b: u8) -> Option<Code> {
        Some(match b {
            0 => Code::Applied,
            1 => Code::Rejected,
            2 => Code::Refused,
            3 => Code::Malformed,
            4 => Code::Busy,
            5 => Code::Stopped,
            6 => Code::Forced,
            _ => return None,
        })
    }
}

/// The owner's answer to a request.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Reply {
    /// The request's id.
    pub id: u64,
    /// What became of it.
    pub code: Code,
    /// The write of the request the reason is about (0 if none).
    pub which: u16,
    /// Why, for every code but `Applied`.
    pub reason: String,
}

/// The owner's greeting.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Greeting {
    /// The protocol version.
    pub version: u16,
    /// Whether the policy lets this connection's process write.
    pub may_write: bool,
}

/// Why a message could not be decoded: what of it was wrong, as the owner answers a tool (and
/// a tool reports an owner) that does not speak the protocol.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum DecodeError {
    /// Longer than [`MAX_MESSAGE`].
    TooLong {
        /// Its length, if known (a message cut by the socket's buffer is longer than that).
        len: Option<usize>,
    },
    /// It ends inside a field.
    Truncated {
        /// The field.
        what: &'static str,
        /// Bytes that were left.
        left: usize,
        /// Bytes the field needs.
        needed: usize,
    },
    /// Bytes follow its end.
    Trailing {
        /// How many.
        bytes: usize,
    },
    /// A text field that is not UTF-8 (the error is its [`source`](std::error::Error::source)).
    NotUtf8 {
        /// The field.
        what: &'static str,
        /// Where the valid text ends.
        error: std::str::Utf8Error,
    },
    /// A text holding a NUL character.
    Nul,
    /// Not the greeting's magic bytes.
    NotAGreeting,
    /// A byte that is none of the values its field may hold (a tag, a kind, a code, a bool).
    Unknown {
        /// The field.
        what: &'static str,
        /// The byte.
        byte: u8,
    },
    /// A request of no writes or more than [`MAX_WRITES`].
    WriteCount {
        /// The count it gives.
        count: usize,
    },
    /// A release or trace of too few or too many values, or a trace of every 0th cycle.
    Count {
        /// What was counted.
        what: &'static str,
        /// The count it gives.
        count: usize,
        /// The fewest allowed.
        min: usize,
        /// The most allowed.
        max: usize,
    },
    /// A reply's reason longer than the protocol carries (1,024 bytes).
    ReasonTooLong {
        /// The length it gives.
        len: usize,
    },
}

impl std::fmt::Display for DecodeError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            DecodeError::TooLong { len: Some(len) } => write!(
                f,
                "the message is {len} bytes, more than the {MAX_MESSAGE} allowed"
            ),
            DecodeError::TooLong { len: None } => write!(
                f,
                "the message is longer than the {MAX_MESSAGE} bytes allowed"
            ),
            DecodeError::Truncated { what, left, needed } => write!(
                f,
                "the message ends inside the {what} ({left} bytes left, {needed} needed)"
            ),
            DecodeError::Trailing { bytes } => {
                write!(f, "{bytes} bytes follow the end of the message")
            }
            DecodeError::NotUtf8 { what, error } => write!(f, "the {what} is not UTF-8: {error}"),
            DecodeError::Nul => f.write_str("a text holds a NUL character"),
            DecodeError::NotAGreeting => f.write_str("not a plc-vars greeting"),
            DecodeError::Unknown { what, byte } => write!(f, "{what} {byte}"),
            DecodeError::WriteCount { count } => {
                write!(f, "a request holds 1 to {MAX_WRITES} writes, not {count}")
            }
            DecodeError::Count {
                what,
                count,
                min,
                max,
            } => write!(f, "{what} must be {min} to {max}, not {count}"),
            DecodeError::ReasonTooLong { len } => write!(f, "a reason of {len} bytes"),
        }
    }
}

impl std::error::Error for DecodeError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            DecodeError::NotUtf8 { error, .. } => Some(error),
            _ => None,
        }
    }
}

/// Reads a message front to back, every read checked.
pub(super) struct Reader<'a> {
    rest: &'a [u8],
}

impl<'a> Reader<'a> {
    pub(super) fn take(&mut self, n: usize, what: &'static str) -> Result<&'a [u8], DecodeError> {
        if self.rest.len() < n {
            return Err(DecodeError::Truncated {
                what,
                left: self.rest.len(),
                needed: n,
            });
        }
        let (head, rest) = self.rest.split_at(n);
        self.rest = rest;
        Ok(head)
    }
    pub(super) fn array<const N: usize>(
        &mut self,
        what: &'static str,
    ) -> Result<[u8; N], DecodeError> {
        let mut a = [0u8; N];
        a.copy_from_slice(self.take(N, what)?);
        Ok(a)
    }
    pub(super) fn u8(&mut self, what: &'static str) -> Result<u8, DecodeError> {
        Ok(self.array::<1>(what)?[0])
    }
    pub(super) fn u16(&mut self, what: &'static str) -> Result<u16, DecodeError> {
        Ok(u16::from_le_bytes(self.array(what)?))
    }
    pub(super) fn u32(&mut self, what: &'static str) -> Result<u32, DecodeError> {
        Ok(u32::from_le_bytes(self.array(what)?))
    }
    pub(super) fn u64(&mut self, what: &'static str) -> Result<u64, DecodeError> {
        Ok(u64::from_le_bytes(self.array(what)?))
    }
    pub(super) fn utf8(&mut self, n: usize, what: &'static str) -> Result<&'a str, DecodeError> {
        std::str::from_utf8(self.take(n, what)?)
            .map_err(|error| DecodeError::NotUtf8 { what, error })
    }
    pub(super) fn end(&self) -> Result<(), DecodeError> {
        if self.rest.is_empty() {
            Ok(())
        } else {
            Err(DecodeError::Trailing {
                bytes: self.rest.len(),
            })
        }
    }
}

pub(super) fn start(bytes: &[u8]) -> Result<Reader<'_>, DecodeError> {
    if bytes.len() > MAX_MESSAGE {
        return Err(DecodeError::TooLong {
            len: Some(bytes.len()),
        });
    }
    Ok(Reader { rest: bytes })
}

/// The greeting's bytes.
pub fn encode_greeting(may_write: bool) -> Vec<u8> {
    let mut out = GREETING_MAGIC.to_vec();
    out.extend_from_slice(&VERSION.to_le_bytes());
    out.push(u8::from(may_write));
    out
}

/// Decodes a greeting.
pub fn decode_greeting(bytes: &[u8]) -> Result<Greeting, DecodeError> {
    let mut r = start(bytes)?;
    if r.take(4, "greeting")? != GREETING_MAGIC {
        return Err(DecodeError::NotAGreeting);
    }
    let version = r.u16("version")?;
    let may_write = match r.u8("write permission")? {
        0 => false,
        1 => true,
        byte => {
            return Err(DecodeError::Unknown {
                what: "write permission byte",
                byte,
            });
        }
    };
    r.end()?;
    Ok(Greeting { version, may_write })
}

/// How many bytes a request (or force) of `writes` takes: at most [`MAX_MESSAGE`] can be sent.
pub fn request_len(writes: &[Write]) -> usize {
    11 + writes
        .iter()
        .map(|w| {
            4 + 4
                + 1
                + match w.value {
                    Value::Bool(_) => 1,
                    Value::Text(t) => 1 + t.as_str().len(),
                    _ => 8,
                }
        })
        .sum::<usize>()
}

/// A request's bytes. The caller keeps to [`MAX_WRITES`] and [`MAX_MESSAGE`].
pub fn encode_request(request: &WriteRequest) -> Vec<u8> {
    encode_writes(TAG_WRITE, request)
}

/// A force's bytes: the values to hold, as a write request carries them.
pub fn encode_force(request: &WriteRequest) -> Vec<u8> {
    encode_writes(TAG_FORCE, request)
}

fn encode_writes(tag: u8, request: &WriteRequest) -> Vec<u8> {
    let mut out = vec![tag];
    out.extend_from_slice(&request.id.to_le_bytes());
    out.extend_from_slice(&(request.writes.len() as u16).to_le_bytes());
    for w in &request.writes {
        // 32 bits on the wire; an index beyond them (no declaration has one) becomes the
        // largest, which the owner refuses as no such variable.
        let wire = |n: usize| u32::try_from(n).unwrap_or(u32::MAX).to_le_bytes();
        out.extend_from_slice(&wire(w.index));
        out.extend_from_slice(&wire(w.leaf));
        match w.value {
            Value::Bool(b) => out.extend_from_slice(&[0, u8::from(b)]),
            Value::Int(i) => {
                out.push(1);
                out.extend_from_slice(&i.to_le_bytes());
            }
            Value::UInt(u) => {
                out.push(2);
                out.extend_from_slice(&u.to_le_bytes());
            }
            Value::Real(f) => {
                out.push(3);
                out.extend_from_slice(&f.to_bits().to_le_bytes());
            }
            Value::Text(t) => {
                let s = t.as_str().as_bytes();
                out.extend_from_slice(&[4, s.len() as u8]);
                out.extend_from_slice(s);
            }
            Value::Time(t) => {
                out.push(5);
                out.extend_from_slice(&t.as_nanos().to_le_bytes());
            }
        }
    }
    out
}

/// Decodes a write request.
pub fn decode_request(bytes: &[u8]) -> Result<WriteRequest, DecodeError> {
    match decode(bytes)? {
        Request::Write(w) => Ok(w),
        _ => Err(DecodeError::Unknown {
            what: "unknown message tag",
            byte: bytes[0],
        }),
    }
}

/// The rest of a write or force request, after its tag.
pub(super) fn decode_writes(r: &mut Reader<'_>) -> Result<WriteRequest, DecodeError> {
    let id = r.u64("request id")?;
    let count = usize::from(r.u16("write count")?);
    if count == 0 || count > MAX_WRITES {
        return Err(DecodeError::WriteCount { count });
    }
    // Bounded by MAX_WRITES, whatever the message says.
    let mut writes = Vec::with_capacity(count);
    for _ in 0..count {
        let index = r.u32("variable index")? as usize;
        let leaf = r.u32("element")? as usize;
        let value = match r.u8("value kind")? {
            0 => match r.u8("bool")? {
                0 => Value::Bool(false),
                1 => Value::Bool(true),
                byte => {
                    return Err(DecodeError::Unknown {
                        what: "bool byte",
                        byte,
                    });
                }
            },
            1 => Value::Int(r.u64("int")? as i64),
            2 => Value::UInt(r.u64("uint")?),
            3 => Value::Real(f64::from_bits(r.u64("real")?)),
            4 => {
                let len = usize::from(r.u8("text length")?);
                let text = r.utf8(len, "text")?;
                if text.contains('\0') {
                    return Err(DecodeError::Nul);
                }
                Value::Text(FixedString::from_str_truncate(text))
            }
            5 => Value::Time(plc_core::Time::from_nanos(r.u64("duration")? as i64)),
            byte => {
                return Err(DecodeError::Unknown {
                    what: "unknown value kind",
                    byte,
                });
            }
        };
        writes.push(Write { index, leaf, value });
    }
    r.end()?;
    Ok(WriteRequest { id, writes })
}

/// A reply's bytes; a reason longer than the protocol carries is cut at a character boundary.
pub fn encode_reply(reply: &Reply) -> Vec<u8> {
    let mut end = reply.reason.len().min(MAX_REASON);
    while !reply.reason.is_char_boundary(end) {
        end -= 1;
    }
    let reason = &reply.reason.as_bytes()[..end];
    let mut out = vec![TAG_REPLY];
    out.extend_from_slice(&reply.id.to_le_bytes());
    out.push(reply.code as u8);
    out.extend_from_slice(&reply.which.to_le_bytes());
    out.extend_from_slice(&(reason.len() as u16).to_le_bytes());
    out.extend_from_slice(reason);
    out
}

/// Decodes a reply.
pub fn decode_reply(bytes: &[u8]) -> Result<Reply, DecodeError> {
    let mut r = start(bytes)?;
    let tag = r.u8("tag")?;
    if tag != TAG_REPLY {
        return Err(DecodeError::Unknown {
            what: "unknown message tag",
            byte: tag,
        });
    }
    let id = r.u64("request id")?;
    let code = r.u8("code")?;
    let code = Code::from_byte(code).ok_or(DecodeError::Unknown {
        what: "reply code",
        byte: code,
    })?;
    let which = r.u16("write number")?;
    let len = usize::from(r.u16("reason length")?);
    if len > MAX_REASON {
        return Err(DecodeError::ReasonTooLong { len });
    }
    let reason = r.utf8(len, "reason")?.to_string();
    r.end()?;
    Ok(Reply {
        id,
        code,
        which,
        reason,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn any_value() -> impl Strategy<Value = Value> {
        prop_oneof![
            any::<bool>().prop_map(Value::Bool),
            any::<i64>().prop_map(Value::Int),
            any::<u64>().prop_map(Value::UInt),
            any::<u64>().prop_map(|b| Value::Real(f64::from_bits(b))),
            "[^\\x00]{0,60}".prop_map(|s| Value::Text(FixedString::from_str_truncate(&s))),
            any::<i64>().prop_map(|n| Value::Time(plc_core::Time::from_nanos(n))),
        ]
    }

    fn same(a: &Value, b: &Value) -> bool {
        match (a, b) {
            // NaN payloads compare by bits.
            (Value::Real(x), Value::Real(y)) => x.to_bits() == y.to_bits(),
            _ => a == b,
        }
    }

    #[test]
    fn a_thousand_numbers_fit_a_request_and_texts_as_many_as_64_kib_hold() {
        let number = Write {
            index: 1,
            leaf: 2,
            value: Value::Real(1.5),
        };
        assert!(request_len(&vec![number; MAX_WRITES]) <= MAX_MESSAGE);
        let text = Write {
            value: Value::Text(FixedString::from_str_truncate(&"x".repeat(255))),
            ..number
        };
        assert!(request_len(&vec![text; 247]) <= MAX_MESSAGE);
        assert!(request_len(&vec![text; 248]) > MAX_MESSAGE);
        let bytes = encode_request(&WriteRequest {
            id: 9,
            writes: vec![text; 248],
        });
        assert_eq!(bytes.len(), request_len(&vec![text; 248]));
        assert!(
            decode_request(&bytes).is_err(),
            "the owner refuses what a tool would not send"
        );
    }

    proptest! {
        /// Whatever bytes arrive, the decoders answer (a value or an error), never panic, and
        /// what they accept encodes back to the same bytes: one meaning per message.
        #[test]
        fn arbitrary_bytes_decode_to_an_error_or_to_their_one_meaning(
            bytes in proptest::collection::vec(any::<u8>(), 0..2048),
            tag in 0u8..4,
        ) {
            let mut bytes = bytes;
            if let Some(b) = bytes.first_mut() {
                *b = tag; // reach past the tag check most of the time
            }
            if let Ok(request) = decode_request(&bytes) {
                prop_assert_eq!(encode_request(&request), bytes.clone());
            }
            if let Ok(reply) = decode_reply(&bytes) {
                prop_assert_eq!(encode_reply(&reply), bytes.clone());
            }
            let _ = decode_greeting(&bytes);
        }

        /// Every request a tool can send decodes to itself, and every truncation of it is an
        /// error.
        #[test]
        fn requests_round_trip_and_their_truncations_are_refused(
            id in any::<u64>(),
            writes in proptest::collection::vec(
                (any::<u32>(), any::<u32>(), any_value()), 1..=MAX_WRITES),
            cut in any::<proptest::sample::Index>(),
        ) {
            let request = WriteRequest {
                id,
                writes: writes
                    .into_iter()
                    .map(|(index, leaf, value)| Write { index: index as usize, leaf: leaf as usize, value })
                    .collect(),
            };
            let bytes = encode_request(&request);
            prop_assert_eq!(bytes.len(), request_len(&request.writes));
            if bytes.len() > MAX_MESSAGE {
                // A tool refuses to send it (`request_len`); the owner would refuse it too.
                prop_assert!(decode_request(&bytes).is_err());
                return Ok(());
            }
            let back = decode_request(&bytes).unwrap();
            prop_assert_eq!(back.id, request.id);
            prop_assert_eq!(back.writes.len(), request.writes.len());
            for (a, b) in back.writes.iter().zip(&request.writes) {
                prop_assert!(a.index == b.index && a.leaf == b.leaf);
                prop_assert!(same(&a.value, &b.value), "{:?} / {:?}", a.value, b.value);
            }
            let cut = cut.index(bytes.len());
            prop_assert!(decode_request(&bytes[..cut]).is_err());
        }
    }

    #[test]
    fn a_request_with_no_or_too_many_writes_is_refused() {
        let mut none = vec![TAG_WRITE];
        none.extend_from_slice(&7u64.to_le_bytes());
        none.extend_from_slice(&0u16.to_le_bytes());
        assert!(decode_request(&none).unwrap_err() == DecodeError::WriteCount { count: 0 });
        let mut many = none.clone();
        many[9..11].copy_from_slice(&u16::MAX.to_le_bytes());
        assert!(
            decode_request(&many)
                .unwrap_err()
                .to_string()
                .contains("not 65535")
        );
    }

    #[test]
    fn a_long_reason_is_cut_at_a_character_boundary() {
        let reply = Reply {
            id: 1,
            code: Code::Rejected,
            which: 0,
            reason: "é".repeat(MAX_REASON),
        };
        let back = decode_reply(&encode_reply(&reply)).unwrap();
        assert_eq!(back.reason.len(), MAX_REASON);
    }

    #[test]
    fn greetings_round_trip() {
        for may_write in [false, true] {
            let g = decode_greeting(&encode_greeting(may_write)).unwrap();
            assert_eq!((g.version, g.may_write), (VERSION, may_write));
        }
    }
}
