//! The exchange and the descriptions against scripted devices, hostile ones included.

use super::*;
use async_io::block_on;
use std::collections::VecDeque;

/// A device that answers from a script.
struct Scripted {
    capacity: usize,
    sent: Vec<Vec<u8>>,
    replies: VecDeque<Vec<u8>>,
    /// Answer this frame for ever once the script is through.
    endless: Option<Vec<u8>>,
}

impl Scripted {
    fn new(replies: Vec<Vec<u8>>) -> Self {
        Scripted {
            capacity: 128,
            sent: Vec::new(),
            replies: replies.into(),
            endless: None,
        }
    }
}

impl Mailbox for Scripted {
    fn capacity(&self) -> usize {
        self.capacity
    }
    async fn send(&mut self, frame: &[u8]) -> Result<(), String> {
        self.sent.push(frame.to_vec());
        Ok(())
    }
    async fn receive(&mut self) -> Result<Vec<u8>, String> {
        match self.replies.pop_front().or_else(|| self.endless.clone()) {
            Some(mut r) => {
                r.resize(self.capacity.max(r.len()), 0);
                Ok(r)
            }
            None => Err("no answer within 1000 ms".into()),
        }
    }
}

/// A CoE SDO information frame: mailbox header (stated length `stated`, or the real one),
/// CoE header, info header, data.
fn frame(op: u8, left: u16, data: &[u8], stated: Option<u16>) -> Vec<u8> {
    let len = stated.unwrap_or((6 + data.len()) as u16);
    let mut f = len.to_le_bytes().to_vec();
    f.extend_from_slice(&[0, 0, 0, 0x13]);
    f.extend_from_slice(&(8u16 << 12).to_le_bytes());
    f.extend_from_slice(&[op, 0]);
    f.extend_from_slice(&left.to_le_bytes());
    f.extend_from_slice(data);
    f
}

fn entry(index: u16, sub: u8, ty: u16, bits: u16, name: &str) -> Vec<u8> {
    let mut d = index.to_le_bytes().to_vec();
    d.extend_from_slice(&[sub, 0]);
    d.extend_from_slice(&ty.to_le_bytes());
    d.extend_from_slice(&bits.to_le_bytes());
    d.extend_from_slice(&0x0087u16.to_le_bytes());
    d.extend_from_slice(name.as_bytes());
    d
}

#[test]
fn an_entry_description_gives_name_type_and_bits_and_the_counter_starts_at_0() {
    let mut m = Scripted::new(vec![frame(
        0x06,
        0,
        &entry(0x6000, 0x11, 3, 16, "Value"),
        None,
    )]);
    let mut c = Counter::default();
    let d = block_on(describe_entry(&mut m, &mut c, 0x6000, 0x11)).unwrap();
    assert_eq!(
        d,
        Description {
            name: "Value".into(),
            data_type: 3,
            bits: 16
        }
    );
    let sent = &m.sent[0];
    assert_eq!(sent[..6], [10, 0, 0, 0, 0, 0x03], "CoE, counter 0");
    assert_eq!(sent[6..], [0x00, 0x80, 0x05, 0, 0, 0, 0x00, 0x60, 0x11, 0]);
    assert_eq!((c.next(), c.next()), (1, 2));
}

#[test]
fn counters_after_the_first_cycle_through_1_to_7() {
    let mut c = Counter::default();
    let got: Vec<u8> = (0..10).map(|_| c.next()).collect();
    assert_eq!(got, [0, 1, 2, 3, 4, 5, 6, 7, 1, 2]);
}

#[test]
fn an_entry_without_a_name_takes_its_objects_name_and_fragments_are_joined() {
    let whole = entry(0x6040, 0, 6, 16, "");
    let mut object = 0x6040u16.to_le_bytes().to_vec();
    object.extend_from_slice(&[6, 0, 0, 7]);
    object.extend_from_slice(b"Controlword\0\0");
    let mut m = Scripted::new(vec![
        frame(0x86, 1, &whole[..5], None),
        frame(0x06, 0, &whole[5..], None),
        frame(0x04, 0, &object, None),
    ]);
    let d = block_on(describe_entry(&mut m, &mut Counter::default(), 0x6040, 0)).unwrap();
    assert_eq!((d.name.as_str(), d.data_type), ("Controlword", 6));
    assert_eq!(m.sent.len(), 2);
    assert_eq!(m.sent[1][5] >> 4, 1, "the second request counts on");
}

#[test]
fn an_sdo_info_error_fails_the_entry_only() {
    let mut m = Scripted::new(vec![frame(0x07, 0, &0x0602_0000u32.to_le_bytes(), None)]);
    let err = block_on(describe_entry(&mut m, &mut Counter::default(), 0x6000, 1));
    assert_eq!(
        err,
        Err(Failure::Entry(
            "SDO information error, abort code 0x06020000".into()
        ))
    );
}

#[test]
fn hostile_answers_fail_the_device_without_hanging() {
    let ask = |m: &mut Scripted| block_on(describe_entry(m, &mut Counter::default(), 0x6000, 0x11));
    let device = |r: Result<Description, Failure>| match r {
        Err(Failure::Device(why)) => why,
        other => panic!("{other:?}"),
    };
    // A length beyond the mailbox.
    let mut m = Scripted::new(vec![frame(0x06, 0, &[], Some(500))]);
    assert_eq!(
        device(ask(&mut m)),
        "an answer states 500 bytes, more than the 122 its mailbox holds"
    );
    // Endless fragments.
    let mut m = Scripted::new(Vec::new());
    m.endless = Some(frame(0x86, 3, &[0; 8], None));
    let why = device(ask(&mut m));
    assert_eq!(why, "a fragment says 3 more follow after one that said 3");
    let mut m = Scripted::new(
        (0..100)
            .map(|i| frame(0x86, 1000 - i, &[0; 8], None))
            .collect(),
    );
    assert_eq!(device(ask(&mut m)), "an answer in more than 16 fragments");
    // An answer about another object, a short one, no answer, a mailbox error reply.
    let mut m = Scripted::new(vec![frame(
        0x06,
        0,
        &entry(0x6010, 0x11, 3, 16, "Value"),
        None,
    )]);
    assert_eq!(
        device(ask(&mut m)),
        "asked for object 0x6000:11, the device described 0x6010:11"
    );
    let mut m = Scripted::new(vec![frame(0x06, 0, &[0, 0x60], None)]);
    assert!(device(ask(&mut m)).contains("shorter than its 10-byte head"));
    let mut m = Scripted::new(Vec::new());
    assert_eq!(device(ask(&mut m)), "no answer within 1000 ms");
    let mut m = Scripted::new(vec![vec![4, 0, 0, 0, 0, 0x10, 1, 0, 2, 0]]);
    assert!(device(ask(&mut m)).starts_with("mailbox error 0x0002"));
    // Any bytes at all: an error or a description, never a panic.
    for len in 0..40u8 {
        let garbage: Vec<u8> = (0..len).map(|i| i.wrapping_mul(37) ^ len).collect();
        let _ = ask(&mut Scripted::new(vec![garbage]));
    }
}

#[test]
fn a_name_longer_than_the_limit_is_not_used_and_odd_bytes_become_question_marks() {
    let long = "x".repeat(MAX_NAME + 1);
    let mut m = Scripted::new(vec![frame(0x06, 0, &entry(0x6000, 1, 1, 1, &long), None)]);
    m.capacity = 1024;
    let r = block_on(describe_entry(&mut m, &mut Counter::default(), 0x6000, 1));
    assert!(matches!(r, Err(Failure::Entry(_))), "{r:?}");
    assert_eq!(text(b"Wert \xb5V\0\0", "x"), Ok("Wert ?V".to_string()));
}
