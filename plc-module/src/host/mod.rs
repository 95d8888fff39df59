//! The host's side of running a module: its variables for the runtime ([`ModuleMemory`],
//! over the schema its descriptor gives).

pub mod change;
pub mod memory;
mod schema;
pub mod tick;
