//! The I/O side of the cycle: a backend moves inputs into the struct and outputs out of it.

use super::BusState;
use std::fmt;

/// What one exchange achieved.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct IoStatus {
    /// The inputs in the struct are this cycle's.
    pub inputs_valid: bool,
    /// The bus is not healthy this cycle.
    pub bus_fault: bool,
    /// The bus state ([`BusState::NoBus`] without a bus).
    pub bus_state: BusState,
}

impl IoStatus {
    /// The status of a program without I/O: inputs are whatever the program holds.
    pub const NONE: IoStatus = IoStatus {
        inputs_valid: true,
        bus_fault: false,
        bus_state: BusState::NoBus,
    };
}

/// Why a backend could not start.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct IoError(pub String);

impl fmt::Display for IoError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for IoError {}

/// Real I/O for the cycle: EtherCAT (`plc_io::ethercat::EtherCatBackend`), a process image,
/// a simulation, or nothing ([`NoIo`]). Synchronous: an async bus runs its own executor.
pub trait IoBackend<T> {
    /// Brings the I/O up (e.g. the bus to OP). Called once before the first cycle.
    fn start(&mut self) -> Result<(), IoError>;
    /// Sends the outputs of the last cycle and receives this cycle's inputs into `gm`.
    fn exchange(&mut self, gm: &mut T) -> IoStatus;
    /// The program failed: outputs are already zero in `gm`; put the I/O in a safe state
    /// (EtherCAT: zero outputs out, SubDevices to SAFE-OP).
    fn fault(&mut self, gm: &mut T) {
        let _ = gm;
    }
    /// Shuts the I/O down (EtherCAT: back to INIT). Called once at the end.
    fn stop(&mut self);
}

/// No I/O: for programs that only talk through shared memory, and for tests.
#[derive(Clone, Copy, Debug, Default)]
pub struct NoIo;

impl<T> IoBackend<T> for NoIo {
    fn start(&mut self) -> Result<(), IoError> {
        Ok(())
    }
    fn exchange(&mut self, _: &mut T) -> IoStatus {
        IoStatus::NONE
    }
    fn stop(&mut self) {}
}
