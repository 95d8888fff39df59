//! Shared memory: a program's variables in a named segment that other processes read and
//! write while it runs.
//!
//! - [`SharedGlobalMemory`]: the owner publishes each cycle; typed readers snapshot.
//! - [`DynSegment`]: tools without the Rust type, through the descriptor stored in the segment.
//! - [`list_segments`]: what runs on this machine.
//!
//! A segment (`/dev/shm/plc.<name>`, mode 0600) holds a header (magic, format version,
//! layout hash, image size, generation, seqlock sequence), a status block (owner pid, state,
//! period, cycle count and times, overruns, bus state and flags, heartbeat), the image, a
//! mailbox of write requests, and the layout descriptor as JSON. The owner holds an exclusive
//! `flock` on `/dev/shm/plc.<name>.lock` for its whole life: a second owner is refused while it
//! lives, and after it dies (however it dies) a new owner takes the segment over with a new
//! generation, which attached readers notice ([`ShmError::Replaced`]). An owner that stops
//! cleanly marks its segment closed before removing it, so readers still attached are told
//! ([`ShmError::Closed`], saying whether it faulted) instead of reading a frozen image, also
//! once the program runs again. The lock file stays when the program stops: it keeps the last
//! generation, and deleting it while an owner holds it would let a second owner start.
//!
//! The owner trusts nothing another process wrote: header and descriptor numbers are checked
//! before use, and each mailbox request is checked again against the program's own declaration.

mod bytes;
pub(crate) mod codec;
mod descriptor;
mod dynamic;
mod error;
mod layout;
pub mod mailbox;
mod owner;
mod segment;
mod status;
mod view;

pub use descriptor::{BitDescriptor, LayoutDescriptor, VarDescriptor};
pub use dynamic::DynSegment;
pub use error::ShmError;
pub use owner::SharedGlobalMemory;
pub use segment::normalise as normalise_name;
pub use status::{OwnerState, RunState, Status};

/// A running (or left behind) segment, as `plc list` shows it.
#[derive(Clone, Debug)]
pub struct SegmentInfo {
    /// Segment name.
    pub name: String,
    /// Owner pid.
    pub pid: u64,
    /// Owner state.
    pub state: OwnerState,
    /// Cycles done.
    pub cycle_count: u64,
    /// Number of variables.
    pub variables: usize,
}

/// Every plc-vars segment on this machine; a segment that cannot be read is skipped.
pub fn list_segments() -> Vec<SegmentInfo> {
    segment::names()
        .into_iter()
        .filter_map(|name| {
            let seg = DynSegment::attach(&name).ok()?;
            let status = seg.status();
            Some(SegmentInfo {
                pid: status.pid,
                state: seg.owner_state(),
                cycle_count: status.cycle_count,
                variables: seg.descriptor().variables.len(),
                name,
            })
        })
        .collect()
}
