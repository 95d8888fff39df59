//! Shared memory: a program's variables in a named segment that other processes read and
//! write while it runs.
//!
//! - [`SharedGlobalMemory`]: the owner publishes each cycle; typed readers snapshot.
//! - [`DynSegment`]: tools without the Rust type, through the descriptor stored in the segment.
//! - [`list_segments`]: what runs on this machine.
//! - [`Status`], [`BusState`], [`BusClocks`], [`CycleStats`], [`IoStatus`]: the owner's status
//!   block, as the runtime writes it and the tools read it.
//!
//! A segment is an anonymous memory file (`memfd_create`) holding a header (magic, format
//! version, layout hash, image size, generation, seqlock sequence), a status block (owner pid,
//! state, period, cycle count and times, overruns, bus state and flags, heartbeat, write
//! counters, failed retain saves), the image, the table of forces, the bus's distributed
//! clocks, and the layout descriptor as JSON. It is sealed:
//! nobody can shrink or grow it, and once the owner mapped it nobody can map it writable or
//! write it. The owner serves it on a Unix socket, `<name>.sock` in its runtime directory
//! (`$XDG_RUNTIME_DIR/plc-vars`, `/run/plc-vars` for root, or `$PLC_VARS_RUNTIME_DIR`): a tool
//! connects, receives the segment's descriptor with the owner's greeting and maps it
//! read-only. Writes travel over the same connection as messages; the owner learns each
//! writer's uid and groups from the kernel, checks them against its policy ([`Sharing`];
//! default: only its own uid writes), checks each request against its declaration on a server
//! thread, and applies accepted ones at the start of its next cycle, in order, each request
//! all or none, answering each writer.
//!
//! The owner holds an exclusive `flock` on `<name>.lock` beside the socket for its whole life:
//! a second owner is refused while it lives, and after it dies (however it dies) the next owner
//! of the same user removes what it left. An owner that stops marks its segment closed and
//! removes both files, so readers still attached are told ([`ShmError::Closed`], saying
//! whether it faulted) instead of reading a frozen image; a killed owner's readers see its
//! connection hang up ([`ShmError::OwnerGone`]).
//!
//! Neither the directory nor a file in it is used through a symbolic link, and one that is
//! another user's or open to others is refused with a message naming it and the fix
//! ([`ShmError::Unsafe`]). The owner trusts nothing another process sends: messages are
//! bounded and decoded with every length checked, connections are bounded in number, and a
//! tool that stops reading blocks nothing but its own connection.

#![deny(missing_docs)]

mod bus_clocks;
mod bus_state;
mod bytes;
mod client;
mod codec;
mod commission;
mod cycle_stats;
mod descriptor;
mod dynamic;
mod error;
mod forces;
mod io_status;
mod layout;
mod log_limit;
pub mod mailbox;
mod owner;
mod paths;
mod policy;
pub mod protocol;
mod segment;
mod server;
mod status;
mod sys;
pub mod trace;
mod view;

pub use bus_clocks::BusClocks;
pub use bus_state::BusState;
pub use cycle_stats::CycleStats;
pub use descriptor::{BitDescriptor, LayoutDescriptor, VarDescriptor};
pub use dynamic::DynSegment;
pub use error::{Cause, ShmError};
pub use forces::{ForceInfo, path_of, shown_in_log, utc_text};
pub use io_status::IoStatus;
pub use layout::MAX_FORCES;
pub use log_limit::LogLimit;
pub use owner::{SharedGlobalMemory, ShmOwner, ShmReader};
pub use paths::{PathLocation, PathTarget};
pub use policy::Sharing;
pub use server::{GREETING_GRACE, MAX_CONNECTIONS, MAX_PER_UID, RESERVED_FOR_WRITERS};
pub use status::{OwnerState, RunState, Status};
pub use sys::ids::euid;
pub use sys::priority::normal_priority;
pub use sys::rundir::{RUNTIME_DIR_ENV, normalise as normalise_name, owner_dir as runtime_dir};

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
    /// Why the segment cannot be read (damaged, refused, permission denied), if it cannot:
    /// such a segment is listed, not hidden, so its owner can be found and restarted.
    pub problem: Option<ShmError>,
}

/// Every running plc-vars program this process can see: the sockets in the runtime
/// directories ([`runtime_dir`], and root's `/run/plc-vars`). One that cannot be read is
/// listed with its [`problem`](SegmentInfo::problem); one that disappears while being listed
/// (its program stopped) is left out.
pub fn list_segments() -> Vec<SegmentInfo> {
    segment::names()
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
                    problem: None,
                    name,
                })
            }
            Err(ShmError::NotFound(_) | ShmError::Closed { .. } | ShmError::Replaced(_)) => None,
            Err(problem) => Some(SegmentInfo {
                pid: 0,
                state: if segment::owner_alive(&dir, &name) {
                    OwnerState::Running
                } else {
                    OwnerState::Gone
                },
                cycle_count: 0,
                variables: 0,
                retain_failures: 0,
                forces: 0,
                clocks: None,
                problem: Some(problem),
                name,
            }),
        })
        .collect()
}
