//! The PLCopen Motion Control function blocks, with PLCopen's member names, as plain structs
//! that live in the program's image (tools and OPC UA see `power.Status`, `move_to.Busy`).
//!
//! The files: `run` holds what the blocks of one kind share (PLCopen part 1's general
//! rules); `enabled` the Enable-kind blocks (`MC_Power`, `MC_ReadActualPosition`); `home`,
//! `moves` and `stop` the Execute-kind ones (`MC_Home`; `MC_MoveAbsolute`,
//! `MC_MoveRelative`, `MC_MoveVelocity`; `MC_Stop`, `MC_Reset`).

#[macro_use]
mod run;
mod enabled;
mod home;
mod moves;
mod stop;

pub use enabled::{McPower, McReadActualPosition};
pub use home::McHome;
pub use moves::{McMoveAbsolute, McMoveRelative, McMoveVelocity};
pub use stop::{McReset, McStop};
