//! An operator's action on alarms (acknowledge, reset, shelve, unshelve), tool to owner:
//!
//! ```text
//! 6u8  id u64  action u8 (1 acknowledge, 2 reset, 3 shelve, 4 unshelve)  flags u8 (1 all)
//! shelve for, ns i64 (> 0 for a shelve, 0 otherwise)
//! comment: len u8, then len bytes of UTF-8
//! on behalf of: len u8, then len bytes of UTF-8 (a user signed in elsewhere: OPC UA)
//! count u16 (1..=MAX_WRITES; 0 only with all), then count times: alarm u32
//! ```
//!
//! Alarms are named by their number in the descriptor's alarm list. Who may act is the write
//! policy's, as for writes.

use super::decode_error::DecodeError;
use super::reader::Reader;
use super::tags::TAG_ALARM;
use crate::limits::MAX_WRITES;

/// Flag: every alarm the action applies to, not the ones named.
const ALL: u8 = 1;

/// What an operator does to alarms.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AlarmAction {
    /// Acknowledge: the operator has seen it.
    Acknowledge,
    /// Reset a latched alarm whose condition has cleared.
    Reset,
    /// Shelve for this long, nanoseconds.
    Shelve {
        /// How long.
        for_ns: i64,
    },
    /// Take off the shelf.
    Unshelve,
}

impl AlarmAction {
    /// The verb tools and logs use.
    pub const fn verb(self) -> &'static str {
        match self {
            AlarmAction::Acknowledge => "acknowledge",
            AlarmAction::Reset => "reset",
            AlarmAction::Shelve { .. } => "shelve",
            AlarmAction::Unshelve => "unshelve",
        }
    }
}

/// An action on some alarms, or on every one it applies to.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct AlarmRequest {
    /// The tool's number for it.
    pub id: u64,
    /// What to do.
    pub action: AlarmAction,
    /// Every alarm the action applies to (then `alarms` is empty).
    pub all: bool,
    /// What the operator wrote with it (at most 255 bytes).
    pub comment: String,
    /// The user a tool acts for, signed in elsewhere (at most 255 bytes; empty: the tool's
    /// own user).
    pub on_behalf: String,
    /// The alarms' numbers.
    pub alarms: Vec<usize>,
}

/// The request's bytes. Texts are cut to 255 bytes (at a character's boundary); the caller
/// keeps to [`MAX_WRITES`] alarms.
pub fn encode_alarm(request: &AlarmRequest) -> Vec<u8> {
    let (code, for_ns) = match request.action {
        AlarmAction::Acknowledge => (1, 0),
        AlarmAction::Reset => (2, 0),
        AlarmAction::Shelve { for_ns } => (3, for_ns),
        AlarmAction::Unshelve => (4, 0),
    };
    let mut out = vec![TAG_ALARM];
    out.extend_from_slice(&request.id.to_le_bytes());
    out.push(code);
    out.push(u8::from(request.all) * ALL);
    out.extend_from_slice(&for_ns.to_le_bytes());
    for text in [&request.comment, &request.on_behalf] {
        let text = cut(text, 255);
        out.push(text.len() as u8);
        out.extend_from_slice(text.as_bytes());
    }
    out.extend_from_slice(&(request.alarms.len() as u16).to_le_bytes());
    for &alarm in &request.alarms {
        out.extend_from_slice(&u32::try_from(alarm).unwrap_or(u32::MAX).to_le_bytes());
    }
    out
}

/// `text` cut to at most `max` bytes at a character's boundary.
pub fn cut(text: &str, max: usize) -> &str {
    let mut end = text.len().min(max);
    while !text.is_char_boundary(end) {
        end -= 1;
    }
    &text[..end]
}

/// Decodes the request after its tag.
pub(crate) fn decode_alarm(r: &mut Reader<'_>) -> Result<AlarmRequest, DecodeError> {
    let id = r.u64("request id")?;
    let code = r.u8("alarm action")?;
    let flags = r.u8("alarm flags")?;
    if flags & !ALL != 0 {
        return Err(DecodeError::Unknown {
            what: "alarm flags",
            byte: flags,
        });
    }
    let for_ns = r.u64("shelve duration")? as i64;
    let action = match code {
        1 => AlarmAction::Acknowledge,
        2 => AlarmAction::Reset,
        3 => AlarmAction::Shelve { for_ns },
        4 => AlarmAction::Unshelve,
        byte => {
            return Err(DecodeError::Unknown {
                what: "alarm action",
                byte,
            });
        }
    };
    // One meaning per message: a duration only with a shelve, and a shelve only with one.
    if matches!(action, AlarmAction::Shelve { .. }) != (for_ns != 0) || for_ns < 0 {
        return Err(DecodeError::Count {
            what: "nanoseconds of a shelve (and none with another action)",
            count: usize::try_from(for_ns).unwrap_or(0),
            min: usize::from(code == 3),
            max: if code == 3 { i64::MAX as usize } else { 0 },
        });
    }
    let comment = text(r, "comment")?;
    let on_behalf = text(r, "user acted for")?;
    let all = flags & ALL != 0;
    let count = usize::from(r.u16("alarm count")?);
    let (min, max) = if all { (0, 0) } else { (1, MAX_WRITES) };
    if !(min..=max).contains(&count) {
        return Err(DecodeError::Count {
            what: "the alarms an action names",
            count,
            min,
            max,
        });
    }
    let mut alarms = Vec::with_capacity(count);
    for _ in 0..count {
        alarms.push(r.u32("alarm number")? as usize);
    }
    Ok(AlarmRequest {
        id,
        action,
        all,
        comment,
        on_behalf,
        alarms,
    })
}

fn text(r: &mut Reader<'_>, what: &'static str) -> Result<String, DecodeError> {
    let len = usize::from(r.u8(what)?);
    let text = r.utf8(len, what)?;
    if text.contains('\0') {
        return Err(DecodeError::Nul);
    }
    Ok(text.to_string())
}

#[cfg(test)]
mod tests {
    use super::super::commands::{Request, decode};
    use super::*;
    use proptest::prelude::*;

    proptest! {
        /// Whatever bytes arrive with the tag, the decoder answers, and what it accepts
        /// encodes back to the same bytes.
        #[test]
        fn arbitrary_alarm_requests_decode_to_an_error_or_their_one_meaning(
            bytes in proptest::collection::vec(any::<u8>(), 0..600),
        ) {
            let mut bytes = bytes;
            if let Some(b) = bytes.first_mut() {
                *b = TAG_ALARM;
            }
            if let Ok(Request::Alarm(a)) = decode(&bytes) {
                prop_assert_eq!(encode_alarm(&a), bytes);
            }
        }

        #[test]
        fn alarm_requests_round_trip_and_their_truncations_are_refused(
            id in any::<u64>(),
            alarms in proptest::collection::vec(0u32..100_000, 1..50),
            comment in "\\PC{0,80}",
            shelve in 1i64..i64::MAX,
            cut_at in any::<proptest::sample::Index>(),
        ) {
            let alarms: Vec<usize> = alarms.into_iter().map(|a| a as usize).collect();
            for action in [
                AlarmAction::Acknowledge,
                AlarmAction::Reset,
                AlarmAction::Shelve { for_ns: shelve },
                AlarmAction::Unshelve,
            ] {
                let request = AlarmRequest {
                    id,
                    action,
                    all: false,
                    comment: cut(&comment, 255).to_string(),
                    on_behalf: "anna".into(),
                    alarms: alarms.clone(),
                };
                let bytes = encode_alarm(&request);
                prop_assert_eq!(decode(&bytes).unwrap(), Request::Alarm(request));
                prop_assert!(decode(&bytes[..cut_at.index(bytes.len())]).is_err());
            }
        }
    }

    #[test]
    fn all_names_no_alarm_and_only_a_shelve_has_a_duration() {
        let all = AlarmRequest {
            id: 1,
            action: AlarmAction::Acknowledge,
            all: true,
            comment: String::new(),
            on_behalf: String::new(),
            alarms: vec![],
        };
        assert_eq!(
            decode(&encode_alarm(&all)).unwrap(),
            Request::Alarm(all.clone())
        );
        let named_too = AlarmRequest {
            alarms: vec![0],
            ..all.clone()
        };
        assert!(decode(&encode_alarm(&named_too)).is_err());
        let timeless = AlarmRequest {
            action: AlarmAction::Shelve { for_ns: 0 },
            ..all.clone()
        };
        assert!(decode(&encode_alarm(&timeless)).is_err());
        let mut ack_with_time = encode_alarm(&all);
        ack_with_time[11] = 1;
        assert!(decode(&ack_with_time).is_err());
        assert_eq!(cut("ääää", 3), "ä");
    }
}
