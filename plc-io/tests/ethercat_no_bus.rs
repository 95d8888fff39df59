//! The EtherCAT backend without SubDevices: a transport whose frames never come back, and a
//! backend used before it is started. (The end-to-end tests on the simulated bus are in
//! `ethercat_sim.rs`.)

use plc_core::{
    Direction, GlobalMemory, ProcessImage, ProcessImageError, SetError, Value, VarInfo,
};
use plc_io::ethercat::{
    BusConfig, BusState, EtherCatBackend, EtherCatError, Options, Transport, devices,
};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

/// One linked bool, written by hand (the derive is tested elsewhere).
#[derive(Debug, Default, Clone)]
struct OneInput {
    button: bool,
}

impl GlobalMemory for OneInput {
    type Image = [u8; 1];
    const VARIABLES: &'static [VarInfo] =
        &[plc_core::__private::var::<bool>("button", "bool", 0, 1)
            .link("ethercat.di.input1")
            .direction(Direction::Input)];
    const LAYOUT_HASH: u64 = 0;
    fn unpack_bits(&mut self) {}
    fn pack_bits(&mut self) {}
    fn to_image(&self) -> [u8; 1] {
        [u8::from(self.button)]
    }
    fn from_image(image: &[u8; 1]) -> Self {
        OneInput {
            button: image[0] != 0,
        }
    }
    fn try_get(&self, index: usize, element: usize) -> Option<Value> {
        (index == 0 && element == 0).then_some(Value::Bool(self.button))
    }
    fn set(&mut self, index: usize, _element: usize, value: Value) -> Result<(), SetError> {
        match value {
            Value::Bool(b) if index == 0 => {
                self.button = b;
                Ok(())
            }
            _ => Err(SetError::UnknownIndex { index }),
        }
    }
    fn read_inputs<B: AsRef<[u8]>>(
        &mut self,
        _: &ProcessImage<B>,
    ) -> Result<(), ProcessImageError> {
        Ok(())
    }
    fn write_outputs<B: AsRef<[u8]> + AsMut<[u8]>>(
        &self,
        _: &mut ProcessImage<B>,
    ) -> Result<(), ProcessImageError> {
        Ok(())
    }
}

fn bus() -> BusConfig {
    BusConfig {
        devices: vec![devices::ek1100("coupler"), devices::el1004("di")],
    }
}

/// Sends every frame into the void until ethercrab asks the driver to exit; records the exit.
fn dead_bus(exited: Arc<AtomicBool>) -> Transport {
    Transport::custom(move |mut tx, _rx| {
        let thread = std::thread::spawn(move || {
            while !tx.should_exit() {
                while let Some(frame) = tx.next_sendable_frame() {
                    let _ = frame.send_blocking(|data| Ok(data.len()));
                }
                std::thread::sleep(Duration::from_micros(200));
            }
            exited.store(true, Ordering::SeqCst);
        });
        Ok(Box::new(JoinOnDrop(Some(thread))))
    })
}

struct JoinOnDrop(Option<std::thread::JoinHandle<()>>);

impl Drop for JoinOnDrop {
    fn drop(&mut self) {
        if let Some(t) = self.0.take() {
            let _ = t.join();
        }
    }
}

#[test]
fn a_bus_that_never_answers_fails_start_with_advice_and_closes_the_transport() {
    let exited = Arc::new(AtomicBool::new(false));
    let mut backend =
        EtherCatBackend::<OneInput>::new(bus(), dead_bus(exited.clone()), Options::default())
            .unwrap();
    let t = Instant::now();
    let err = backend.start().unwrap_err();
    assert!(matches!(err, EtherCatError::Bus { .. }), "{err}");
    let text = err.to_string();
    assert!(text.contains("scanning the bus"), "{text}");
    assert!(
        text.contains("check the cable, the interface name"),
        "{text}"
    );
    assert!(
        exited.load(Ordering::SeqCst),
        "the driver was not told to exit"
    );
    assert!(t.elapsed() < Duration::from_secs(5));
    // A failed backend cannot be restarted: it says so instead of hanging.
    let again = backend.start().unwrap_err().to_string();
    assert!(again.contains("build a new one"), "{again}");
}

#[test]
fn exchange_before_start_reports_a_stopped_bus_and_invalid_inputs() {
    let exited = Arc::new(AtomicBool::new(false));
    let mut backend =
        EtherCatBackend::<OneInput>::new(bus(), dead_bus(exited), Options::default()).unwrap();
    let mut gm = OneInput { button: true };
    let status = backend.exchange(&mut gm);
    assert!(!status.inputs_valid && status.bus_fault);
    assert_eq!(status.state, BusState::Stopped);
    assert_eq!(status.expected_working_counter, 1, "EL1004: one read FMMU");
    backend.stop();
    backend.fault();
}

#[test]
fn links_are_resolved_when_the_backend_is_built() {
    let exited = Arc::new(AtomicBool::new(false));
    let config = BusConfig {
        devices: vec![devices::ek1100("coupler"), devices::el2004("di")],
    };
    let err = EtherCatBackend::<OneInput>::new(config, dead_bus(exited), Options::default())
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("`button` (link `ethercat.di.input1`): device `di` has no entry `input1`: use one of `output1`"),
        "{err}"
    );
}

#[test]
fn a_permission_or_name_problem_on_a_nic_is_a_clear_transport_error() {
    let mut backend = EtherCatBackend::<OneInput>::new(
        bus(),
        Transport::Interface("plc-no-such-nic0".into()),
        Options::default(),
    )
    .unwrap();
    let err = backend.start().unwrap_err();
    assert!(matches!(err, EtherCatError::Transport(_)), "{err}");
    let text = err.to_string();
    assert!(
        text.contains("cannot open network interface `plc-no-such-nic0`"),
        "{text}"
    );
    assert!(
        text.contains("CAP_NET_RAW")
            || text.contains("no such interface")
            || text.contains("No such"),
        "{text}"
    );
}
