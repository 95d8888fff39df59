//! Round trips and hostile bytes across the protocol's messages.

use super::tags::TAG_WRITE;
use super::*;
use plc_core::write::Write;
use plc_core::{FixedString, Value};
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
