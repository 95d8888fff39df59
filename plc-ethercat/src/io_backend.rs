//! The EtherCAT backend as the runtime's `IoBackend`.

use super::backend::EtherCatBackend;
use super::error::EtherCatError;
use plc_core::memory::Memory;
use plc_runtime::{CyclePhase, IoBackend, IoError, IoStatus};
use plc_shm::BusClocks;

impl From<EtherCatError> for IoError {
    fn from(e: EtherCatError) -> Self {
        IoError::new(e)
    }
}

impl<T: Memory> IoBackend<T> for EtherCatBackend<T> {
    fn start(&mut self) -> Result<(), IoError> {
        EtherCatBackend::start(self).map_err(IoError::from)
    }

    fn exchange(&mut self, gm: &mut T) -> IoStatus {
        let s = EtherCatBackend::exchange(self, gm);
        IoStatus {
            inputs_valid: s.inputs_valid,
            bus_fault: s.bus_fault,
            bus_state: s.state,
            clocks: s.dc.map(BusClocks::from),
        }
    }

    fn fault(&mut self, _gm: &mut T) {
        EtherCatBackend::fault(self);
    }

    fn stop(&mut self) {
        EtherCatBackend::stop(self);
    }

    fn check_period(&self, period: std::time::Duration) -> Result<(), IoError> {
        EtherCatBackend::check_period(self, period).map_err(IoError::from)
    }

    fn cycle_phase(&self) -> Option<CyclePhase> {
        EtherCatBackend::cycle_phase(self)
    }

    fn rebind(&mut self, schema: &plc_core::memory::Schema) -> Result<(), IoError> {
        EtherCatBackend::rebind(self, schema).map_err(IoError::from)
    }
}

#[cfg(test)]
mod tests {
    /// The runtime needs `Send` backends (it may run on its own thread).
    #[test]
    fn the_ethercat_backend_is_send() {
        fn assert_send<S: Send>() {}
        #[derive(plc_core::GlobalMemory, Clone)]
        struct Gm {
            x: u8,
        }
        assert_send::<super::EtherCatBackend<Gm>>();
    }
}
