//! Shared memory: a program's variables in a named segment that other processes read and
//! write while it runs.
//!
//! - [`SharedGlobalMemory`]: the owner publishes each cycle; typed readers snapshot.
//! - [`DynSegment`]: tools without the Rust type, through the descriptor stored in the segment.
//! - [`list_segments`]: what runs on this machine.
//!
//! A segment (`/dev/shm/plc.<name>`, mode 0600) holds a header (magic, format version,
//! layout hash, image size, generation, seqlock sequence), a status block (owner pid, state,
//! period, cycle count and times, overruns, bus state and flags, heartbeat, failed retain
//! saves), the image, a mailbox of write requests, and the layout descriptor as JSON. The owner
//! holds an exclusive `flock` on `/dev/shm/plc.<name>.lock` for its whole life: a second owner
//! is refused while it lives, and after it dies (however it dies) a new owner takes the segment
//! over with a new generation, which attached readers notice ([`ShmError::Replaced`]). An owner
//! that stops cleanly marks its segment closed and removes both files, so readers still
//! attached are told ([`ShmError::Closed`], saying whether it faulted) instead of reading a
//! frozen image, also once the program runs again. What a killed owner leaves is removed by
//! the next owner of the same user that starts, whatever its name.
//!
//! Neither file is opened through a symbolic link, and a file that is another user's or open
//! to others is refused with a message naming it and the fix ([`ShmError::Unsafe`]). The owner
//! trusts nothing another process wrote: its seqlock counter and mailbox position live in its
//! own memory, header and descriptor numbers are checked (and capped) before a reader uses
//! them, every loop over shared words is bounded, each mailbox request is checked again
//! against the program's own declaration, and a segment truncated under a process reads as
//! zeros instead of killing it with SIGBUS. The owner writes its header, descriptor and mailbox
//! words again from its own memory every 100 ms, and replaces a truncated segment by a new one
//! at its next cycle.

mod bytes;
pub(crate) mod codec;
mod descriptor;
mod dynamic;
mod error;
mod guard;
mod layout;
pub mod mailbox;
mod owner;
mod paths;
mod segment;
mod status;
mod view;

pub use descriptor::{BitDescriptor, LayoutDescriptor, VarDescriptor};
pub use dynamic::DynSegment;
pub use error::ShmError;
pub use owner::{SharedGlobalMemory, ShmOwner, ShmReader};
pub use paths::{PathLocation, PathTarget};
pub use segment::normalise as normalise_name;
pub use status::{OwnerState, RunState, Status};

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
    /// Why the segment cannot be read (damaged, refused, permission denied), if it cannot:
    /// such a segment is listed, not hidden, so its owner can be found and restarted.
    pub problem: Option<ShmError>,
}

/// Every plc-vars segment on this machine. One that cannot be read is listed with its
/// [`problem`](SegmentInfo::problem); one that disappears while being listed (its program
/// stopped) is left out.
pub fn list_segments() -> Vec<SegmentInfo> {
    segment::names()
        .into_iter()
        .filter_map(|name| match DynSegment::attach(&name) {
            Ok(seg) => {
                let status = seg.status();
                Some(SegmentInfo {
                    pid: status.pid,
                    state: seg.owner_state(),
                    cycle_count: status.cycle_count,
                    variables: seg.descriptor().variables.len(),
                    retain_failures: status.retain_failures,
                    problem: None,
                    name,
                })
            }
            Err(ShmError::NotFound(_) | ShmError::Closed { .. } | ShmError::Replaced(_)) => None,
            Err(problem) => Some(SegmentInfo {
                pid: 0,
                state: if segment::owner_alive(&name) {
                    OwnerState::Running
                } else {
                    OwnerState::Gone
                },
                cycle_count: 0,
                variables: 0,
                retain_failures: 0,
                problem: Some(problem),
                name,
            }),
        })
        .collect()
}
