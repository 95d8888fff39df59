//! What runs on this machine, as `plc list` shows it.

use super::dynamic::DynSegment;
use crate::error::ShmError;
use crate::format::bus_clocks::BusClocks;
use crate::format::status::OwnerState;
use crate::sys::rundir;

/// A running (or left behind) segment, as `plc list` shows it.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct SegmentInfo {
    /// Segment name.
    pub name: String,
    /// Owner pid (0 if the segment cannot be read).
    pub pid: u64,
    /// Owner state.
    pub state: OwnerState,
    /// Cycles done.
    pub cycle_count: u64,
    /// Number of variables.
    pub variables: usize,
    /// Saves of retained values that failed so far.
    pub retain_failures: u64,
    /// Values forced now.
    pub forces: u64,
    /// The bus's distributed clocks, on a bus that runs them.
    pub clocks: Option<BusClocks>,
    /// The program's alarms waiting for an acknowledgement.
    pub alarms_unacknowledged: u64,
    /// Why the segment cannot be read (damaged, refused, permission denied), if it cannot:
    /// such a segment is listed, not hidden, so its owner can be found and restarted.
    pub problem: Option<ShmError>,
}

/// Every running plc-vars program this process can see: the sockets in the runtime
/// directories ([`runtime_dir`](crate::runtime_dir), and root's `/run/plc-vars`). One that cannot be read is
/// listed with its [`problem`](SegmentInfo::problem); one that disappears while being listed
/// (its program stopped) is left out.
pub fn list_segments() -> Vec<SegmentInfo> {
    rundir::names()
        .into_iter()
        .filter_map(|(name, dir)| match DynSegment::attach(&name) {
            Ok(seg) => {
                let status = seg.status();
                Some(SegmentInfo {
                    pid: status.pid,
                    state: seg.owner_state(),
                    cycle_count: status.cycle_count,
                    variables: seg.descriptor().variables.len(),
                    retain_failures: status.retain_failures,
                    forces: status.forces,
                    clocks: status.clocks,
                    alarms_unacknowledged: status.alarms_unacknowledged,
                    problem: None,
                    name,
                })
            }
            Err(ShmError::NotFound(_) | ShmError::Closed { .. } | ShmError::Replaced(_)) => None,
            Err(problem) => Some(SegmentInfo {
                pid: 0,
                state: if rundir::owner_alive(&dir, &name) {
                    OwnerState::Running
                } else {
                    OwnerState::Gone
                },
                cycle_count: 0,
                variables: 0,
                retain_failures: 0,
                forces: 0,
                clocks: None,
                alarms_unacknowledged: 0,
                problem: Some(problem),
                name,
            }),
        })
        .collect()
}
