//! Where each PDO entry sits in its SubDevice's process data: the bus rules' layout
//! (`plc_rules::bus::layout`), which the derive also uses to check links while compiling.

pub use plc_rules::bus::layout::*;
