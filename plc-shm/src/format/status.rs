//! The status block: what the owner reports about its cycle, and the one owner state tools show.

use super::bus_clocks::BusClocks;
use super::bus_state::BusState;
use super::cycle_stats::CycleStats;
use super::io_status::IoStatus;
use super::layout::*;
use crate::sys::base::Base;
use crate::sys::clock::now_ns;
use std::fmt;
use std::time::Duration;

/// The owner's own account of itself.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RunState {
    /// Created, first cycle not done.
    Starting = 0,
    /// Cycling.
    Running = 1,
    /// The program failed (a panic in its cycle); outputs were zeroed.
    Faulted = 2,
    /// Stopped cleanly.
    Stopped = 3,
}

impl RunState {
    fn from_code(c: u64) -> RunState {
        match c {
            1 => RunState::Running,
            2 => RunState::Faulted,
            3 => RunState::Stopped,
            _ => RunState::Starting,
        }
    }
}

/// The state tools show: the owner's account checked against its lock and heartbeat.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OwnerState {
    /// Alive and cycling.
    Running,
    /// Alive, but its heartbeat has not advanced for a while.
    Stalled,
    /// Alive, and reports a fault.
    Faulted,
    /// Alive, and reports it stopped.
    Stopped,
    /// No live process holds the segment.
    Gone,
}

impl OwnerState {
    /// Lower-case name.
    pub fn name(self) -> &'static str {
        match self {
            OwnerState::Running => "running",
            OwnerState::Stalled => "stalled",
            OwnerState::Faulted => "faulted",
            OwnerState::Stopped => "stopped",
            OwnerState::Gone => "gone",
        }
    }
}

impl fmt::Display for OwnerState {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(self.name())
    }
}

/// Bus flag: the bus is faulty.
pub const BUS_FAULT: u64 = 1;
/// Bus flag: this cycle's inputs are valid.
pub const INPUTS_VALID: u64 = 2;

/// A snapshot of the status block.
#[derive(Clone, Debug, PartialEq)]
pub struct Status {
    /// Owner process id.
    pub pid: u64,
    /// The owner's own account.
    pub run_state: RunState,
    /// Cycles done.
    pub cycle_count: u64,
    /// The period and the cycle times, as the owner's program sees them.
    pub stats: CycleStats,
    /// The bus state ([`BusState::NoBus`] without a bus).
    pub bus_state: BusState,
    /// The bus is faulty.
    pub bus_fault: bool,
    /// This cycle's inputs are valid.
    pub inputs_valid: bool,
    /// The bus's distributed clocks, on a bus that runs them (`None` otherwise). The three
    /// words are read one by one, not under the image's seqlock: the period is the one set up
    /// at start, the other two may come from consecutive cycles.
    pub clocks: Option<BusClocks>,
    /// Time since the last heartbeat.
    pub heartbeat_age: Duration,
    /// Writes from outside applied (each variable element of a request counts).
    pub writes_applied: u64,
    /// Writes refused by the program's declaration (not writable, element, value) or its
    /// `set`; every write of a refused request counts.
    pub writes_rejected: u64,
    /// Requests not taken because too many were waiting (the writer was told to try again).
    pub writes_reclaimed: u64,
    /// Messages on the socket that were not valid write requests, dropped.
    pub writes_discarded: u64,
    /// Requests accepted and waiting for the start of the next cycle.
    pub writes_pending: u64,
    /// Requests refused because the writer's uid and groups may not write (see the owner's
    /// [`Sharing`](crate::Sharing) policy).
    pub writes_refused: u64,
    /// Generation: increases with every new owner of the name (a restart or a takeover).
    pub generation: u64,
    /// Saves of retained values that failed so far (each is tried again; one that fails at
    /// stop makes the program exit with an error).
    pub retain_failures: u64,
    /// When the owner published the values of the last cycle, in nanoseconds since the Unix
    /// epoch (UTC, CLOCK_REALTIME; 0 before the first cycle): what a client shows as the
    /// values' source time (OPC UA's SourceTimestamp).
    pub cycle_utc_ns: u64,
    /// Values forced now (`plc force`; at most [`MAX_FORCES`](crate::MAX_FORCES)).
    pub forces: u64,
    /// The program's alarms active now (raised, or latched and waiting for a reset), as of
    /// the last cycle that changed them.
    pub alarms_active: u64,
    /// The program's alarms waiting for an operator's acknowledgement.
    pub alarms_unacknowledged: u64,
}

impl Status {
    pub(crate) fn read_run_state(base: &Base) -> RunState {
        RunState::from_code(base.load(S_STATE))
    }

    pub(crate) fn read(base: &Base, off: &Offsets) -> Status {
        let d = |o| Duration::from_nanos(base.load(o));
        let flags = base.load(S_BUS_FLAGS);
        Status {
            pid: base.load(S_PID),
            run_state: Self::read_run_state(base),
            cycle_count: base.load(S_CYCLES),
            stats: CycleStats {
                period: d(S_PERIOD_NS),
                last: d(S_LAST_NS),
                min: d(S_MIN_NS),
                max: d(S_MAX_NS),
                mean: d(S_MEAN_NS),
                overruns: base.load(S_OVERRUNS),
            },
            bus_state: BusState::from_code(base.load(S_BUS_STATE)),
            bus_fault: flags & BUS_FAULT != 0,
            inputs_valid: flags & INPUTS_VALID != 0,
            clocks: BusClocks::from_words([0, 1, 2].map(|w| base.load(off.c_word(w)))),
            heartbeat_age: Duration::from_nanos(now_ns().saturating_sub(base.load(S_HEARTBEAT_NS))),
            writes_applied: base.load(S_WRITES_APPLIED),
            writes_rejected: base.load(S_WRITES_REJECTED),
            writes_reclaimed: base.load(off.w_busy()),
            writes_discarded: base.load(off.w_malformed()),
            writes_pending: base.load(off.w_pending()),
            writes_refused: base.load(off.w_refused()),
            generation: base.load(H_GENERATION),
            retain_failures: base.load(S_RETAIN_FAILED),
            cycle_utc_ns: base.load(S_CYCLE_UTC_NS),
            forces: base.load(off.f_count()),
            alarms_active: base.load(off.a_active()),
            alarms_unacknowledged: base.load(off.a_unacknowledged()),
        }
    }

    /// The state tools show, given whether the owner's lock is held.
    pub fn owner_state(&self, alive: bool) -> OwnerState {
        if !alive {
            return OwnerState::Gone;
        }
        match self.run_state {
            RunState::Faulted => OwnerState::Faulted,
            RunState::Stopped => OwnerState::Stopped,
            _ => {
                // Stalled: no heartbeat for ten periods, and at least half a second.
                let limit = (self.stats.period * 10).max(Duration::from_millis(500));
                if self.heartbeat_age > limit {
                    OwnerState::Stalled
                } else {
                    OwnerState::Running
                }
            }
        }
    }
}

/// Stores one cycle's figures and a heartbeat.
/// The figures of cycle `cycle_count`, whose values were published at `utc_ns` (the heartbeat
/// is the publish's).
pub(crate) fn write_report(
    base: &Base,
    off: &Offsets,
    cycle_count: u64,
    stats: &CycleStats,
    io: &IoStatus,
    utc_ns: u64,
) {
    // In u64 arithmetic (`as_nanos` is u128): this runs every cycle.
    let ns = |d: Duration| {
        d.as_secs()
            .saturating_mul(1_000_000_000)
            .saturating_add(u64::from(d.subsec_nanos()))
    };
    base.store(S_PERIOD_NS, ns(stats.period));
    base.store(S_CYCLES, cycle_count);
    base.store(S_LAST_NS, ns(stats.last));
    base.store(S_MIN_NS, ns(stats.min));
    base.store(S_MAX_NS, ns(stats.max));
    base.store(S_MEAN_NS, ns(stats.mean));
    base.store(S_OVERRUNS, stats.overruns);
    base.store(S_BUS_STATE, u64::from(io.bus_state.code()));
    let flags = (io.bus_fault as u64 * BUS_FAULT) | (io.inputs_valid as u64 * INPUTS_VALID);
    base.store(S_BUS_FLAGS, flags);
    for (w, v) in BusClocks::to_words(io.clocks.as_ref())
        .into_iter()
        .enumerate()
    {
        base.store(off.c_word(w), v);
    }
    base.store(S_CYCLE_UTC_NS, utc_ns);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A status block and the words after an image of 4 bytes, in memory of this test's own.
    struct Block {
        words: Vec<u64>,
        off: Offsets,
    }

    impl Block {
        fn new() -> Block {
            let off = Offsets::new(4);
            Block {
                words: vec![0; off.descriptor / 8],
                off,
            }
        }

        fn base(&mut self) -> Base {
            // SAFETY: the vector's u64s are 8-byte aligned, `len` bytes long, and outlive the
            // `Base`, used only within each test while `self` lives.
            unsafe { Base::new(self.words.as_mut_ptr().cast(), self.words.len() * 8) }
        }

        fn report(&mut self, io: &IoStatus) -> Status {
            let (base, off) = (self.base(), self.off);
            write_report(&base, &off, 9, &CycleStats::default(), io, 0);
            Status::read(&base, &off)
        }
    }

    #[test]
    fn the_bus_clocks_reach_the_status_and_leave_it_with_the_bus() {
        let mut block = Block::new();
        let clocks = BusClocks {
            sync0_period_ns: 1_000_000,
            max_time_difference_ns: Some(3),
            sync0_offset_ns: 120_000,
        };
        let io = IoStatus {
            inputs_valid: true,
            bus_fault: false,
            bus_state: BusState::Op,
            clocks: Some(clocks),
        };
        let status = block.report(&io);
        assert_eq!(status.clocks, Some(clocks));
        assert_eq!((status.bus_state, status.cycle_count), (BusState::Op, 9));
        let unread = IoStatus {
            clocks: Some(BusClocks {
                max_time_difference_ns: None,
                ..clocks
            }),
            ..io
        };
        assert_eq!(block.report(&unread).clocks, unread.clocks);
        assert_eq!(block.report(&IoStatus::NONE).clocks, None);
    }

    #[test]
    fn damaged_clock_words_read_as_no_clocks_never_a_panic() {
        let mut block = Block::new();
        let (base, off) = (block.base(), block.off);
        for words in [[u64::MAX; 3], [1 << 32, 0, 0], [0, u64::MAX, u64::MAX]] {
            for (w, v) in words.into_iter().enumerate() {
                base.store(off.c_word(w), v);
            }
            let status = Status::read(&base, &off);
            assert_eq!(status.clocks, None, "{words:?}");
        }
        base.store(off.c_word(0), 500);
        let clocks = Status::read(&base, &off).clocks.expect("a period fits");
        assert_eq!(
            clocks.max_time_difference_ns, None,
            "u64::MAX does not fit a u32"
        );
        assert_eq!(clocks.sync0_offset_ns, u64::MAX);
        assert!(!clocks.to_string().is_empty());
    }
}
