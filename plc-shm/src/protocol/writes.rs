//! Write requests, and forces, which carry their values the same way: encoded by a tool,
//! decoded by the owner with every length checked.

use super::decode_error::DecodeError;
use super::reader::Reader;
use super::tags::{TAG_FORCE, TAG_WRITE};
use crate::limits::MAX_WRITES;
use plc_core::write::Write;
use plc_core::{FixedString, Value};

/// A request: writes checked whole and applied in one cycle, all or none.
#[derive(Clone, Debug, PartialEq)]
pub struct WriteRequest {
    /// The writer's number for it, echoed in the reply.
    pub id: u64,
    /// The writes, in order.
    pub writes: Vec<Write>,
}

/// How many bytes a request (or force) of `writes` takes: at most [`MAX_MESSAGE`](crate::limits::MAX_MESSAGE) can be sent.
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

/// A request's bytes. The caller keeps to [`MAX_WRITES`] and [`MAX_MESSAGE`](crate::limits::MAX_MESSAGE).
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

/// The rest of a write or force request, after its tag.
pub(crate) fn decode_writes(r: &mut Reader<'_>) -> Result<WriteRequest, DecodeError> {
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
