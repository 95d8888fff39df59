//! The bus description (`BusConfig`): plc-rules holds it (`plc_rules::bus`), so that the
//! derive can check links against it while compiling; re-exported here where it has always
//! been.

pub use plc_rules::bus::{
    BusConfig, ConfigError, DeviceConfig, Identity, PdoDirection, PdoEntry, StartupSdo,
};
