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
//! clocks, the program's alarm counts (active, unacknowledged), and the layout descriptor as
//! JSON. It is sealed:
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

// Layers, bottom to top: `error`, `limits` and the texts of messages; `sys` (system calls);
// `format` (the segment's format); `protocol` (the socket's messages and their answers); then
// `owner` and `tool`, which never import each other; `shared_global_memory` above both.
mod calendar;
mod env;
mod error;
pub mod limits;
mod log_limit;
mod naming;

mod sys;

mod format;

pub mod protocol;

mod owner;
mod tool;

mod shared_global_memory;

pub use calendar::{parse_utc, utc_text};
pub use env::RUNTIME_DIR_ENV;
pub use error::{Cause, ShmError};
pub use format::alarm_descriptor::AlarmDescriptor;
pub use format::alarm_table::AlarmEntry;
pub use format::bus_clocks::BusClocks;
pub use format::bus_state::BusState;
pub use format::change;
pub use format::codec;
pub use format::cycle_stats::CycleStats;
pub use format::descriptor::{BitDescriptor, LayoutDescriptor, VarDescriptor};
pub use format::force_table::ForceInfo;
pub use format::io_status::IoStatus;
pub use format::status::{OwnerState, RunState, Status};
pub use limits::{GREETING_GRACE, MAX_CONNECTIONS, MAX_FORCES, MAX_PER_UID, RESERVED_FOR_WRITERS};
pub use log_limit::LogLimit;
pub use naming::{path_of, shown_in_log};
pub use owner::policy::Sharing;
pub use owner::{AlarmCommand, AlarmRefusal, HeldForce, Rejection, ShmOwner};
pub use protocol::{Ticket, WriteOutcome};
pub use shared_global_memory::SharedGlobalMemory;
pub use sys::clock::clock_ns;
pub use sys::ids::{euid, user_name};
pub use sys::memfd::memory_file;
pub use sys::priority::normal_priority;
pub use sys::rundir::{normalise as normalise_name, owner_dir as runtime_dir};
pub use sys::signals::stop_on_signals;
pub use tool::dynamic::DynSegment;
pub use tool::list::{SegmentInfo, list_segments};
pub use tool::paths::{PathLocation, PathTarget};
pub use tool::reader::ShmReader;
pub use tool::trace;
