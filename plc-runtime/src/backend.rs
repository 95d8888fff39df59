//! The I/O side of the cycle: a backend moves inputs into the struct and outputs out of it.

pub use plc_shm::IoStatus;
use std::fmt;
use std::sync::Arc;

/// Why a backend could not start: the backend's own error, kept whole as this error's
/// [`source`](std::error::Error::source) (for EtherCAT an `EtherCatError`), or a message.
///
/// ```
/// use plc_runtime::IoError;
/// let e = IoError::new("the simulated press is not answering; start it first");
/// assert_eq!(e.to_string(), "the simulated press is not answering; start it first");
/// ```
#[derive(Clone, Debug)]
pub struct IoError(Arc<dyn std::error::Error + Send + Sync + 'static>);

impl IoError {
    /// Wraps a backend's error, or a message (`&str`, `String`).
    pub fn new(cause: impl Into<Box<dyn std::error::Error + Send + Sync + 'static>>) -> Self {
        IoError(Arc::from(cause.into()))
    }

    /// The backend's error, to look at its type (`downcast_ref`).
    pub fn cause(&self) -> &(dyn std::error::Error + Send + Sync + 'static) {
        &*self.0
    }
}

impl fmt::Display for IoError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.0, f)
    }
}

impl std::error::Error for IoError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        Some(&*self.0)
    }
}

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
    /// Whether the I/O can run at the cycle's `period` (EtherCAT with distributed clocks:
    /// SYNC0 must be a whole multiple of it). [`RuntimeBuilder::build`](crate::RuntimeBuilder::build)
    /// asks before anything starts. Default: any period.
    fn check_period(&self, period: std::time::Duration) -> Result<(), IoError> {
        let _ = period;
        Ok(())
    }
    /// Where the last [`exchange`](Self::exchange) fell against a clock the I/O keeps of
    /// its own, when it keeps one and that exchange measured it: `None` (the default) leaves
    /// the cycle on the runtime's monotonic clock alone. EtherCAT with distributed clocks
    /// answers with where its frame passed the reference clock after SYNC0 and where it
    /// should have (the shift), which ethercrab's `tx_rx_dc` measures; the runtime then moves
    /// its next deadlines a little at a time until the two meet, so the cycle follows the
    /// bus's time instead of drifting against it (see [`CyclePhase`]).
    ///
    /// Called once per cycle, right after the exchange; answer `None` for a cycle whose
    /// exchange measured nothing (a lost frame), never an old measurement, which would be
    /// corrected for twice.
    fn cycle_phase(&self) -> Option<CyclePhase> {
        None
    }
    /// A new build of the program takes over between two cycles (an online change) with the
    /// variables `schema` describes: bind the I/O to them (EtherCAT: each link to its entry
    /// again, by name, on the devices already running). Called on the cycle thread between
    /// two exchanges. An error refuses the change and leaves the I/O bound as it was; the
    /// default refuses, for I/O that cannot follow a change.
    fn rebind(&mut self, schema: &plc_core::memory::Schema) -> Result<(), IoError> {
        let _ = schema;
        Err(IoError::new(
            "this program's I/O cannot follow a change of its variables: stop it and start \
             the new build",
        ))
    }
}

/// Where a cycle's exchange fell against the I/O's own clock ([`IoBackend::cycle_phase`]):
/// `offset` after that clock's last tick, where it should be `target` after one. Both are
/// taken modulo the cycle's period (the I/O's ticks, e.g. SYNC0, come every whole number of
/// periods), so only the difference between them counts.
///
/// The runtime corrects its next deadline by a quarter of that difference, at most a
/// sixteenth of the period per cycle (`schedule`'s documentation says why): a cycle then
/// follows the I/O's clock within a few microseconds after a few dozen cycles, and a
/// wrong or wild value moves one cycle's start by at most a sixteenth of the period.
///
/// ```
/// use plc_runtime::CyclePhase;
/// use std::time::Duration;
/// // The frame passed the reference clock 300 us after SYNC0; it should pass at 250 us.
/// let phase = CyclePhase {
///     offset: Duration::from_micros(300),
///     target: Duration::from_micros(250),
/// };
/// assert!(phase.offset > phase.target);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CyclePhase {
    /// When the exchange met the I/O's clock, after its last tick (EtherCAT: when the frame
    /// passed the DC reference clock, after the last SYNC0 pulse).
    pub offset: std::time::Duration,
    /// Where the I/O wants it (EtherCAT: the description's SYNC0 `shift`).
    pub target: std::time::Duration,
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
    fn rebind(&mut self, _: &plc_core::memory::Schema) -> Result<(), IoError> {
        Ok(())
    }
}
