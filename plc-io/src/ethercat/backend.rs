//! The EtherCAT I/O backend: ethercrab's MainDevice driving one group of SubDevices, moving the
//! linked variables of a `GlobalMemory` struct to and from the process data each cycle.

use super::config::{BusConfig, ConfigError, PdoDirection};
use super::layout::{BusLayout, LayoutError, read_bits, write_bits};
use super::recovery::{self, Configured, Outcome};
use super::resolve::{Binding, ResolveError, resolve};
use super::{MAX_FRAMES, MAX_PDI, MAX_PDU_DATA, MAX_SUBDEVICES};
use ethercrab::error::Error as CrabError;
use ethercrab::subdevice_group::{HasPdi, NoDc, Op, SafeOp};
use ethercrab::{
    DefaultLock, MainDevice, MainDeviceConfig, PduRx, PduStorage, PduTx, SubDeviceGroup,
    SubDeviceState, Timeouts,
};
// async-io's block_on drives the timer reactor ethercrab's timeouts use on this thread, instead
// of waking the fallback "async-io" thread every cycle.
use async_io::block_on;
use plc_core::{GlobalMemory, IecType, TypeFamily, Value};
use std::fmt;
use std::marker::PhantomData;

type Group<S> = SubDeviceGroup<MAX_SUBDEVICES, MAX_PDI, DefaultLock, S, NoDc>;

/// What the driver of a custom transport hands back: kept alive while the bus runs and dropped
/// after ethercrab has told the driver to exit (`MainDevice::release_all`), so a guard that
/// joins the driver's thread on drop shuts it down cleanly.
pub type DriverGuard = Box<dyn Send>;

/// A function that starts something driving ethercrab's frames (see [`Transport::custom`]).
pub type DriverFn =
    Box<dyn FnOnce(PduTx<'static>, PduRx<'static>) -> std::io::Result<DriverGuard> + Send>;

/// How frames reach the SubDevices.
pub enum Transport {
    /// A network interface (`eth0`, `enp3s0`): a raw socket driven by ethercrab's
    /// `tx_rx_task` on its own thread. Needs root or `CAP_NET_RAW`
    /// (`sudo setcap cap_net_raw=ep <program>`).
    Interface(String),
    /// Anything that drives ethercrab's `PduTx`/`PduRx`, e.g. the in-process simulated bus.
    Custom(DriverFn),
}

impl Transport {
    /// A custom driver: `start` receives ethercrab's frame queues and starts moving frames
    /// (usually on a thread of its own), returning a guard kept until the bus stops.
    ///
    /// With the simulated bus of `ethercat-sim`:
    /// `Transport::custom(move |tx, rx| Ok(Box::new(ethercat_sim::inproc::spawn(tx, rx, bus))))`.
    pub fn custom(
        start: impl FnOnce(PduTx<'static>, PduRx<'static>) -> std::io::Result<DriverGuard>
        + Send
        + 'static,
    ) -> Self {
        Transport::Custom(Box::new(start))
    }
}

impl fmt::Debug for Transport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Transport::Interface(name) => f.debug_tuple("Interface").field(name).finish(),
            Transport::Custom(_) => f.write_str("Custom(..)"),
        }
    }
}

/// What the struct's input variables hold while the bus does not answer correctly.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum InputsOnFault {
    /// Set every linked input to 0 / `false` (the default): a program that ignores the
    /// inputs-valid flag sees "no signal", which is the safe reading of normally-closed
    /// limit switches and broken wires, rather than a frozen "all good".
    #[default]
    Zero,
    /// Keep the last values read while the bus answered correctly (the program must watch the
    /// inputs-valid flag).
    KeepLast,
}

/// Settings of the backend. `Options::default()` suits real hardware.
#[derive(Clone, Debug)]
pub struct Options {
    /// ethercrab's timeouts. The PDU timeout bounds how long one `exchange` waits when a frame
    /// is lost; the default 30 ms is ethercrab's.
    pub timeouts: Timeouts,
    /// ethercrab's distributed-clock static drift compensation frames at start-up (its default
    /// 10 000; 100 is plenty on the simulated bus).
    pub dc_static_sync_iterations: u32,
    /// See [`InputsOnFault`].
    pub inputs_on_fault: InputsOnFault,
    /// While the bus is faulty, how often `exchange` tries to bring SubDevices that answer
    /// but are not in OP back to OP (a few datagrams per SubDevice; see
    /// [`EtherCatBackend::problems`]).
    pub recovery_interval: std::time::Duration,
}

impl Options {
    /// Settings for the simulated bus: few DC sync frames, and timeouts with room for a busy
    /// machine (the simulated SubDevices answer from a thread that may wait for a core, where
    /// ethercrab's 10 ms EEPROM timeout assumes hardware answering within microseconds).
    pub fn simulated() -> Self {
        Options {
            timeouts: Timeouts {
                pdu: std::time::Duration::from_millis(200),
                eeprom: std::time::Duration::from_millis(500),
                ..Timeouts::default()
            },
            dc_static_sync_iterations: 100,
            ..Options::default()
        }
    }
}

impl Default for Options {
    fn default() -> Self {
        Options {
            timeouts: Timeouts::default(),
            dc_static_sync_iterations: MainDeviceConfig::default().dc_static_sync_iterations,
            inputs_on_fault: InputsOnFault::Zero,
            recovery_interval: std::time::Duration::from_millis(100),
        }
    }
}

/// The AL state of the bus as the last exchange saw it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum BusState {
    /// Not started, or stopped.
    #[default]
    Stopped,
    /// All SubDevices in INIT.
    Init,
    /// All SubDevices in PRE-OP.
    PreOp,
    /// All SubDevices in SAFE-OP (inputs update, outputs held safe).
    SafeOp,
    /// All SubDevices in OP.
    Op,
    /// SubDevices in different states.
    Mixed,
    /// The last frame did not come back.
    NoAnswer,
}

impl BusState {
    /// Upper-case name as EtherCAT tools show it: `OP`, `SAFE-OP`, ...
    pub const fn name(self) -> &'static str {
        match self {
            BusState::Stopped => "STOPPED",
            BusState::Init => "INIT",
            BusState::PreOp => "PRE-OP",
            BusState::SafeOp => "SAFE-OP",
            BusState::Op => "OP",
            BusState::Mixed => "MIXED",
            BusState::NoAnswer => "NO-ANSWER",
        }
    }
}

impl fmt::Display for BusState {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(self.name())
    }
}

/// The outcome of one exchange.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BusStatus {
    /// The inputs in the struct are this cycle's: the frame came back with the expected working
    /// counter and every SubDevice in OP.
    pub inputs_valid: bool,
    /// The bus is not healthy this cycle (lost frame, wrong working counter, a SubDevice out of
    /// OP, or the bus not running).
    pub bus_fault: bool,
    /// The AL state seen.
    pub state: BusState,
    /// The working counter received (0 when the frame was lost).
    pub working_counter: u16,
    /// The working counter a healthy bus gives: per SubDevice 1 if it has inputs plus 2 if it
    /// has outputs (an ESC counts a read FMMU once and a write FMMU twice in an LRW).
    pub expected_working_counter: u16,
    /// Faulty exchanges since start.
    pub fault_count: u64,
}

/// Why the bus could not be started.
#[derive(Debug)]
pub enum EtherCatError {
    /// The bus description is not valid.
    Config(ConfigError),
    /// The struct's links do not fit the bus description.
    Links(ResolveError),
    /// The SubDevices found differ from the description (count or identity), by position.
    Identity(Vec<String>),
    /// The process data ethercrab configured differs from the description.
    Layout(LayoutError),
    /// The transport could not be opened.
    Transport(String),
    /// ethercrab failed.
    Bus {
        /// What was being done.
        during: &'static str,
        /// ethercrab's error.
        error: CrabError,
    },
    /// `start` was called on a running backend, or `exchange` before `start`.
    State(&'static str),
}

impl fmt::Display for EtherCatError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            EtherCatError::Config(e) => e.fmt(f),
            EtherCatError::Links(e) => e.fmt(f),
            EtherCatError::Identity(problems) => {
                f.write_str(
                    "the SubDevices on the bus do not match the bus description (fix the \
                     description or the wiring; nothing was switched to OP):",
                )?;
                for p in problems {
                    write!(f, "\n  - {p}")?;
                }
                Ok(())
            }
            EtherCatError::Layout(e) => e.fmt(f),
            EtherCatError::Transport(e) => f.write_str(e),
            EtherCatError::Bus { during, error } => {
                write!(f, "EtherCAT error while {during}: {error}")?;
                match error {
                    CrabError::Timeout(_) => f.write_str(
                        " (no answer: check the cable, the interface name and that the \
                         SubDevices are powered)",
                    ),
                    CrabError::Capacity(_) | CrabError::PdiTooLong { .. } => write!(
                        f,
                        " (the bus is larger than plc-io's caps of {MAX_SUBDEVICES} SubDevices \
                         and {MAX_PDI} bytes of process data)"
                    ),
                    _ => Ok(()),
                }
            }
            EtherCatError::State(s) => f.write_str(s),
        }
    }
}

impl std::error::Error for EtherCatError {}

impl From<ConfigError> for EtherCatError {
    fn from(e: ConfigError) -> Self {
        EtherCatError::Config(e)
    }
}

impl From<ResolveError> for EtherCatError {
    fn from(e: ResolveError) -> Self {
        EtherCatError::Links(e)
    }
}

fn bus(during: &'static str) -> impl FnOnce(CrabError) -> EtherCatError {
    move |error| EtherCatError::Bus { during, error }
}

enum Stage {
    Op(Group<Op>),
    SafeOp(Group<SafeOp>),
}

struct Running {
    maindevice: MainDevice<'static>,
    group: Option<Stage>,
    driver: Option<DriverGuard>,
    /// What ethercrab configured on each SubDevice, in ring order, to restore after a fault.
    configured: Vec<Configured>,
    /// When recovery was last tried.
    last_recovery: Option<std::time::Instant>,
}

impl Running {
    /// Stops the driver: ethercrab tells it to exit, then the guard is dropped.
    fn release(self) {
        let Running {
            maindevice,
            group,
            driver,
            ..
        } = self;
        drop(group);
        // SAFETY: no frame is in flight (every ethercrab call above was awaited to the end) and
        // the group configured with this MainDevice was dropped just above, so it is never
        // used with another MainDevice.
        let _ = unsafe { maindevice.release_all() };
        drop(driver);
    }
}

/// The EtherCAT backend for a `GlobalMemory` type `T`.
///
/// `new` checks the description and resolves `T`'s links (no bus traffic); `start` brings the
/// bus up: init, identity check, PRE-OP -> SAFE-OP, process data sizes checked against the
/// description, OP. `exchange` then runs one cycle: linked outputs from the struct into the
/// process data, one `tx_rx`, and, when the working counter is right and every SubDevice is in
/// OP, the linked inputs into the struct. Otherwise the inputs are flagged invalid and set as
/// [`InputsOnFault`] says, never left to look fresh. `fault` zeroes the outputs and drops to
/// SAFE-OP (a panicking program), where a later `stop` leaves the bus; otherwise `stop`
/// zeroes the outputs and returns to INIT.
///
/// Recovery: while the bus is faulty, `exchange` looks at each SubDevice every
/// [`Options::recovery_interval`] and brings back to OP the ones that answer again but are
/// not in OP: acknowledging an error (a tripped SyncManager watchdog leaves SAFE-OP with AL
/// status code 0x001B), or, for one that lost power and restarted in INIT, giving it its
/// station address and the SyncManager and FMMU settings ethercrab made at start-up again.
/// Inputs stay invalid until the whole bus is in OP with the right working counter. What is
/// still wrong is kept in [`problems`](Self::problems), one line per SubDevice, and printed
/// to stderr when it changes. After `fault` the backend stays in SAFE-OP: no recovery.
///
/// Implements `plc_io::IoBackend` (`start`, `exchange`, `fault`, `stop`) for
/// `plc_io::Runtime`.
///
/// Each started backend leaks ethercrab's frame storage (about 20 KiB): ethercrab needs it
/// `'static`, and a stopped bus may still see late frames.
pub struct EtherCatBackend<T> {
    config: BusConfig,
    layout: BusLayout,
    inputs: Vec<Binding>,
    outputs: Vec<Binding>,
    transport: Option<Transport>,
    options: Options,
    expected_wkc: u16,
    status: BusStatus,
    running: Option<Running>,
    problems: Vec<String>,
    _gm: PhantomData<fn(&mut T)>,
}

impl<T> fmt::Debug for EtherCatBackend<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("EtherCatBackend")
            .field("devices", &self.layout.names)
            .field("inputs", &self.inputs.len())
            .field("outputs", &self.outputs.len())
            .field("status", &self.status)
            .finish_non_exhaustive()
    }
}

impl<T: GlobalMemory> EtherCatBackend<T> {
    /// Checks `config` and resolves every link of `T` against it; nothing is sent yet.
    pub fn new(
        config: BusConfig,
        transport: Transport,
        options: Options,
    ) -> Result<Self, EtherCatError> {
        config.validate()?;
        let layout = BusLayout::new(&config);
        let bindings = resolve::<T>(&layout)?;
        let (inputs, outputs) = bindings
            .into_iter()
            .partition(|b| b.entry.direction == PdoDirection::Input);
        let expected_wkc = layout
            .devices
            .iter()
            .map(|d| u16::from(d.input_bytes > 0) + 2 * u16::from(d.output_bytes > 0))
            .sum();
        Ok(EtherCatBackend {
            config,
            layout,
            inputs,
            outputs,
            transport: Some(transport),
            options,
            expected_wkc,
            status: BusStatus {
                bus_fault: true,
                expected_working_counter: expected_wkc,
                ..BusStatus::default()
            },
            running: None,
            problems: Vec::new(),
            _gm: PhantomData,
        })
    }

    /// The bus description.
    pub fn config(&self) -> &BusConfig {
        &self.config
    }

    /// The resolved links, inputs then outputs.
    pub fn bindings(&self) -> impl Iterator<Item = &Binding> {
        self.inputs.iter().chain(&self.outputs)
    }

    /// The status of the last exchange.
    pub fn status(&self) -> BusStatus {
        self.status
    }

    /// Brings the bus to OP. On error the transport is closed again; a backend whose start
    /// failed cannot be started again (build a new one).
    pub fn start(&mut self) -> Result<(), EtherCatError> {
        if self.running.is_some() {
            return Err(EtherCatError::State("the EtherCAT bus is running already"));
        }
        let transport = self.transport.take().ok_or(EtherCatError::State(
            "this EtherCAT backend was started before: build a new one to start again",
        ))?;
        let storage: &'static PduStorage<MAX_FRAMES, MAX_PDU_DATA> =
            Box::leak(Box::new(PduStorage::new()));
        let (tx, rx, pdu_loop) = storage.try_split().map_err(|()| {
            EtherCatError::Transport("ethercrab's frame storage was split twice".into())
        })?;
        let driver = match transport {
            Transport::Interface(name) => spawn_interface(&name, tx, rx)?,
            Transport::Custom(start) => start(tx, rx).map_err(|e| {
                EtherCatError::Transport(format!("the EtherCAT transport did not start: {e}"))
            })?,
        };
        let maindevice = MainDevice::new(
            pdu_loop,
            self.options.timeouts,
            MainDeviceConfig {
                dc_static_sync_iterations: self.options.dc_static_sync_iterations,
                ..MainDeviceConfig::default()
            },
        );
        let mut running = Running {
            maindevice,
            group: None,
            driver: Some(driver),
            configured: Vec::new(),
            last_recovery: None,
        };
        match self.bring_up(&mut running) {
            Ok(()) => {
                self.running = Some(running);
                self.status = BusStatus {
                    state: BusState::Op,
                    expected_working_counter: self.expected_wkc,
                    ..BusStatus::default()
                };
                Ok(())
            }
            Err(e) => {
                running.release();
                Err(e)
            }
        }
    }

    fn bring_up(&self, running: &mut Running) -> Result<(), EtherCatError> {
        let md = &running.maindevice;
        let group = block_on(md.init_single_group::<MAX_SUBDEVICES, MAX_PDI>(now))
            .map_err(bus("scanning the bus (init to PRE-OP)"))?;
        let mut problems = Vec::new();
        let found: Vec<_> = group
            .iter(md)
            .map(|sd| (sd.name().to_owned(), sd.identity()))
            .collect();
        for (pos, want) in self.config.devices.iter().enumerate() {
            match found.get(pos) {
                None => problems.push(format!(
                    "position {pos}: expected `{}` ({}), found no SubDevice (the bus has {})",
                    want.name,
                    want.identity,
                    found.len()
                )),
                Some((name, id)) => {
                    let w = want.identity;
                    if id.vendor_id != w.vendor
                        || id.product_id != w.product
                        || w.revision.is_some_and(|r| r != id.revision)
                    {
                        problems.push(format!(
                            "position {pos}: expected `{}` ({}), found {name} (vendor {:#x}, \
                             product {:#010x}, revision {:#010x})",
                            want.name, w, id.vendor_id, id.product_id, id.revision
                        ));
                    }
                }
            }
        }
        for (pos, (name, id)) in found.iter().enumerate().skip(self.config.devices.len()) {
            problems.push(format!(
                "position {pos}: found {name} (vendor {:#x}, product {:#010x}), which the \
                 description does not list: add it",
                id.vendor_id, id.product_id
            ));
        }
        if !problems.is_empty() {
            return Err(EtherCatError::Identity(problems));
        }
        let group = block_on(group.into_safe_op(md)).map_err(bus("going to SAFE-OP"))?;
        let reported: Vec<(usize, usize)> = group
            .iter(md)
            .map(|sd| (sd.inputs_raw().len(), sd.outputs_raw().len()))
            .collect();
        self.layout
            .check_sizes(&reported)
            .map_err(EtherCatError::Layout)?;
        // Outputs are zero in ethercrab's fresh PDI; one exchange before OP makes the
        // SubDevices' outputs valid, as the SyncManager watchdogs expect.
        block_on(group.tx_rx(md)).map_err(bus("the first SAFE-OP exchange"))?;
        let group = block_on(group.into_op(md)).map_err(bus("going to OP"))?;
        let mut configured = Vec::new();
        for (pos, sd) in group.iter(md).enumerate() {
            let c = block_on(Configured::read(
                md,
                pos as u16,
                sd.configured_address(),
                sd.name(),
                (sd.identity().vendor_id, sd.identity().product_id),
            ))
            .map_err(bus("reading back the SyncManager and FMMU settings"))?;
            configured.push(c);
        }
        running.configured = configured;
        running.group = Some(Stage::Op(group));
        Ok(())
    }

    /// One cycle: see the type's documentation.
    pub fn exchange(&mut self, gm: &mut T) -> BusStatus {
        let Some(running) = self.running.as_mut() else {
            self.status.inputs_valid = false;
            self.status.bus_fault = true;
            self.status.state = BusState::Stopped;
            return self.status;
        };
        let md = &running.maindevice;
        let result = match &running.group {
            Some(Stage::Op(g)) => cycle(g, md, gm, &self.outputs),
            Some(Stage::SafeOp(g)) => cycle(g, md, gm, &self.outputs),
            None => Err(CrabError::Internal),
        };
        let (wkc, state) = match result {
            Ok(r) => (r.working_counter, state_of(&r.subdevice_states)),
            Err(_) => (0, BusState::NoAnswer),
        };
        let good = wkc == self.expected_wkc && state == BusState::Op;
        if good {
            if let Some(Stage::Op(g)) = &running.group {
                copy_inputs(g, md, gm, &self.inputs);
            }
            self.set_problems(Vec::new());
        } else {
            self.status.fault_count += 1;
            if self.options.inputs_on_fault == InputsOnFault::Zero {
                zero_inputs(gm, &self.inputs);
            }
            let running = self.running.as_mut().expect("checked above");
            let due = running
                .last_recovery
                .is_none_or(|t| t.elapsed() >= self.options.recovery_interval);
            let in_op_stage = matches!(running.group, Some(Stage::Op(_)));
            if state == BusState::NoAnswer {
                self.set_problems(vec![
                    "no frame came back from the bus: check the cable from the network \
                     interface to the first SubDevice, and its power"
                        .into(),
                ]);
            } else if due && in_op_stage {
                running.last_recovery = Some(std::time::Instant::now());
                let problems = recover(running, &self.layout.names, self.options.timeouts.eeprom);
                self.set_problems(problems);
            }
        }
        self.status.inputs_valid = good;
        self.status.bus_fault = !good;
        self.status.state = state;
        self.status.working_counter = wkc;
        self.status
    }

    /// What is wrong with the bus now, one line per SubDevice that is not in OP (naming its
    /// position, name and model, its state and AL status code, and what was done or what to
    /// do). Empty while the bus is healthy. It changes only after a recovery attempt
    /// ([`Options::recovery_interval`]); each change is also printed to stderr.
    pub fn problems(&self) -> &[String] {
        &self.problems
    }

    fn set_problems(&mut self, problems: Vec<String>) {
        if problems == self.problems {
            return;
        }
        if problems.is_empty() {
            eprintln!("plc-io EtherCAT: the bus is back in OP");
        } else {
            for p in &problems {
                eprintln!("plc-io EtherCAT: {p}");
            }
        }
        self.problems = problems;
    }

    /// The panic path: outputs to zero on the bus, then SAFE-OP (the SubDevices hold their
    /// outputs safe and keep updating inputs). Later exchanges report the fault.
    pub fn fault(&mut self) {
        let Some(running) = self.running.as_mut() else {
            return;
        };
        let md = &running.maindevice;
        running.group = match running.group.take() {
            Some(Stage::Op(g)) => {
                zero_outputs(&g, md);
                let _ = block_on(g.tx_rx(md));
                match block_on(g.into_safe_op(md)) {
                    Ok(g) => Some(Stage::SafeOp(g)),
                    Err(_) => None,
                }
            }
            other => other,
        };
        self.status.bus_fault = true;
        self.status.inputs_valid = false;
        self.status.state = BusState::SafeOp;
    }

    /// Outputs to zero, the bus back to INIT, the transport closed. After [`fault`](Self::fault)
    /// the SubDevices stay in SAFE-OP (outputs off and zero, inputs still readable by a
    /// diagnostic tool): a program that panicked leaves the bus in its safe state rather
    /// than looking like a clean shutdown. Safe to call twice.
    pub fn stop(&mut self) {
        let Some(mut running) = self.running.take() else {
            return;
        };
        let md = &running.maindevice;
        match running.group.take() {
            Some(Stage::Op(g)) => {
                zero_outputs(&g, md);
                let _ = block_on(g.tx_rx(md));
                if let Ok(g) = block_on(g.into_safe_op(md)) {
                    zero_outputs(&g, md);
                    let _ = block_on(g.tx_rx(md));
                    if let Ok(g) = block_on(g.into_pre_op(md)) {
                        let _ = block_on(g.into_init(md));
                    }
                }
            }
            Some(Stage::SafeOp(g)) => {
                zero_outputs(&g, md);
                let _ = block_on(g.tx_rx(md));
            }
            None => {}
        }
        running.release();
        self.status = BusStatus {
            bus_fault: true,
            expected_working_counter: self.expected_wkc,
            fault_count: self.status.fault_count,
            ..BusStatus::default()
        };
    }
}

impl<T> Drop for EtherCatBackend<T> {
    fn drop(&mut self) {
        if let Some(running) = self.running.take() {
            // Dropped without `stop` (e.g. a panic unwinding): the SubDevices' watchdogs
            // take them to SAFE-OP once frames stop; close the transport.
            running.release();
        }
    }
}

fn now() -> u64 {
    ethercrab::std::ethercat_now()
}

fn spawn_interface(
    name: &str,
    tx: PduTx<'static>,
    rx: PduRx<'static>,
) -> Result<DriverGuard, EtherCatError> {
    let task = ethercrab::std::tx_rx_task(name, tx, rx).map_err(|e| {
        let hint = match e.kind() {
            std::io::ErrorKind::PermissionDenied => {
                " (raw sockets need root or CAP_NET_RAW: `sudo setcap cap_net_raw=ep <program>`, \
                 or run without --interface for the simulated bus)"
            }
            std::io::ErrorKind::NotFound => " (no such interface: see `ip link`)",
            _ => "",
        };
        EtherCatError::Transport(format!("cannot open network interface `{name}`: {e}{hint}"))
    })?;
    let handle = std::thread::Builder::new()
        .name(format!("ethercat-{name}"))
        .spawn(move || block_on(task).map(|_| ()))
        .map_err(|e| EtherCatError::Transport(format!("cannot start the EtherCAT thread: {e}")))?;
    Ok(Box::new(JoinOnDrop(Some(handle))))
}

/// Joins the transport thread when dropped (after ethercrab told it to exit).
struct JoinOnDrop(Option<std::thread::JoinHandle<Result<(), CrabError>>>);

impl Drop for JoinOnDrop {
    fn drop(&mut self) {
        if let Some(h) = self.0.take() {
            let _ = h.join();
        }
    }
}

/// One recovery attempt on every SubDevice (see `recovery`); the problems that remain.
fn recover(
    running: &Running,
    names: &[String],
    eeprom_timeout: std::time::Duration,
) -> Vec<String> {
    let md = &running.maindevice;
    let mut problems = Vec::new();
    let mut cut_off = false;
    for dev in &running.configured {
        let pos = usize::from(dev.position);
        let what = format!(
            "position {pos} (`{}`, {})",
            names.get(pos).map_or("?", String::as_str),
            dev.model
        );
        match block_on(recovery::attempt(md, dev, eeprom_timeout)) {
            Outcome::Op => {}
            Outcome::NotOp(text) => problems.push(format!(
                "{what} is {text}; inputs stay invalid until it is back in OP"
            )),
            Outcome::NoAnswer => {
                // Frames turn back before a device whose link is down, so every device behind
                // it is silent too: name the first one, where the cable or power is to check.
                if !cut_off {
                    cut_off = true;
                    let behind = if pos + 1 < running.configured.len() {
                        " (the SubDevices behind it are cut off too)"
                    } else {
                        ""
                    };
                    problems.push(format!(
                        "{what} does not answer: check its power and the cable into it{behind}; \
                         it is brought back to OP when it answers again"
                    ));
                }
            }
        }
    }
    problems
}

fn state_of(states: &[SubDeviceState]) -> BusState {
    let mut it = states.iter();
    let Some(first) = it.next() else {
        return BusState::NoAnswer;
    };
    if it.any(|s| s != first) {
        return BusState::Mixed;
    }
    match first {
        SubDeviceState::Init => BusState::Init,
        SubDeviceState::PreOp => BusState::PreOp,
        SubDeviceState::SafeOp => BusState::SafeOp,
        SubDeviceState::Op => BusState::Op,
        _ => BusState::Mixed,
    }
}

fn cycle<S: HasPdi, T: GlobalMemory>(
    g: &Group<S>,
    md: &MainDevice<'static>,
    gm: &T,
    outputs: &[Binding],
) -> Result<ethercrab::TxRxResponse<MAX_SUBDEVICES>, CrabError> {
    write_outputs(g, md, gm, outputs);
    block_on(g.tx_rx(md))
}

fn write_outputs<S: HasPdi, T: GlobalMemory>(
    g: &Group<S>,
    md: &MainDevice<'static>,
    gm: &T,
    outputs: &[Binding],
) {
    // Bindings are grouped by device in resolution order; take each device's guard once per
    // run of bindings.
    let mut i = 0;
    while i < outputs.len() {
        let dev = outputs[i].entry.device;
        let end = outputs[i..]
            .iter()
            .position(|b| b.entry.device != dev)
            .map_or(outputs.len(), |n| i + n);
        if let Ok(sd) = g.subdevice(md, dev) {
            let mut out = sd.outputs_raw_mut();
            for b in &outputs[i..end] {
                if let Some(v) = gm.try_get(b.var, 0) {
                    write_bits(
                        &mut out,
                        b.entry.bit_offset,
                        b.entry.bits,
                        encode(v, b.entry.iec_type),
                    );
                }
            }
        }
        i = end;
    }
}

fn copy_inputs<S: HasPdi, T: GlobalMemory>(
    g: &Group<S>,
    md: &MainDevice<'static>,
    gm: &mut T,
    inputs: &[Binding],
) {
    let mut i = 0;
    while i < inputs.len() {
        let dev = inputs[i].entry.device;
        let end = inputs[i..]
            .iter()
            .position(|b| b.entry.device != dev)
            .map_or(inputs.len(), |n| i + n);
        if let Ok(sd) = g.subdevice(md, dev) {
            let data = sd.inputs_raw();
            for b in &inputs[i..end] {
                let raw = read_bits(&data, b.entry.bit_offset, b.entry.bits);
                // Resolution checked that the entry's type widens to the variable's, so the
                // value always fits.
                let _ = gm.set(b.var, 0, decode(raw, b.entry.iec_type, b.entry.bits));
            }
        }
        i = end;
    }
}

fn zero_inputs<T: GlobalMemory>(gm: &mut T, inputs: &[Binding]) {
    for b in inputs {
        let zero = match b.var_type.family() {
            TypeFamily::Bool => Value::Bool(false),
            TypeFamily::Real => Value::Real(0.0),
            _ => Value::UInt(0),
        };
        let _ = gm.set(b.var, 0, zero);
    }
}

fn zero_outputs<S: HasPdi>(g: &Group<S>, md: &MainDevice<'static>) {
    for sd in g.iter(md) {
        sd.outputs_raw_mut().fill(0);
    }
}

/// A raw entry value as a [`Value`] of the entry's type.
fn decode(raw: u64, ty: IecType, bits: u32) -> Value {
    match ty.family() {
        TypeFamily::Bool => Value::Bool(raw & 1 != 0),
        TypeFamily::SignedInt => {
            let shift = 64 - bits;
            Value::Int(((raw << shift) as i64) >> shift)
        }
        TypeFamily::Real if ty == IecType::Real => {
            Value::Real(f64::from(f32::from_bits(raw as u32)))
        }
        TypeFamily::Real => Value::Real(f64::from_bits(raw)),
        _ => Value::UInt(raw),
    }
}

/// A variable's value as the raw bits of an entry of type `ty` (the caller masks to the width).
fn encode(v: Value, ty: IecType) -> u64 {
    let real = |f: f64| match ty {
        IecType::Real => u64::from((f as f32).to_bits()),
        _ => f.to_bits(),
    };
    match (v, ty.family()) {
        (Value::Bool(b), _) => u64::from(b),
        (Value::Int(i), TypeFamily::Real) => real(i as f64),
        (Value::UInt(u), TypeFamily::Real) => real(u as f64),
        (Value::Real(f), TypeFamily::Real) => real(f),
        (Value::Int(i), _) => i as u64,
        (Value::UInt(u), _) => u,
        (Value::Real(_) | Value::Text(_), _) => 0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_round_trip_through_raw_bits() {
        assert_eq!(
            decode(encode(Value::Int(-3), IecType::Int), IecType::Int, 16),
            Value::Int(-3)
        );
        assert_eq!(decode(0xfff0, IecType::Int, 16), Value::Int(-16));
        assert_eq!(
            decode(encode(Value::Real(1.5), IecType::Real), IecType::Real, 32),
            Value::Real(1.5)
        );
        assert_eq!(
            decode(encode(Value::UInt(7), IecType::Lreal), IecType::Lreal, 64),
            Value::Real(7.0)
        );
        assert_eq!(decode(1, IecType::Bool, 1), Value::Bool(true));
        assert_eq!(decode(0b1010, IecType::Uint, 4), Value::UInt(10));
    }

    #[test]
    fn bus_state_of_mixed_and_uniform_states() {
        use SubDeviceState::*;
        assert_eq!(state_of(&[Op, Op]), BusState::Op);
        assert_eq!(state_of(&[Op, SafeOp]), BusState::Mixed);
        assert_eq!(state_of(&[]), BusState::NoAnswer);
    }
}
