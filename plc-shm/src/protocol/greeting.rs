//! The owner's greeting, sent with the segment's memory file to every tool it admits: the
//! protocol's version and whether the tool may write.

use super::decode_error::DecodeError;
use super::reader::start;

/// Protocol version, in the greeting: a tool and an owner of another version refuse each other.
/// Version 2 added forces and traces (and the segment's table of forces).
pub const VERSION: u16 = 2;
/// The greeting's first bytes.
const GREETING_MAGIC: &[u8; 4] = b"PLCW";

/// The owner's greeting.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Greeting {
    /// The protocol version.
    pub version: u16,
    /// Whether the policy lets this connection's process write.
    pub may_write: bool,
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn greetings_round_trip() {
        for may_write in [false, true] {
            let g = decode_greeting(&encode_greeting(may_write)).unwrap();
            assert_eq!((g.version, g.may_write), (VERSION, may_write));
        }
    }
}
