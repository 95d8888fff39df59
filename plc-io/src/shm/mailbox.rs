//! The mailbox: a bounded multi-producer, single-consumer ring of write requests in the
//! segment (a Vyukov bounded queue). Each slot carries a sequence number that says whose turn
//! it is, so producers in other processes never block each other, a full ring is refused at
//! once, and a producer killed between claiming a slot and committing it is skipped by the
//! owner after a timeout instead of stalling the queue forever.
//!
//! Skipping a slot hands it to the producer one lap later while the skipped producer may still
//! be alive (stopped, swapped out) and store into it when it resumes. So every request carries
//! a checksum over its ticket and payload, written last and verified by the owner: a request
//! mixed from two producers, or left there by the skipped one, is discarded and counted, never
//! applied. After taking a request the owner leaves its outcome in the slot, tagged with the
//! ticket, where the producer can read it until the slot is reused.
//!
//! Slot: `0` sequence, `8` index | element << 32 (the outcome once taken), `16` kind |
//! checksum << 8, `24` number, `32` text (255 bytes, zero padded).

use super::bytes;
use super::layout::{Base, Offsets, SLOTS};
use plc_core::{FixedString, SetError, Value};
use std::fmt;
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
    /// The ring's shared words do not fit together (another process wrote over them).
    Damaged,
}

/// A posted request's place in the queue, to ask what became of it
/// ([`DynSegment::outcome`](super::DynSegment::outcome)).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Ticket(pub(crate) u64);

/// What became of a posted request.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// In the mailbox; the owner has not taken it yet.
    Pending,
    /// The owner applied it.
    Applied,
    /// The owner refused it: the variable may not be written from outside, or the program's
    /// `set` refused the value.
    Rejected,
    /// The owner found the request damaged (a skipped writer stored into its slot late) and
    /// dropped it.
    Discarded,
    /// The owner took it, but the slot has been reused since: the outcome is no longer known.
    Unknown,
}

/// Why the owner refused a request that reached it. The owner does not trust the mailbox: any
/// process that can map the segment can post anything.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rejection {
    /// The variable may not be written from outside.
    NotWritable {
        /// The variable.
        variable: &'static str,
        /// Why: read-only, input or status.
        reason: &'static str,
    },
    /// The program's [`GlobalMemory::set`](plc_core::GlobalMemory::set) refused it (unknown
    /// index, element out of range, value that does not fit).
    Set(SetError),
}

impl fmt::Display for Rejection {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Rejection::NotWritable { variable, reason } => {
                write!(f, "`{variable}` cannot be written: {reason}")
            }
            Rejection::Set(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for Rejection {}

/// Sets the ring up empty (owner, at creation).
pub fn init(base: &Base, off: &Offsets) {
    base.store(off.mb_head(), 0);
    base.store(off.mb_tail(), 0);
    base.store(off.mb_reclaimed(), 0);
    base.store(off.mb_discarded(), 0);
    for i in 0..SLOTS {
        base.store(off.slot(i), i as u64);
    }
}

/// Requests in the ring: claimed by a producer and not yet taken by the owner.
pub fn pending(base: &Base, off: &Offsets) -> u64 {
    // Tail first: both only grow and the head is never behind the tail, so a head read later
    // is at least this tail.
    let tail = base.load(off.mb_tail());
    base.load(off.mb_head()).saturating_sub(tail)
}

/// Free slots just now (other producers may take them at any moment).
pub fn free(base: &Base, off: &Offsets) -> usize {
    SLOTS.saturating_sub(usize::try_from(pending(base, off)).unwrap_or(SLOTS))
}

const TEXT: usize = 255;

fn encode(value: &Value) -> (u64, u64, [u8; TEXT]) {
    let mut text = [0u8; TEXT];
    let (kind, num) = match *value {
        Value::Bool(b) => (0, b as u64),
        Value::Int(i) => (1, i as u64),
        Value::UInt(u) => (2, u),
        Value::Real(r) => (3, r.to_bits()),
        Value::Text(t) => {
            let s = t.as_str().as_bytes();
            text[..s.len()].copy_from_slice(s);
            (4, s.len() as u64)
        }
        Value::Time(t) => (5, t.as_nanos() as u64),
    };
    (kind, num, text)
}

fn decode(kind: u64, num: u64, text: &[u8]) -> Value {
    match kind {
        0 => Value::Bool(num != 0),
        1 => Value::Int(num as i64),
        2 => Value::UInt(num),
        3 => Value::Real(f64::from_bits(num)),
        5 => Value::Time(plc_core::Time::from_nanos(num as i64)),
        _ => {
            let len = usize::try_from(num).map_or(text.len(), |n| n.min(text.len()));
            let s = match std::str::from_utf8(&text[..len]) {
                Ok(s) => s,
                Err(e) => std::str::from_utf8(&text[..e.valid_up_to()]).unwrap_or_default(),
            };
            Value::Text(FixedString::from_str_truncate(s))
        }
    }
}

/// FNV-1a 64 over the ticket and every payload byte, folded to the 56 bits the kind word has
/// room for. It detects accidents (a late producer's stores), not forgeries: the owner checks
/// what a request may do separately.
fn checksum(ticket: u64, index_element: u64, kind: u64, num: u64, text: &[u8]) -> u64 {
    let words = [ticket, index_element, kind, num];
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in words
        .iter()
        .flat_map(|w| w.to_le_bytes())
        .chain(text.iter().copied())
    {
        h = (h ^ b as u64).wrapping_mul(0x0000_0100_0000_01b3);
    }
    h >> 8
}

/// How long a producer tries to claim a slot before it takes the ring's words to be damaged.
/// Legitimate contention resolves in microseconds; words that another process wrote over
/// (a slot sequence ahead of the head that never catches up) would make it spin for ever.
const CLAIM_PATIENCE: Duration = Duration::from_millis(200);

/// Posts a request (any process). Returns its ticket.
pub fn post(base: &Base, off: &Offsets, request: &Request) -> Result<Ticket, PostError> {
    let head = base.word(off.mb_head());
    let mut deadline = None;
    let mut spins = 0u32;
    let pos = loop {
        let pos = head.load(Acquire);
        let seq = base.word(off.slot(pos as usize)).load(Acquire);
        let next = pos.checked_add(1).ok_or(PostError::Damaged)?;
        if seq == pos {
            if head
                .compare_exchange_weak(pos, next, AcqRel, Relaxed)
                .is_ok()
            {
                break pos;
            }
        } else if seq < pos {
            return Err(PostError::Full);
        }
        // Another producer moved the head since we read it, or the words are damaged: bounded.
        spins += 1;
        if spins.is_multiple_of(64) {
            let now = Instant::now();
            if now > *deadline.get_or_insert(now + CLAIM_PATIENCE) {
                return Err(PostError::Damaged);
            }
            std::thread::yield_now();
        } else {
            std::hint::spin_loop();
        }
    };
    #[cfg(feature = "fault-injection")]
    hooks::after_claim();
    let slot = off.slot(pos as usize);
    let (kind, num, text) = encode(&request.value);
    let index_element = (request.index as u64) | ((request.element as u64) << 32);
    let sum = checksum(pos, index_element, kind, num, &text);
    let w = |o: usize, v: u64| base.word(slot + o).store(v, Relaxed);
    w(8, index_element);
    w(24, num);
    bytes::store(base, slot + 32, &text);
    w(16, kind | (sum << 8));
    #[cfg(feature = "fault-injection")]
    hooks::before_commit();
    base.word(slot)
        .compare_exchange(pos, pos.wrapping_add(1), Release, Relaxed)
        .map(|_| Ticket(pos))
        .map_err(|_| PostError::Reclaimed)
}

/// Tag of an outcome word: producers' index | element words never have the top bit set
/// (indices and elements are far below 2^31).
const OUTCOME_TAG: u64 = 1 << 63;

fn outcome_word(ticket: u64, outcome: Outcome) -> u64 {
    let code = match outcome {
        Outcome::Applied => 0,
        Outcome::Rejected => 1,
        _ => 2,
    };
    OUTCOME_TAG | ((ticket << 2) & !OUTCOME_TAG) | code
}

/// What became of the request with `ticket` (any process).
pub fn outcome(base: &Base, off: &Offsets, ticket: Ticket) -> Outcome {
    let pos = ticket.0;
    let slot = off.slot(pos as usize);
    if base.word(slot).load(Acquire) <= pos.saturating_add(1) {
        return Outcome::Pending;
    }
    let w = base.word(slot + 8).load(Relaxed);
    if w & !3 != outcome_word(pos, Outcome::Applied) {
        return Outcome::Unknown;
    }
    match w & 3 {
        0 => Outcome::Applied,
        1 => Outcome::Rejected,
        _ => Outcome::Discarded,
    }
}

/// The owner's side: takes committed requests in ticket order.
///
/// Its position and counters live in its own memory: the shared words are written from them
/// for tools and never read back, so another process cannot steer the owner through them.
#[derive(Debug, Default)]
pub struct Consumer {
    /// The next ticket to take.
    tail: u64,
    stuck_since: Option<(u64, Instant)>,
    /// Requests applied.
    pub(crate) applied: u64,
    /// Requests refused.
    pub(crate) rejected: u64,
    /// Requests skipped because their producer never committed them.
    pub reclaimed: u64,
    /// Requests dropped because their checksum did not match.
    pub discarded: u64,
}

impl Consumer {
    /// Takes every committed request, in order (at most one ring's worth per call), calling
    /// `apply` for each intact one; `apply` says whether it was applied. Returns how many were
    /// handed to `apply`.
    pub fn drain(
        &mut self,
        base: &Base,
        off: &Offsets,
        mut apply: impl FnMut(Request) -> bool,
    ) -> usize {
        let mut n = 0;
        for _ in 0..SLOTS {
            let pos = self.tail;
            let slot = off.slot(pos as usize);
            let seq_word = base.word(slot);
            let seq = seq_word.load(Acquire);
            if seq == pos.wrapping_add(1) {
                let r = |o: usize| base.word(slot + o).load(Relaxed);
                let (index_element, kind_sum, num) = (r(8), r(16), r(24));
                let mut text = [0u8; TEXT];
                bytes::load(base, slot + 32, &mut text);
                let kind = kind_sum & 0xFF;
                let outcome = if kind_sum >> 8 == checksum(pos, index_element, kind, num, &text) {
                    n += 1;
                    let request = Request {
                        index: (index_element & 0xFFFF_FFFF) as usize,
                        element: (index_element >> 32) as usize,
                        value: decode(kind, num, &text),
                    };
                    if apply(request) {
                        Outcome::Applied
                    } else {
                        Outcome::Rejected
                    }
                } else {
                    self.discarded = self.discarded.wrapping_add(1);
                    base.store(off.mb_discarded(), self.discarded);
                    Outcome::Discarded
                };
                // Before the slot is released, so the next producer's payload overwrites the
                // outcome and never the other way round.
                base.word(slot + 8)
                    .store(outcome_word(pos, outcome), Relaxed);
                seq_word.store(pos.wrapping_add(SLOTS as u64), Release);
                self.advance(base, off);
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
                    .compare_exchange(pos, pos.wrapping_add(SLOTS as u64), AcqRel, Relaxed)
                    .is_ok()
                {
                    self.reclaimed = self.reclaimed.wrapping_add(1);
                    base.store(off.mb_reclaimed(), self.reclaimed);
                    self.advance(base, off);
                }
                self.stuck_since = None;
            } else {
                break;
            }
        }
        n
    }

    /// Starts over on a new, empty ring (the segment was replaced); the counts go on.
    pub(crate) fn restart(&mut self, base: &Base, off: &Offsets) {
        self.tail = 0;
        self.stuck_since = None;
        init(base, off);
        base.store(off.mb_reclaimed(), self.reclaimed);
        base.store(off.mb_discarded(), self.discarded);
    }

    /// Writes the ring's tail and counters again from the owner's memory, and starts the ring
    /// over, empty, at the owner's position if its words no longer fit together: the head
    /// within one lap of the tail, and every slot of that lap free or claimed (its sequence the
    /// position or one more). Anything else is another process's doing, and would make
    /// producers give up for ever.
    pub(crate) fn repair(&mut self, base: &Base, off: &Offsets) {
        let tail = self.tail;
        base.store(off.mb_tail(), tail);
        base.store(off.mb_reclaimed(), self.reclaimed);
        base.store(off.mb_discarded(), self.discarded);
        let lap = SLOTS as u64;
        let head = base.load(off.mb_head());
        let head_fits = head >= tail && head - tail <= lap;
        let slots_fit = (0..lap).all(|i| {
            let pos = tail.wrapping_add(i);
            let seq = base.load(off.slot(pos as usize));
            seq == pos || seq == pos.wrapping_add(1)
        });
        if !(head_fits && slots_fit) {
            base.store(off.mb_head(), tail);
            for i in 0..lap {
                let pos = tail.wrapping_add(i);
                base.store(off.slot(pos as usize), pos);
            }
            self.stuck_since = None;
        }
    }

    /// Moves past the slot just taken, and tells the producers.
    fn advance(&mut self, base: &Base, off: &Offsets) {
        self.tail = self.tail.wrapping_add(1);
        base.store(off.mb_tail(), self.tail);
        self.stuck_since = None;
    }
}

/// Test hooks (feature `fault-injection`, enabled by this crate's own tests only): a producer
/// that stops at a chosen point, as a killed, stopped or swapped-out process would.
#[cfg(feature = "fault-injection")]
#[doc(hidden)]
pub mod hooks {
    use std::cell::RefCell;
    use std::sync::atomic::{AtomicBool, Ordering::Relaxed};

    /// Producers of this process stop for ever after storing the payload, before committing.
    pub static STOP_AFTER_CLAIM: AtomicBool = AtomicBool::new(false);

    type Hook = Box<dyn FnOnce()>;

    thread_local! {
        static AFTER_CLAIM: RefCell<Option<Hook>> = const { RefCell::new(None) };
    }

    /// The next post on this thread calls `f` after claiming its slot, before storing into it.
    pub fn on_next_claim(f: impl FnOnce() + 'static) {
        AFTER_CLAIM.with(|h| *h.borrow_mut() = Some(Box::new(f)));
    }

    pub(super) fn after_claim() {
        if let Some(f) = AFTER_CLAIM.with(|h| h.borrow_mut().take()) {
            f();
        }
    }

    pub(super) fn before_commit() {
        if STOP_AFTER_CLAIM.load(Relaxed) {
            loop {
                std::thread::park();
            }
        }
    }
}

#[cfg(feature = "fault-injection")]
#[doc(hidden)]
pub use hooks::STOP_AFTER_CLAIM;
