//! Where everything is in a segment.
//!
//! ```text
//! 0     header   magic, format version, layout hash, image size, generation, seqlock
//!                sequence, descriptor offset and length            (8 x u64)
//! 64    status   owner pid, state, period, cycle count, cycle times, overruns, bus state
//!                and flags, heartbeat, write counters, retain failures, the cycle's
//!                wall-clock time                                   (16 x u64)
//! 192   image    T::Image, padded to 8 bytes
//! ...   writes   counters of writes from outside: refused by the policy, malformed,
//!                not taken (too many waiting), waiting now         (4 x u64)
//! ...   forces   sequence (odd while the owner changes them), count, then per force:
//!                variable index, leaf, uid, since (UTC ns)         (2 + 256 x 4 x u64)
//! ...   clocks   the bus's distributed clocks: SYNC0 period (0: none), largest system
//!                time difference (u64::MAX: not read), cycle's offset after SYNC0, in ns
//!                                                                  (3 x u64)
//! ...   alarms   active now, waiting for an acknowledgement             (2 x u64)
//! ...   descriptor, JSON
//! ...   alarm states, 8-aligned: sequence, then per alarm in the descriptor's order its
//!       state and level, since when, shelved until             (1 + alarms x 3 x u64)
//! ```
//! Only the owner writes any of it (tools map it read-only, and the memory is sealed).
//! Every shared word is a naturally aligned `u64` used only through `AtomicU64`
//! ([`Base`](crate::sys::base::Base)).

use crate::limits::MAX_FORCES;

/// "PLCVARS2", little endian (the segment whose writes travel over its socket).
pub const MAGIC: u64 = u64::from_le_bytes(*b"PLCVARS2");
/// Written over the magic when the owner stops, before it closes its socket: readers still
/// mapping it learn that nobody publishes into it or applies writes any more, even after a
/// new owner has created a new segment of the same name.
pub const MAGIC_CLOSED: u64 = u64::from_le_bytes(*b"PLCSTOP!");

pub const H_MAGIC: usize = 0;
pub const H_VERSION: usize = 8;
pub const H_LAYOUT_HASH: usize = 16;
pub const H_IMAGE_SIZE: usize = 24;
pub const H_GENERATION: usize = 32;
pub const H_SEQ: usize = 40;
pub const H_DESC_OFFSET: usize = 48;
pub const H_DESC_LEN: usize = 56;

pub const STATUS: usize = 64;
pub const S_PID: usize = STATUS;
pub const S_STATE: usize = STATUS + 8;
pub const S_PERIOD_NS: usize = STATUS + 16;
pub const S_CYCLES: usize = STATUS + 24;
pub const S_LAST_NS: usize = STATUS + 32;
pub const S_MIN_NS: usize = STATUS + 40;
pub const S_MAX_NS: usize = STATUS + 48;
pub const S_MEAN_NS: usize = STATUS + 56;
pub const S_OVERRUNS: usize = STATUS + 64;
pub const S_BUS_STATE: usize = STATUS + 72;
pub const S_BUS_FLAGS: usize = STATUS + 80;
pub const S_HEARTBEAT_NS: usize = STATUS + 88;
pub const S_WRITES_APPLIED: usize = STATUS + 96;
pub const S_WRITES_REJECTED: usize = STATUS + 104;
pub const S_RETAIN_FAILED: usize = STATUS + 112;
pub const S_CYCLE_UTC_NS: usize = STATUS + 120;

pub const IMAGE: usize = 192;

/// Bytes of the write counters after the image.
const WRITES: usize = 32;
/// Words of one force in the table.
pub const FORCE_WORDS: usize = 4;
/// Bytes of the table of forces after the write counters.
const FORCES: usize = 8 * (2 + MAX_FORCES * FORCE_WORDS);
/// Bytes of the distributed clocks' words after the table of forces.
const CLOCKS: usize = 8 * 3;
/// Bytes of the alarm counts after the distributed clocks.
const ALARMS: usize = 8 * 2;

pub const fn pad8(n: usize) -> usize {
    n.div_ceil(8) * 8
}

/// Offsets that depend on the image size.
#[derive(Clone, Copy, Debug)]
pub struct Offsets {
    pub image_size: usize,
    pub writes: usize,
    pub forces: usize,
    pub clocks: usize,
    pub alarms: usize,
    pub descriptor: usize,
}

impl Offsets {
    /// The offsets for an image of `image_size` bytes, or `None` if they do not fit in the
    /// address space (a damaged header read by a reader).
    pub const fn checked(image_size: usize) -> Option<Self> {
        // `new` adds a fixed amount to the padded image size: check that sum first.
        match image_size.checked_next_multiple_of(8) {
            Some(padded) if padded <= usize::MAX - (IMAGE + WRITES + FORCES + CLOCKS + ALARMS) => {
                Some(Self::new(image_size))
            }
            _ => None,
        }
    }

    /// The offsets for an image of `image_size` bytes (a compiled type's own image).
    pub const fn new(image_size: usize) -> Self {
        let writes = IMAGE + pad8(image_size);
        let forces = writes + WRITES;
        let clocks = forces + FORCES;
        let alarms = clocks + CLOCKS;
        Offsets {
            image_size,
            writes,
            forces,
            clocks,
            alarms,
            descriptor: alarms + ALARMS,
        }
    }

    pub const fn w_refused(&self) -> usize {
        self.writes
    }
    pub const fn w_malformed(&self) -> usize {
        self.writes + 8
    }
    pub const fn w_busy(&self) -> usize {
        self.writes + 16
    }
    pub const fn w_pending(&self) -> usize {
        self.writes + 24
    }
    /// The forces table's sequence word.
    pub const fn f_seq(&self) -> usize {
        self.forces
    }
    /// How many forces are held.
    pub const fn f_count(&self) -> usize {
        self.forces + 8
    }
    /// Word `word` of force `n`.
    pub const fn f_entry(&self, n: usize, word: usize) -> usize {
        self.forces + 16 + 8 * (n * FORCE_WORDS + word)
    }
    /// Word `word` of the distributed clocks (period, difference, offset).
    pub const fn c_word(&self, word: usize) -> usize {
        self.clocks + 8 * word
    }
    /// Alarms active now.
    pub const fn a_active(&self) -> usize {
        self.alarms
    }
    /// Alarms waiting for an acknowledgement.
    pub const fn a_unacknowledged(&self) -> usize {
        self.alarms + 8
    }
}
