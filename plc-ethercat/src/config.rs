//! The bus description (`BusConfig`), as the bus rules hold it (`plc_rules::bus`) so that the
//! derive can check links against it while compiling.

pub use plc_rules::bus::{
    BusConfig, ConfigError, DcConfig, DeviceConfig, Identity, PdoDirection, PdoEntry, StartupSdo,
};
