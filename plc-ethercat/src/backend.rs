//! The EtherCAT I/O backend: ethercrab's MainDevice driving one group of SubDevices, moving the
//! linked variables of a `GlobalMemory` struct to and from the process data each cycle. The
//! steps live beside it: `transport` (frames), `bringup` (to OP), `dc` (distributed clocks),
//! `group` (ethercrab's group with or without them), `process_data` (the variables),
//! `recovery` (back to OP after a fault), `status` (what an exchange counts).

use super::bringup::{Up, bring_up};
use super::config::{BusConfig, PdoDirection};
use super::dc::{DcDevice, largest_difference};
use super::error::EtherCatError;
use super::group::Group;
use super::layout::BusLayout;
use super::options::{DriverGuard, InputsOnFault, Options, Transport};
use super::process_data::{copy_inputs, cycle, zero_inputs, zero_outputs};
use super::recovery::{Configured, RecoveryTimer, recover};
use super::resolve::{Binding, resolve_vars};
use super::status::{BusStatus, DcStatus};
use async_io::block_on;
use ethercrab::MainDevice;
use ethercrab::subdevice_group::{HasPdi, Op, SafeOp};
use plc_core::GlobalMemory;
use plc_core::memory::{Memory, Schema};
use plc_runtime::CyclePhase;
use plc_shm::BusState;
use std::fmt;
use std::marker::PhantomData;
use std::time::{Duration, Instant};

enum Stage {
    Op(Group<Op>),
    SafeOp(Group<SafeOp>),
}

struct Running {
    maindevice: MainDevice<'static>,
    group: Option<Stage>,
    driver: Option<DriverGuard>,
    frame_thread: super::transport::FrameThread,
    /// What ethercrab configured on each SubDevice, in ring order, to restore after a fault.
    configured: Vec<Configured>,
    recovery: RecoveryTimer,
    /// The SubDevices configured for SYNC0 (empty without distributed clocks).
    dc_devices: Vec<DcDevice>,
    /// When their system time differences are read next.
    dc_check: RecoveryTimer,
    /// The description's SYNC0 shift: where the cycle's frame should pass the reference
    /// clock after SYNC0 (the runtime's cycle follows it, [`EtherCatBackend::cycle_phase`]).
    sync0_shift: Duration,
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
        // The frame loop handed back could serve a new MainDevice; a stopped backend makes
        // none (a new start leaks fresh storage), so it is not kept.
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
/// still wrong is kept in [`problems`](Self::problems), one line per SubDevice, and logged
/// (the `log` crate, target `plc_ethercat`) when it changes. After `fault` the backend stays in SAFE-OP: no recovery.
///
/// Distributed clocks: where the description gives devices `dc` (`DcConfig`), `start`
/// refuses any of them without a DC unit ([`EtherCatError::DistributedClocks`], naming it),
/// sets SYNC0 on them in PRE-OP with the description's period and shift (SYNC0 starts
/// 100 ms after configuration, on a whole period), exchanges on the
/// DC time until every SubDevice is in OP, and each `exchange` is then one `tx_rx_dc`, which
/// also distributes the reference clock's time. [`BusStatus::dc`] tells the largest system
/// time difference and the cycle's offset to SYNC0; [`check_period`](Self::check_period)
/// the cycle periods SYNC0 allows; [`cycle_phase`](Self::cycle_phase) where the frame fell
/// against SYNC0, which `plc_runtime::Runtime` follows so the cycle runs on the DC time.
/// Recovery gives a DC SubDevice that restarted after a power loss its clock offset and SYNC0
/// again in PRE-OP (the description's period, starting 100 ms later on a whole period of
/// the reference clock's time, as at start-up) before it goes on to SAFE-OP and OP. Not
/// recovered: a restart of the reference clock itself (the first SubDevice with a DC unit),
/// whose time starts afresh; the other clocks follow it at their loops' pace.
///
/// Implements `plc_runtime::IoBackend` (`start`, `exchange`, `fault`, `stop`,
/// `check_period`, `cycle_phase`) for `plc_runtime::Runtime` (`plc_io::Runtime` in a
/// control program).
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
    /// The last exchange's phase against SYNC0 (`None` when it measured none).
    phase: Option<CyclePhase>,
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

impl<T: GlobalMemory + Memory> EtherCatBackend<T> {
    /// Checks `config` and resolves every link of `T` against it; nothing is sent yet.
    pub fn new(
        config: BusConfig,
        transport: Transport,
        options: Options,
    ) -> Result<Self, EtherCatError> {
        Self::for_schema(config, transport, options, &Schema::of::<T>())
    }
}

impl<T: Memory> EtherCatBackend<T> {
    /// [`new`](Self::new) for a program whose variables `schema` describes (a host's loaded
    /// module, known only at run time).
    pub fn for_schema(
        config: BusConfig,
        transport: Transport,
        options: Options,
        schema: &Schema,
    ) -> Result<Self, EtherCatError> {
        config.validate()?;
        let layout = BusLayout::new(&config);
        let bindings = resolve_vars(schema.variables, &layout)?;
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
            status: BusStatus::stopped(expected_wkc, 0),
            running: None,
            problems: Vec::new(),
            phase: None,
            _gm: PhantomData,
        })
    }

    /// Binds the links of the variables `schema` describes (a new build of the program taking
    /// over) to the entries of the running bus: links may move between its entries, and a
    /// link to a device or entry the bus does not have is refused, naming it (a new device
    /// or PDO needs a restart). On a refusal the bindings stay as they were.
    pub fn rebind(&mut self, schema: &Schema) -> Result<(), EtherCatError> {
        let bindings = resolve_vars(schema.variables, &self.layout)?;
        let (inputs, outputs) = bindings
            .into_iter()
            .partition(|b| b.entry.direction == PdoDirection::Input);
        self.inputs = inputs;
        self.outputs = outputs;
        Ok(())
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

    /// Checks that a cycle of `period` fits the description's distributed clocks: SYNC0 a
    /// whole multiple of the period, so every pulse meets the same point of a cycle. Any
    /// period fits a bus without `dc`. `plc_runtime::RuntimeBuilder::build` asks it (through
    /// `IoBackend::check_period`) before anything starts.
    pub fn check_period(&self, period: std::time::Duration) -> Result<(), EtherCatError> {
        let dc = self.config.dc();
        match dc.and_then(|dc| super::dc::period_problem(dc, period)) {
            Some(problem) => Err(EtherCatError::Period(problem)),
            None => Ok(()),
        }
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
        let (maindevice, driver, frame_thread) = super::transport::open(transport, &self.options)?;
        let mut running = Running {
            maindevice,
            group: None,
            driver: Some(driver),
            frame_thread,
            configured: Vec::new(),
            recovery: RecoveryTimer::new(self.options.recovery_interval),
            dc_devices: Vec::new(),
            dc_check: RecoveryTimer::new(self.options.dc_check_interval),
            sync0_shift: Duration::ZERO,
        };
        let dc = self.config.dc();
        if let Some(dc) = dc {
            // Validation keeps the shift within 0..sync0.
            running.sync0_shift = Duration::from_nanos(dc.shift.as_nanos().max(0) as u64);
        }
        let up = bring_up(
            &running.maindevice,
            &self.config.devices,
            &self.layout,
            dc,
            self.options.timeouts.state_transition,
        );
        match up {
            Ok(Up {
                group,
                mut configured,
                dc_devices,
            }) => {
                // What recovery needs to set up a restarted DC device's SYNC0 again.
                let recorded = match dc {
                    Some(dc) if !dc_devices.is_empty() => super::dc::record_for_recovery(
                        &group,
                        &running.maindevice,
                        &dc_devices,
                        dc,
                        &mut configured,
                    ),
                    _ => Ok(()),
                };
                if let Err(e) = recorded {
                    drop(group);
                    running.release();
                    return Err(e);
                }
                let dc_status = dc.filter(|_| !dc_devices.is_empty()).map(|dc| DcStatus {
                    // Validation keeps sync0 within u32 nanoseconds.
                    sync0_period_ns: u32::try_from(dc.sync0.as_nanos()).unwrap_or(u32::MAX),
                    ..DcStatus::default()
                });
                running.group = Some(Stage::Op(group));
                running.configured = configured;
                running.dc_devices = dc_devices;
                self.running = Some(running);
                self.status = BusStatus {
                    state: BusState::Op,
                    expected_working_counter: self.expected_wkc,
                    dc: dc_status,
                    ..BusStatus::default()
                };
                Ok(())
            }
            Err(e) => {
                let ended = running.frame_thread.ended();
                running.release();
                Err(match ended {
                    Some(problem) => {
                        EtherCatError::Transport(format!("{problem} (while bringing it up: {e})"))
                    }
                    None => e,
                })
            }
        }
    }

    /// One cycle: see the type's documentation.
    pub fn exchange(&mut self, gm: &mut T) -> BusStatus {
        // Only this exchange's measurement counts: an old one would be corrected for twice.
        self.phase = None;
        let Some(running) = self.running.as_mut() else {
            self.status.inputs_valid = false;
            self.status.bus_fault = true;
            self.status.state = BusState::Stopped;
            return self.status;
        };
        let md = &running.maindevice;
        // Any error of the exchange (a lost frame, a timeout) means no answer this cycle: it
        // is counted and reported as such below.
        let answer = match &running.group {
            Some(Stage::Op(g)) => cycle(g, md, gm, &self.outputs),
            Some(Stage::SafeOp(g)) => cycle(g, md, gm, &self.outputs),
            None => Err(ethercrab::error::Error::Internal),
        }
        .ok();
        if let (Some(dc), Some(cycle)) = (
            self.status.dc.as_mut(),
            answer.as_ref().and_then(|a| a.cycle),
        ) {
            dc.sync0_offset_ns =
                u64::try_from(cycle.cycle_start_offset.as_nanos()).unwrap_or(u64::MAX);
            self.phase = Some(CyclePhase {
                offset: cycle.cycle_start_offset,
                target: running.sync0_shift,
            });
            if running.dc_check.due(Instant::now()) {
                dc.max_time_difference_ns = largest_difference(md, &running.dc_devices);
            }
        }
        let answer = answer.map(|a| (a.working_counter, a.state));
        if self.status.record(answer) {
            if let Some(Stage::Op(g)) = &running.group {
                copy_inputs(g, md, gm, &self.inputs);
            }
            self.set_problems(Vec::new());
            return self.status;
        }
        if self.options.inputs_on_fault == InputsOnFault::Zero {
            zero_inputs(gm, &self.inputs);
        }
        let in_op_stage = matches!(running.group, Some(Stage::Op(_)));
        if self.status.state == BusState::NoAnswer {
            let problem = running.frame_thread.ended().unwrap_or_else(|| {
                "no frame came back from the bus: check the cable from the network interface \
                 to the first SubDevice, and its power"
                    .into()
            });
            self.set_problems(vec![problem]);
        } else if in_op_stage
            && running.recovery.due(Instant::now())
            && let Some(Stage::Op(g)) = &running.group
        {
            let devices = &self.config.devices;
            // A restarted device lost its start-up SDOs with its power: written again in
            // PRE-OP, through ethercrab's CoE on the group's handle of that device.
            let pre_op = async |pos: u16| -> Result<(), String> {
                let pos = usize::from(pos);
                match devices.get(pos) {
                    Some(d) if !d.startup.is_empty() => {
                        let sd = g.subdevice(md, pos).map_err(|e| e.to_string())?;
                        super::startup::write(&sd, pos, d)
                            .await
                            .map_err(|e| e.to_string())
                    }
                    _ => Ok(()),
                }
            };
            let problems = recover(
                md,
                &running.configured,
                &self.layout.names,
                self.options.timeouts.eeprom,
                &pre_op,
            );
            self.set_problems(problems);
        }
        self.status
    }

    /// Where the last exchange's frame passed the DC reference clock after SYNC0
    /// ([`CyclePhase::offset`], ethercrab's `CycleInfo::cycle_start_offset`) and where it
    /// should pass (the description's `shift`), on a bus with SYNC0 whose last exchange came
    /// back; `None` otherwise. `plc_runtime::Runtime` moves its next deadline towards it each
    /// cycle (`IoBackend::cycle_phase`), so the cycle runs on the DC time: its frame leaves
    /// `shift` after each SYNC0 pulse, give or take the machine's jitter, instead of wandering
    /// through the SYNC0 period as the host's and the reference clock's crystals differ.
    pub fn cycle_phase(&self) -> Option<CyclePhase> {
        self.phase
    }

    /// What is wrong with the bus now, one line per SubDevice that is not in OP (naming its
    /// position, name and model, its state and AL status code, and what was done or what to
    /// do). Empty while the bus is healthy. It changes only after a recovery attempt
    /// ([`Options::recovery_interval`]); each change is also logged.
    pub fn problems(&self) -> &[String] {
        &self.problems
    }

    fn set_problems(&mut self, problems: Vec<String>) {
        if problems == self.problems {
            return;
        }
        if problems.is_empty() {
            log::info!(target: "plc_io::ethercat", "plc-io EtherCAT: the bus is back in OP");
        } else {
            for p in &problems {
                log::warn!(target: "plc_io::ethercat", "plc-io EtherCAT: {p}");
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
                send_zero_outputs(&g, md, "OP");
                match block_on(g.into_safe_op(md)) {
                    Ok(g) => Some(Stage::SafeOp(g)),
                    Err(e) => {
                        // The SubDevices' watchdogs take them to SAFE-OP once frames stop.
                        log::error!(target: "plc_io::ethercat", "plc-io EtherCAT: the bus did not go to SAFE-OP: {e}");
                        None
                    }
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
        self.phase = None;
        let Some(mut running) = self.running.take() else {
            return;
        };
        let md = &running.maindevice;
        match running.group.take() {
            Some(Stage::Op(g)) => {
                send_zero_outputs(&g, md, "OP");
                let to_init = block_on(g.into_safe_op(md))
                    .inspect(|g| send_zero_outputs(g, md, "SAFE-OP"))
                    .and_then(|g| block_on(g.into_pre_op(md)))
                    .and_then(|g| block_on(g.into_init(md)));
                if let Err(e) = to_init {
                    // The transport closes anyway; the watchdogs take over from here.
                    log::warn!(target: "plc_io::ethercat", "plc-io EtherCAT: the bus did not go back to INIT: {e}");
                }
            }
            Some(Stage::SafeOp(g)) => send_zero_outputs(&g, md, "SAFE-OP"),
            None => {}
        }
        running.release();
        self.status = BusStatus::stopped(self.expected_wkc, self.status.fault_count);
    }
}

/// Zero outputs on the bus, in one exchange.
fn send_zero_outputs<S: HasPdi>(g: &Group<S>, md: &MainDevice<'static>, stage: &str) {
    zero_outputs(g, md);
    if let Err(e) = block_on(g.exchange(md)) {
        // The state change that follows still turns the outputs off.
        log::warn!(target: "plc_io::ethercat", "plc-io EtherCAT: the zero outputs were not sent in {stage}: {e}");
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
