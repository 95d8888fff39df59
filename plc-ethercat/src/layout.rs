//! Where each PDO entry sits in its SubDevice's process data (`plc_rules::bus::layout`,
//! re-exported where it has always been).

pub use plc_rules::bus::layout::*;
