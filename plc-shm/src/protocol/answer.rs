//! What became of a request: the owner's answer on the wire ([`Reply`] with its [`Code`]), and
//! the tool's handle to ask for it later ([`Ticket`], [`WriteOutcome`]). Both sides use these;
//! neither side's code is needed to read them.

use super::decode_error::DecodeError;
use super::reader::start;
use super::tags::TAG_REPLY;
use crate::limits::MAX_REASON;

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

/// A posted request's number, to ask what became of it
/// ([`DynSegment::outcome`](crate::DynSegment::outcome)).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Ticket(pub(crate) u64);

/// What became of a posted write.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WriteOutcome {
    /// Sent; the owner has not answered yet.
    Pending,
    /// The owner applied it.
    Applied,
    /// The owner refused it: the variable may not be written from outside, or the program's
    /// `set` refused the value.
    Rejected,
    /// The program's policy does not let this process write.
    Refused,
    /// The owner did not take it (too many requests waiting, or it stopped first).
    Discarded,
    /// No answer can come any more (the connection to the owner is gone).
    Unknown,
}

impl WriteOutcome {
    /// What an answer with `code` means for the write.
    pub(crate) fn of(code: Code) -> WriteOutcome {
        match code {
            Code::Applied => WriteOutcome::Applied,
            Code::Rejected | Code::Forced => WriteOutcome::Rejected,
            Code::Refused => WriteOutcome::Refused,
            Code::Malformed | Code::Busy | Code::Stopped => WriteOutcome::Discarded,
        }
    }
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
}
