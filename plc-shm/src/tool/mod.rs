//! The tool's side: a running program's segment as a tool attaches to it (its memory mapped
//! read-only, its descriptor read, its owner watched), the variables read and written by name
//! or path, forces, traces and alarm actions asked for, alarm states read, and the traces' rings drained.
//!
//! Nothing here uses the owner's side: both meet in the segment's format and the protocol.

mod alarms;
mod client;
mod commission;
pub mod dynamic;
pub mod list;
pub mod paths;
pub mod reader;
mod segment;
pub mod trace;
mod view;
