//! The cycle: `Runtime` runs a program's tick at a fixed period with its I/O, shared memory and
//! retained variables.

mod alarm_commands;
pub mod alarm_journal;
mod alarms;
mod backend;
mod change;
mod clock;
mod context;
mod cycle;
pub(crate) mod placement;
mod private_dir;
#[cfg(feature = "cycle-probe")]
pub mod probe;
pub mod retain;
mod schedule;
mod started;
mod stats;
mod swap;

pub use alarms::{AlarmActionError, RuntimeAlarms};
pub use backend::{CyclePhase, IoBackend, IoError, IoStatus, NoIo};
pub use change::{Convert, Swap, SwapEvent};
pub use context::Context;
pub use plc_shm::{BusState, CycleStats};

use cycle::Cycle;

use crate::alarm_journal::JournalError;
use crate::retain::RetainError;
use plc_core::memory::Memory;
use plc_core::{Direction, GlobalMemory, Value};
use plc_shm::ShmError;
use std::fmt;
use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

/// Why the runtime stopped with an error.
#[derive(Debug)]
pub enum RuntimeError {
    /// The I/O backend did not start.
    Io(IoError),
    /// The shared-memory segment could not be created.
    Shm(ShmError),
    /// The retain file could not be loaded.
    Retain(RetainError),
    /// The retained values could not be saved when the program stopped: the file holds those
    /// of the last save that succeeded.
    RetainNotSaved(RetainError),
    /// Realtime scheduling was asked for but not permitted.
    Realtime(String),
    /// An alarm's declaration cannot be followed in this program (a `suppress_when` path
    /// that names no bool): the message names the alarm and the path.
    Alarm(String),
    /// The alarm journal could not be opened (a link or another user's file in its place,
    /// a file too large to be a journal, a directory that cannot be made).
    AlarmJournal(JournalError),
    /// The cycle could not be placed on the CPU asked for
    /// ([`RuntimeBuilder::cpu`]): the message names it and the CPUs the process may use.
    Cpu(String),
    /// The program panicked in its tick: outputs were zeroed and the I/O put in a safe state.
    Panicked {
        /// The cycle it panicked in.
        cycle: u64,
        /// The panic message.
        message: String,
    },
}

impl fmt::Display for RuntimeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RuntimeError::Io(e) => write!(f, "I/O did not start: {e}"),
            RuntimeError::Shm(e) => write!(f, "{e}"),
            RuntimeError::Retain(e) => write!(f, "{e}"),
            RuntimeError::RetainNotSaved(e) => write!(
                f,
                "the retained values were not saved at stop: {e}; the file keeps the values of \
                 the last save that succeeded"
            ),
            RuntimeError::Realtime(e) | RuntimeError::Cpu(e) | RuntimeError::Alarm(e) => {
                write!(f, "{e}")
            }
            RuntimeError::AlarmJournal(e) => write!(f, "{e}"),
            RuntimeError::Panicked { cycle, message } => write!(
                f,
                "the program panicked in cycle {cycle}: {message}; outputs were set to zero and \
                 the I/O put in a safe state"
            ),
        }
    }
}

impl std::error::Error for RuntimeError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            RuntimeError::Io(e) => Some(e),
            RuntimeError::Shm(e) => Some(e),
            RuntimeError::Retain(e) | RuntimeError::RetainNotSaved(e) => Some(e),
            RuntimeError::AlarmJournal(e) => Some(e),
            RuntimeError::Realtime(_)
            | RuntimeError::Cpu(_)
            | RuntimeError::Alarm(_)
            | RuntimeError::Panicked { .. } => None,
        }
    }
}

/// Stops a running [`Runtime`] from another thread (or a signal).
#[derive(Clone, Debug, Default)]
pub struct StopHandle(Arc<AtomicBool>);

impl StopHandle {
    /// Asks the runtime to stop after the current cycle.
    pub fn stop(&self) {
        self.0.store(true, Ordering::Release);
    }

    /// Whether a stop was asked for.
    pub fn is_stopped(&self) -> bool {
        self.0.load(Ordering::Acquire)
    }

    /// Makes SIGINT (Ctrl-C) and SIGTERM ask for a stop instead of ending the process at once,
    /// so the program (a runtime, or a tool such as `plc log`) can finish cleanly: save, flush,
    /// release its I/O. A second signal while the stop is still pending ends the process at
    /// once with exit code 1: the way out of a cycle that never returns (retained values keep
    /// their last save, which is always whole).
    pub fn stop_on_signals(&self) -> std::io::Result<()> {
        plc_shm::stop_on_signals(&self.0)
    }
}

/// Settings of a [`Runtime`].
pub struct RuntimeBuilder<T> {
    /// The variables before the first cycle (before retained values are loaded).
    initial: T,
    period: Duration,
    segment: Option<String>,
    sharing: plc_shm::Sharing,
    retain: Option<PathBuf>,
    retain_interval: Duration,
    alarm_journal: Option<PathBuf>,
    alarm_capacity: usize,
    max_shelve: plc_core::Time,
    backend: Box<dyn IoBackend<T> + Send>,
    swaps: Option<std::sync::mpsc::Receiver<Swap<T>>>,
    realtime: Option<i32>,
    cpu: Option<usize>,
    max_cycles: Option<u64>,
    signals: bool,
    stop: StopHandle,
    #[cfg(feature = "cycle-probe")]
    probe: Option<probe::Probe>,
}

/// Runs a program's cycle: exchange I/O, unpack bits, apply the requests tools sent, the
/// program's tick, pack bits, publish to shared memory, hand changed nonvolatile values to the
/// retain writer.
///
/// ```no_run
/// use plc_core::GlobalMemory;
/// use plc_runtime::Runtime;
/// use std::time::Duration;
///
/// #[derive(GlobalMemory, Debug, Clone)]
/// struct Gm {
///     #[plc(nonvolatile)]
///     count: u64,
/// }
///
/// Runtime::<Gm>::builder()
///     .period(Duration::from_millis(10))
///     .segment("counter")
///     .retain("counter.retain")
///     .build()?
///     .run(|ctx| ctx.gm.count += 1)?;
/// # Ok::<(), plc_runtime::RuntimeError>(())
/// ```
pub struct Runtime<T> {
    settings: RuntimeBuilder<T>,
}

impl<T: GlobalMemory + Memory + Default> Runtime<T> {
    /// Settings with a 10 ms period, no segment, no retain file, no I/O, Ctrl-C/SIGTERM handled.
    pub fn builder() -> RuntimeBuilder<T> {
        Runtime::for_memory(T::default())
    }
}

impl<T: Memory> Runtime<T> {
    /// [`builder`](Self::builder)'s settings for variables that start as `initial`: a
    /// program whose variables are known only at run time (a host's loaded module) starts
    /// here; a compiled one starts from its initial values with `builder`.
    pub fn for_memory(initial: T) -> RuntimeBuilder<T> {
        RuntimeBuilder {
            initial,
            period: Duration::from_millis(10),
            segment: None,
            sharing: plc_shm::Sharing::new(),
            retain: None,
            retain_interval: Duration::from_millis(1000),
            alarm_journal: None,
            alarm_capacity: alarm_journal::DEFAULT_CAPACITY,
            max_shelve: plc_core::alarm::DEFAULT_MAX_SHELVE,
            backend: Box::new(NoIo),
            swaps: None,
            realtime: None,
            cpu: None,
            max_cycles: None,
            signals: true,
            stop: StopHandle::default(),
            #[cfg(feature = "cycle-probe")]
            probe: None,
        }
    }
}

impl<T: Memory> RuntimeBuilder<T> {
    /// The cycle period. Each cycle is due one period after the last one's deadline, an
    /// absolute time on the monotonic clock slept to with no timer slack; a late cycle is
    /// followed at once, with no burst of catch-up cycles. With an I/O that keeps a clock of
    /// its own (EtherCAT with distributed clocks) the deadlines follow that clock: each moves
    /// by at most a sixteenth of the period ([`IoBackend::cycle_phase`]).
    pub fn period(mut self, period: Duration) -> Self {
        self.period = period;
        self
    }
    /// Publishes the variables in shared-memory segment `name`.
    pub fn segment(mut self, name: impl Into<String>) -> Self {
        self.segment = Some(name.into());
        self
    }
    /// Lets the members of system group `group` read the segment's variables (connect to its
    /// socket; the runtime directory becomes mode 0750 and the socket 0660, of that group).
    /// Without it only the program's own user (and root) reads. The name is resolved when
    /// the runtime starts: an unknown group stops the start with an error naming it.
    pub fn read_group(mut self, group: impl Into<String>) -> Self {
        self.sharing = self.sharing.read_group(group);
        self
    }
    /// Lets the members of system group `group` write the variables that may be written from
    /// outside (commands, read-write internals). Without it only the program's own uid writes;
    /// any other writer is refused with a message naming this rule. Members must be able to
    /// connect too: without a [`read_group`](Self::read_group) this group is also the reading
    /// group; with one, they must be in both.
    ///
    /// ```no_run
    /// # use plc_core::GlobalMemory;
    /// # #[derive(GlobalMemory, Debug, Clone)]
    /// # struct Gm { #[plc(direction = "command")] speed: f32 }
    /// plc_runtime::Runtime::<Gm>::builder()
    ///     .segment("press")
    ///     .read_group("plc-viewers")
    ///     .write_group("plc-operators")
    ///     .build()?
    ///     .run(|_| {})?;
    /// # Ok::<(), plc_runtime::RuntimeError>(())
    /// ```
    pub fn write_group(mut self, group: impl Into<String>) -> Self {
        self.sharing = self.sharing.write_group(group);
        self
    }
    /// Keeps nonvolatile variables in this file.
    pub fn retain(mut self, path: impl Into<PathBuf>) -> Self {
        self.retain = Some(path.into());
        self
    }
    /// Saves changed nonvolatile values at most this often (default 1 s; always at stop).
    pub fn retain_interval(mut self, interval: Duration) -> Self {
        self.retain_interval = interval;
        self
    }
    /// Keeps the alarm journal (every alarm transition, and each alarm's state across
    /// restarts) in this file. By default it lies beside the [`retain`](Self::retain) file
    /// (`press.retain` beside `press.alarms`,
    /// [`alarm_journal::beside_retain`]); with neither, alarms are evaluated but their history
    /// is lost at stop, and [`build`](Self::build) warns so. A program without alarms opens
    /// no journal.
    pub fn alarm_journal(mut self, path: impl Into<PathBuf>) -> Self {
        self.alarm_journal = Some(path.into());
        self
    }
    /// Keeps the last `records` records in the alarm journal (default 10,000): older ones are
    /// dropped and counted, never an unacknowledged alarm's state. 1 to 10,000,000.
    pub fn alarm_journal_capacity(mut self, records: usize) -> Self {
        self.alarm_capacity = records;
        self
    }
    /// Lets operators shelve an alarm for at most `max` (default 8 hours: a shelved alarm is
    /// one nobody sees, so the shelf ends by itself). More than 0, at most 30 days.
    pub fn max_shelve(mut self, max: plc_core::Time) -> Self {
        self.max_shelve = max;
        self
    }
    /// The I/O backend (default: none).
    pub fn backend(mut self, backend: impl IoBackend<T> + Send + 'static) -> Self {
        self.backend = Box::new(backend);
        self
    }
    /// Takes online changes from `swaps`: each is made between two cycles (see [`Swap`]). A
    /// host (`plc run`) prepares them; a linked program has no use for it.
    pub fn swaps(mut self, swaps: std::sync::mpsc::Receiver<Swap<T>>) -> Self {
        self.swaps = Some(swaps);
        self
    }
    /// Runs the cycle thread with SCHED_FIFO at this priority (1..=99).
    pub fn realtime_priority(mut self, priority: i32) -> Self {
        self.realtime = Some(priority);
        self
    }
    /// Runs the cycle on CPU `cpu` (numbered as the kernel does, from 0), with the threads
    /// its I/O starts (EtherCAT's sending and receiving), and the runtime's other threads
    /// (the server that answers tools, the retain writer) on the other CPUs the process may
    /// use, so nothing of the runtime's runs on the cycle's CPU between cycles. With
    /// `realtime_priority` and a CPU the kernel keeps free of other work (`isolcpus=` on its
    /// command line), the cycle has that CPU to itself. A CPU the process may not use stops
    /// the start with [`RuntimeError::Cpu`], before anything is created. The calling thread
    /// gets its CPUs back when [`Runtime::run`] returns.
    ///
    /// ```no_run
    /// # use plc_core::GlobalMemory;
    /// # #[derive(GlobalMemory, Debug, Clone)]
    /// # struct Gm { #[plc(direction = "output")] lamp: bool }
    /// plc_runtime::Runtime::<Gm>::builder()
    ///     .period(std::time::Duration::from_millis(1))
    ///     .realtime_priority(80)
    ///     .cpu(3)
    ///     .build()?
    ///     .run(|ctx| ctx.gm.lamp = !ctx.gm.lamp)?;
    /// # Ok::<(), plc_runtime::RuntimeError>(())
    /// ```
    pub fn cpu(mut self, cpu: usize) -> Self {
        self.cpu = Some(cpu);
        self
    }
    /// Stops after this many cycles.
    pub fn max_cycles(mut self, cycles: u64) -> Self {
        self.max_cycles = Some(cycles);
        self
    }
    /// Whether Ctrl-C and SIGTERM stop the runtime cleanly (default true).
    pub fn handle_signals(mut self, on: bool) -> Self {
        self.signals = on;
        self
    }
    /// Calls `probe` after each cycle with the cycle's timestamps (start, bus exchange, tick,
    /// end), on the cycle's thread and outside the cycle's timed span. For the benchmarks
    /// (feature `cycle-probe`); the cycle does the same work with or without it.
    #[cfg(feature = "cycle-probe")]
    #[doc(hidden)]
    pub fn cycle_probe(mut self, probe: impl FnMut(&probe::CycleTimes) + Send + 'static) -> Self {
        self.probe = Some(Box::new(probe));
        self
    }
    /// A handle that stops the runtime.
    pub fn stop_handle(&self) -> StopHandle {
        self.stop.clone()
    }
    /// The runtime, after checking what can be checked before it runs: the [`cpu`](Self::cpu)
    /// is one this process may use, the [`realtime_priority`](Self::realtime_priority) is in
    /// SCHED_FIFO's range and permitted (tried on a short-lived thread), the read and write
    /// groups exist, the [`backend`](Self::backend) can run at the [`period`](Self::period)
    /// ([`IoBackend::check_period`]; [`RuntimeError::Io`] if not). Each refusal names the value and the fix; [`run`](Runtime::run) checks
    /// again when it starts, as a CPU or a permission may change in between.
    ///
    /// ```
    /// # use plc_core::GlobalMemory;
    /// # #[derive(GlobalMemory, Debug, Clone)]
    /// # struct Gm { #[plc(direction = "output")] lamp: bool }
    /// let refused = plc_runtime::Runtime::<Gm>::builder().cpu(100_000).build();
    /// assert!(matches!(refused, Err(plc_runtime::RuntimeError::Cpu(_))));
    /// ```
    pub fn build(self) -> Result<Runtime<T>, RuntimeError> {
        if let Some(cpu) = self.cpu {
            placement::check(cpu)?;
        }
        if let Some(priority) = self.realtime {
            check_realtime(priority)?;
        }
        let segment = self.segment.as_deref().unwrap_or("(no segment)");
        self.sharing.check(segment).map_err(RuntimeError::Shm)?;
        self.backend
            .check_period(self.period)
            .map_err(RuntimeError::Io)?;
        if !(1..=10_000_000).contains(&self.alarm_capacity) {
            return Err(RuntimeError::Alarm(format!(
                "an alarm journal of {} records: keep 1 to 10,000,000 \
                 (`RuntimeBuilder::alarm_journal_capacity`)",
                self.alarm_capacity
            )));
        }
        let month = plc_core::Time::from_secs(30 * 86_400);
        if self.max_shelve.as_nanos() <= 0 || self.max_shelve > month {
            return Err(RuntimeError::Alarm(format!(
                "a longest shelf of {}: give more than 0 and at most 30 days \
                 (`RuntimeBuilder::max_shelve`)",
                self.max_shelve
            )));
        }
        let alarms = self.initial.schema().alarms.len();
        if alarms > 0 && self.alarm_journal_path().is_none() {
            log::warn!(target: "plc_io::runtime",
                "segment `{segment}`: the program's {} alarms are evaluated, but their history \
                 and unacknowledged alarms will not survive a restart: give the runtime a \
                 retain file (`RuntimeBuilder::retain`) or an alarm journal \
                 (`RuntimeBuilder::alarm_journal`)",
                alarms);
        }
        Ok(Runtime { settings: self })
    }

    /// The alarm journal's file: the one asked for, or beside the retain file.
    fn alarm_journal_path(&self) -> Option<PathBuf> {
        self.alarm_journal
            .clone()
            .or_else(|| self.retain.as_deref().map(alarm_journal::beside_retain))
    }
}

/// Checks that `priority` is a SCHED_FIFO priority this process may take, by taking it on a
/// thread of its own that ends at once (the calling thread's scheduling stays as it is).
fn check_realtime(priority: i32) -> Result<(), RuntimeError> {
    // SAFETY: plain queries of the scheduler's range for a policy.
    let (min, max) = unsafe {
        (
            libc::sched_get_priority_min(libc::SCHED_FIFO),
            libc::sched_get_priority_max(libc::SCHED_FIFO),
        )
    };
    if !(min..=max).contains(&priority) {
        return Err(RuntimeError::Realtime(format!(
            "realtime priority {priority} is outside SCHED_FIFO's {min}..={max}; choose one in \
             that range (higher runs first)"
        )));
    }
    std::thread::spawn(move || set_realtime(priority))
        .join()
        .unwrap_or_else(|_| {
            Err(RuntimeError::Realtime(format!(
                "realtime priority {priority} could not be tried: the checking thread failed"
            )))
        })
}

fn set_realtime(priority: i32) -> Result<(), RuntimeError> {
    let param = libc::sched_param {
        sched_priority: priority,
    };
    // SAFETY: plain syscall on the calling thread with a valid parameter struct.
    let r = unsafe { libc::sched_setscheduler(0, libc::SCHED_FIFO, &param) };
    if r == 0 {
        Ok(())
    } else {
        Err(RuntimeError::Realtime(format!(
            "realtime priority {priority} (SCHED_FIFO) is not permitted: {}; run as root, grant \
             CAP_SYS_NICE (`sudo setcap cap_sys_nice=ep <program>`), or run without it",
            std::io::Error::last_os_error()
        )))
    }
}

/// Sets every output variable of `gm` to zero / false / "".
pub fn zero_outputs<T: Memory>(gm: &mut T) {
    for (i, v) in gm.schema().variables.iter().enumerate() {
        if v.direction != Direction::Output {
            continue;
        }
        for e in 0..v.elements() {
            // The zero of a variable's own type is always in range, so `set` accepts it.
            let _ = gm.set(i, e, Value::zero(v.iec_type));
        }
    }
}

impl<T: Memory> Runtime<T> {
    /// The stop handle of this runtime.
    pub fn stop_handle(&self) -> StopHandle {
        self.settings.stop.clone()
    }

    /// Runs `tick` every period until stopped (handle, signal or `max_cycles`). Returns the
    /// variables as they were at the end.
    pub fn run(self, mut tick: impl FnMut(&mut Context<T>)) -> Result<T, RuntimeError> {
        let mut settings = self.settings;
        let mut cycle = Cycle::start(&mut settings)?;
        let result = cycle.repeat(&mut settings, &mut tick);
        cycle.stop(&mut *settings.backend, result)
    }
}
