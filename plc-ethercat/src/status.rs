//! The outcome of one exchange, and how it counts: what makes inputs valid, what is a fault.

use ethercrab::SubDeviceState;
use plc_shm::{BusClocks, BusState};

/// The outcome of one exchange.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BusStatus {
    /// The inputs in the struct are this cycle's: the frame came back with the expected working
    /// counter and every SubDevice in OP.
    pub inputs_valid: bool,
    /// The bus is not healthy this cycle (lost frame, wrong working counter, a SubDevice out of
    /// OP, or the bus not running).
    pub bus_fault: bool,
    /// The AL state seen.
    pub state: BusState,
    /// The working counter received (0 when the frame was lost).
    pub working_counter: u16,
    /// The working counter a healthy bus gives: per SubDevice 1 if it has inputs plus 2 if it
    /// has outputs (an ESC counts a read FMMU once and a write FMMU twice in an LRW).
    pub expected_working_counter: u16,
    /// Faulty exchanges since start.
    pub fault_count: u64,
    /// The distributed clocks, on a bus whose description gives devices `dc` (`None`
    /// otherwise).
    pub dc: Option<DcStatus>,
}

/// The distributed clocks of a running bus with SYNC0: how well the clocks agree and where
/// the cycle falls against SYNC0.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DcStatus {
    /// The SYNC0 period configured (ns).
    pub sync0_period_ns: u32,
    /// The largest system time difference (register 0x092C, magnitude, ns) among the devices
    /// with `dc`: how far the worst clock was from the reference's time when it last received
    /// it. Below 100 ns on a settled bus. Read at start and then every
    /// [`Options::dc_check_interval`](super::Options::dc_check_interval); `None` before the
    /// first reading or when the last one got no answer.
    pub max_time_difference_ns: Option<u32>,
    /// When the last exchange's frame passed the reference clock, after the last SYNC0 pulse
    /// (ethercrab's `CycleInfo::cycle_start_offset`, ns): the cycle's phase against SYNC0. A
    /// value that wanders means the cycle's clock and the DC time drift apart.
    pub sync0_offset_ns: u64,
}

/// The clocks as the status block holds them and the tools show them.
impl From<DcStatus> for BusClocks {
    fn from(dc: DcStatus) -> Self {
        BusClocks {
            sync0_period_ns: dc.sync0_period_ns,
            max_time_difference_ns: dc.max_time_difference_ns,
            sync0_offset_ns: dc.sync0_offset_ns,
        }
    }
}

impl BusStatus {
    /// A bus that is not running: faulty, no valid inputs; the faults counted so far kept.
    pub(super) fn stopped(expected_working_counter: u16, fault_count: u64) -> Self {
        BusStatus {
            bus_fault: true,
            expected_working_counter,
            fault_count,
            ..BusStatus::default()
        }
    }

    /// Takes in one exchange's working counter and state (`None`: no frame came back), counts
    /// it as a fault unless the bus is healthy, and returns whether it is.
    pub(super) fn record(&mut self, answer: Option<(u16, BusState)>) -> bool {
        let (wkc, state) = answer.unwrap_or((0, BusState::NoAnswer));
        let good = wkc == self.expected_working_counter && state == BusState::Op;
        if !good {
            self.fault_count += 1;
        }
        self.inputs_valid = good;
        self.bus_fault = !good;
        self.state = state;
        self.working_counter = wkc;
        good
    }
}

/// The state of a bus whose SubDevices are in `states` (one each, ring order).
pub(super) fn state_of(states: &[SubDeviceState]) -> BusState {
    let mut it = states.iter();
    let Some(first) = it.next() else {
        return BusState::NoAnswer;
    };
    if it.any(|s| s != first) {
        return BusState::Mixed;
    }
    match first {
        SubDeviceState::Init => BusState::Init,
        SubDeviceState::PreOp => BusState::PreOp,
        SubDeviceState::SafeOp => BusState::SafeOp,
        SubDeviceState::Op => BusState::Op,
        _ => BusState::Mixed,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn running(expected: u16) -> BusStatus {
        BusStatus {
            expected_working_counter: expected,
            ..BusStatus::default()
        }
    }

    #[test]
    fn bus_state_of_mixed_and_uniform_states() {
        use SubDeviceState::*;
        assert_eq!(state_of(&[Op, Op]), BusState::Op);
        assert_eq!(state_of(&[Op, SafeOp]), BusState::Mixed);
        assert_eq!(state_of(&[]), BusState::NoAnswer);
    }

    #[test]
    fn a_healthy_exchange_validates_inputs_and_counts_no_fault() {
        let mut s = running(5);
        assert!(s.record(Some((5, BusState::Op))));
        assert_eq!(
            (
                s.inputs_valid,
                s.bus_fault,
                s.working_counter,
                s.fault_count
            ),
            (true, false, 5, 0)
        );
    }

    #[test]
    fn a_wrong_working_counter_a_state_out_of_op_and_a_lost_frame_each_count_one_fault() {
        let mut s = running(5);
        assert!(!s.record(Some((3, BusState::Op))));
        assert!(!s.record(Some((5, BusState::SafeOp))));
        assert!(!s.record(None));
        assert_eq!(
            (s.fault_count, s.state, s.working_counter),
            (3, BusState::NoAnswer, 0)
        );
        assert!(s.bus_fault && !s.inputs_valid);
        assert!(s.record(Some((5, BusState::Op))), "healthy again");
        assert_eq!(s.fault_count, 3, "the count is kept");
    }

    #[test]
    fn a_stopped_bus_is_faulty_and_keeps_its_count() {
        let s = BusStatus::stopped(7, 4);
        assert!(s.bus_fault && !s.inputs_valid);
        assert_eq!(
            (s.state, s.expected_working_counter, s.fault_count),
            (BusState::Stopped, 7, 4)
        );
    }
}
