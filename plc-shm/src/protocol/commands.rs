//! The messages a tool sends besides writes: forces, their release, traces and actions on
//! alarms. Decoded with
//! the same checked reader; [`decode`] reads any tool-to-owner message.

use super::alarm_actions::{AlarmRequest, decode_alarm};
use super::decode_error::DecodeError;
use super::reader::{Reader, start};
use super::tags::{TAG_ALARM, TAG_FORCE, TAG_RELEASE, TAG_TRACE, TAG_WRITE};
use super::writes::{WriteRequest, decode_writes};
use crate::limits::{MAX_TRACED, MAX_WRITES};

/// Release flag: put back the value from before the force.
const RESTORE: u8 = 1;
/// Release flag: every force, not the ones named.
const ALL: u8 = 2;

/// A message from a tool to the owner.
#[derive(Clone, Debug, PartialEq)]
pub enum Request {
    /// Writes, applied once.
    Write(WriteRequest),
    /// Values to hold at both of the cycle's boundaries until released.
    Force(WriteRequest),
    /// Forces to end.
    Release(Release),
    /// A trace to start on this connection.
    Trace(TraceRequest),
    /// An operator's action on alarms.
    Alarm(AlarmRequest),
}

impl Request {
    /// The request's id, echoed in its reply.
    pub fn id(&self) -> u64 {
        match self {
            Request::Write(w) | Request::Force(w) => w.id,
            Request::Release(r) => r.id,
            Request::Trace(t) => t.id,
            Request::Alarm(a) => a.id,
        }
    }
}

/// Forces to end: the values named, or all of them.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Release {
    /// The writer's number for it.
    pub id: u64,
    /// Put back each value as it was before its force; without it the program's next value
    /// stands.
    pub restore: bool,
    /// Every force (then `values` is empty).
    pub all: bool,
    /// (variable index, leaf) of each force to end.
    pub values: Vec<(usize, usize)>,
}

/// A trace: values recorded every `every`th cycle into a ring the tool reads.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TraceRequest {
    /// The writer's number for it.
    pub id: u64,
    /// Record every this many cycles (1: every cycle).
    pub every: u32,
    /// (variable index, leaf) of each value, in the order of a row's columns.
    pub values: Vec<(usize, usize)>,
}

/// 32 bits on the wire; an index beyond them (no declaration has one) becomes the largest,
/// which the owner refuses as no such variable.
fn wire(n: usize) -> [u8; 4] {
    u32::try_from(n).unwrap_or(u32::MAX).to_le_bytes()
}

fn encode_values(out: &mut Vec<u8>, values: &[(usize, usize)]) {
    out.extend_from_slice(&(values.len() as u16).to_le_bytes());
    for &(index, leaf) in values {
        out.extend_from_slice(&wire(index));
        out.extend_from_slice(&wire(leaf));
    }
}

/// A release's bytes. The caller keeps to [`MAX_WRITES`] values.
pub fn encode_release(release: &Release) -> Vec<u8> {
    let mut out = vec![TAG_RELEASE];
    out.extend_from_slice(&release.id.to_le_bytes());
    out.push((u8::from(release.restore) * RESTORE) | (u8::from(release.all) * ALL));
    encode_values(&mut out, &release.values);
    out
}

/// A trace's bytes. The caller keeps to [`MAX_TRACED`] values.
pub fn encode_trace(trace: &TraceRequest) -> Vec<u8> {
    let mut out = vec![TAG_TRACE];
    out.extend_from_slice(&trace.id.to_le_bytes());
    out.extend_from_slice(&trace.every.to_le_bytes());
    encode_values(&mut out, &trace.values);
    out
}

/// `count` (index, leaf) pairs, `count` checked against `min..=max` first.
fn decode_values(
    r: &mut Reader<'_>,
    what: &'static str,
    min: usize,
    max: usize,
) -> Result<Vec<(usize, usize)>, DecodeError> {
    let count = usize::from(r.u16("value count")?);
    if !(min..=max).contains(&count) {
        return Err(DecodeError::Count {
            what,
            count,
            min,
            max,
        });
    }
    // Bounded by `max`, whatever the message says.
    let mut values = Vec::with_capacity(count);
    for _ in 0..count {
        let index = r.u32("variable index")? as usize;
        let leaf = r.u32("element")? as usize;
        values.push((index, leaf));
    }
    Ok(values)
}

/// Decodes any message a tool sends.
pub fn decode(bytes: &[u8]) -> Result<Request, DecodeError> {
    let mut r = start(bytes)?;
    let tag = r.u8("tag")?;
    let request = match tag {
        TAG_WRITE => Request::Write(decode_writes(&mut r)?),
        TAG_FORCE => Request::Force(decode_writes(&mut r)?),
        TAG_RELEASE => {
            let id = r.u64("request id")?;
            let flags = r.u8("release flags")?;
            if flags & !(RESTORE | ALL) != 0 {
                return Err(DecodeError::Unknown {
                    what: "release flags",
                    byte: flags,
                });
            }
            let all = flags & ALL != 0;
            // All, and no values named; or some values named.
            let (min, max) = if all { (0, 0) } else { (1, MAX_WRITES) };
            let values = decode_values(&mut r, "the forces a release names", min, max)?;
            Request::Release(Release {
                id,
                restore: flags & RESTORE != 0,
                all,
                values,
            })
        }
        TAG_TRACE => {
            let id = r.u64("request id")?;
            let every = r.u32("trace period")?;
            if every == 0 {
                return Err(DecodeError::Count {
                    what: "the cycles between a trace's rows",
                    count: 0,
                    min: 1,
                    max: u32::MAX as usize,
                });
            }
            let values = decode_values(&mut r, "the values a trace records", 1, MAX_TRACED)?;
            Request::Trace(TraceRequest { id, every, values })
        }
        TAG_ALARM => Request::Alarm(decode_alarm(&mut r)?),
        byte => {
            return Err(DecodeError::Unknown {
                what: "unknown message tag",
                byte,
            });
        }
    };
    r.end()?;
    Ok(request)
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

#[cfg(test)]
mod tests {
    use super::super::writes::{encode_force, encode_request};
    use super::*;
    use proptest::prelude::*;

    fn encode(request: &Request) -> Vec<u8> {
        match request {
            Request::Write(w) => encode_request(w),
            Request::Force(w) => encode_force(w),
            Request::Release(r) => encode_release(r),
            Request::Trace(t) => encode_trace(t),
            Request::Alarm(a) => super::super::alarm_actions::encode_alarm(a),
        }
    }

    proptest! {
        /// Whatever bytes arrive with a command's tag, the decoder answers and what it accepts
        /// encodes back to the same bytes: one meaning per message.
        #[test]
        fn arbitrary_commands_decode_to_an_error_or_their_one_meaning(
            bytes in proptest::collection::vec(any::<u8>(), 0..1200),
            tag in 3u8..7,
        ) {
            let mut bytes = bytes;
            if let Some(b) = bytes.first_mut() {
                *b = tag;
            }
            if let Ok(request) = decode(&bytes) {
                prop_assert_eq!(encode(&request), bytes);
            }
        }

        /// Releases and traces round trip, and every truncation is refused.
        #[test]
        fn commands_round_trip_and_their_truncations_are_refused(
            id in any::<u64>(),
            every in 1u32..,
            values in proptest::collection::vec((any::<u32>(), any::<u32>()), 1..=MAX_TRACED),
            restore in any::<bool>(),
            cut in any::<proptest::sample::Index>(),
        ) {
            let values: Vec<(usize, usize)> =
                values.into_iter().map(|(i, l)| (i as usize, l as usize)).collect();
            let trace = Request::Trace(TraceRequest { id, every, values: values.clone() });
            let release = Request::Release(Release {
                id,
                restore,
                all: false,
                values: values[..values.len().min(MAX_WRITES)].to_vec(),
            });
            for request in [trace, release] {
                let bytes = encode(&request);
                prop_assert_eq!(decode(&bytes).unwrap(), request);
                prop_assert!(decode(&bytes[..cut.index(bytes.len())]).is_err());
            }
        }
    }

    #[test]
    fn a_release_of_all_names_nothing_and_a_trace_records_something() {
        let all = Release {
            id: 3,
            restore: true,
            all: true,
            values: vec![],
        };
        assert_eq!(
            decode(&encode_release(&all)).unwrap(),
            Request::Release(all.clone())
        );
        let mixed = Release {
            values: vec![(1, 0)],
            ..all
        };
        assert!(matches!(
            decode(&encode_release(&mixed)),
            Err(DecodeError::Count { count: 1, .. })
        ));
        let empty = TraceRequest {
            id: 1,
            every: 1,
            values: vec![],
        };
        assert!(decode(&encode_trace(&empty)).is_err());
        let zero = TraceRequest {
            every: 0,
            values: vec![(0, 0)],
            ..empty
        };
        let e = decode(&encode_trace(&zero)).unwrap_err().to_string();
        assert!(e.contains("not 0"), "{e}");
    }
}
