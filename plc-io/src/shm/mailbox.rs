//! The mailbox: a bounded multi-producer, single-consumer ring of write requests in the
//! segment (a Vyukov bounded queue). Each slot carries a sequence number that says whose turn
//! it is, so producers in other processes never block each other, a full ring is refused at
//! once, and a producer killed between claiming a slot and committing it is skipped by the
//! owner after a timeout instead of stalling the queue forever.

use super::bytes;
use super::layout::{Base, Offsets, SLOTS};
use plc_core::{FixedString, Value};
use std::sync::atomic::Ordering::{AcqRel, Acquire, Relaxed, Release};
use std::time::{Duration, Instant};

/// How long a claimed but uncommitted slot may block the queue before the owner skips it.
pub const RECLAIM_AFTER: Duration = Duration::from_millis(500);

/// A write request: variable index, element, value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Request {
    /// Index of the variable.
    pub index: usize,
    /// Element (row-major), 0 for a scalar.
    pub element: usize,
    /// The value, already checked against the variable by the writer.
    pub value: Value,
}

/// Why a request could not be posted.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PostError {
    /// Every slot holds a request the owner has not applied yet.
    Full,
    /// The owner skipped this request because it took too long to commit.
    Reclaimed,
}

/// Sets the ring up empty (owner, at creation).
pub fn init(base: &Base, off: &Offsets) {
    base.store(off.mb_head(), 0);
    base.store(off.mb_tail(), 0);
    base.store(off.mb_reclaimed(), 0);
    for i in 0..SLOTS {
        base.store(off.slot(i), i as u64);
    }
}

fn encode(value: &Value) -> (u32, u64, FixedString<255>) {
    match *value {
        Value::Bool(b) => (0, b as u64, FixedString::new()),
        Value::Int(i) => (1, i as u64, FixedString::new()),
        Value::UInt(u) => (2, u, FixedString::new()),
        Value::Real(r) => (3, r.to_bits(), FixedString::new()),
        Value::Text(t) => (4, t.len() as u64, t),
    }
}

fn decode(kind: u32, num: u64, text: &[u8]) -> Value {
    match kind {
        0 => Value::Bool(num != 0),
        1 => Value::Int(num as i64),
        2 => Value::UInt(num),
        3 => Value::Real(f64::from_bits(num)),
        _ => {
            let len = (num as usize).min(text.len());
            let s = std::str::from_utf8(&text[..len]).unwrap_or_default();
            Value::Text(FixedString::from_str_truncate(s))
        }
    }
}

/// Test hook: a producer that stops between claiming a slot and committing it (as if killed).
#[doc(hidden)]
pub static STOP_AFTER_CLAIM: std::sync::atomic::AtomicBool =
    std::sync::atomic::AtomicBool::new(false);

/// Posts a request (any process). Returns its ticket.
pub fn post(base: &Base, off: &Offsets, request: &Request) -> Result<u64, PostError> {
    let head = base.word(off.mb_head());
    let pos = loop {
        let pos = head.load(Acquire);
        let seq = base.word(off.slot(pos as usize)).load(Acquire);
        if seq == pos {
            if head
                .compare_exchange_weak(pos, pos + 1, AcqRel, Relaxed)
                .is_ok()
            {
                break pos;
            }
        } else if seq < pos {
            return Err(PostError::Full);
        } else {
            std::hint::spin_loop();
        }
    };
    let slot = off.slot(pos as usize);
    let (kind, num, text) = encode(&request.value);
    let w = |o: usize, v: u64| base.word(slot + o).store(v, Relaxed);
    w(8, (request.index as u64) | ((request.element as u64) << 32));
    w(16, kind as u64);
    w(24, num);
    bytes::store(base, slot + 32, text.as_bytes());
    if STOP_AFTER_CLAIM.load(Relaxed) {
        loop {
            std::thread::park();
        }
    }
    base.word(slot)
        .compare_exchange(pos, pos + 1, Release, Relaxed)
        .map(|_| pos)
        .map_err(|_| PostError::Reclaimed)
}

/// The owner's side: takes committed requests in ticket order.
#[derive(Debug, Default)]
pub struct Consumer {
    stuck_since: Option<(u64, Instant)>,
    /// Requests skipped because their producer never committed them.
    pub reclaimed: u64,
}

impl Consumer {
    /// Takes every committed request, in order, calling `apply` for each.
    pub fn drain(&mut self, base: &Base, off: &Offsets, mut apply: impl FnMut(Request)) -> usize {
        let mut n = 0;
        loop {
            let pos = base.load(off.mb_tail());
            let slot = off.slot(pos as usize);
            let seq_word = base.word(slot);
            let seq = seq_word.load(Acquire);
            if seq == pos + 1 {
                let r = |o: usize| base.word(slot + o).load(Relaxed);
                let (ie, kind, num) = (r(8), r(16), r(24));
                let mut text = [0u8; 255];
                bytes::load(base, slot + 32, &mut text);
                let request = Request {
                    index: (ie & 0xFFFF_FFFF) as usize,
                    element: (ie >> 32) as usize,
                    value: decode(kind as u32, num, &text),
                };
                seq_word.store(pos + SLOTS as u64, Release);
                base.store(off.mb_tail(), pos + 1);
                self.stuck_since = None;
                apply(request);
                n += 1;
            } else if seq == pos && base.load(off.mb_head()) > pos {
                // Claimed, not committed: a slow or dead producer.
                let since = match self.stuck_since {
                    Some((p, t)) if p == pos => t,
                    _ => {
                        self.stuck_since = Some((pos, Instant::now()));
                        break;
                    }
                };
                if since.elapsed() < RECLAIM_AFTER {
                    break;
                }
                if seq_word
                    .compare_exchange(pos, pos + SLOTS as u64, AcqRel, Relaxed)
                    .is_ok()
                {
                    base.store(off.mb_tail(), pos + 1);
                    base.word(off.mb_reclaimed()).fetch_add(1, Relaxed);
                    self.reclaimed += 1;
                }
                self.stuck_since = None;
            } else {
                break;
            }
        }
        n
    }
}
