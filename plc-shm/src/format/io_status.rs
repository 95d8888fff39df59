//! What one exchange of the I/O achieved: handed by the backend to the cycle, published in the
//! status block.

use super::bus_clocks::BusClocks;
use super::bus_state::BusState;

/// What one exchange achieved.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct IoStatus {
    /// The inputs in the struct are this cycle's.
    pub inputs_valid: bool,
    /// The bus is not healthy this cycle.
    pub bus_fault: bool,
    /// The bus state ([`BusState::NoBus`] without a bus).
    pub bus_state: BusState,
    /// The bus's distributed clocks, on a bus that runs them (`None` otherwise).
    pub clocks: Option<BusClocks>,
}

impl IoStatus {
    /// The status of a program without I/O: inputs are whatever the program holds.
    pub const NONE: IoStatus = IoStatus {
        inputs_valid: true,
        bus_fault: false,
        bus_state: BusState::NoBus,
        clocks: None,
    };
}
