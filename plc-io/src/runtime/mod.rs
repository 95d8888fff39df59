//! The cycle: `Runtime` runs a program's tick at a fixed period with its I/O, shared memory and
//! retained variables.

mod backend;
mod context;

pub use backend::{IoBackend, IoError, IoStatus, NoIo};
pub use context::{Context, CycleStats};

use crate::retain::{RetainError, RetainReport, RetainStore, RetainWriter};
use crate::shm::{BUS_STATES, CycleReport, RunState, SharedGlobalMemory, ShmError};
use plc_core::{Direction, GlobalMemory, IecType, TypeFamily, Value};
use std::fmt;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};
use zerocopy::{Immutable, IntoBytes};

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
            RuntimeError::Realtime(e) => write!(f, "{e}"),
            RuntimeError::Panicked { cycle, message } => write!(
                f,
                "the program panicked in cycle {cycle}: {message}; outputs were set to zero and \
                 the I/O put in a safe state"
            ),
        }
    }
}

impl std::error::Error for RuntimeError {}

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
        for sig in [signal_hook::consts::SIGINT, signal_hook::consts::SIGTERM] {
            // First the exit if a stop is already pending, then the flag: handlers of one
            // signal run in the order they were registered.
            signal_hook::flag::register_conditional_shutdown(sig, 1, self.0.clone())?;
            signal_hook::flag::register(sig, self.0.clone())?;
        }
        Ok(())
    }
}

/// Settings of a [`Runtime`].
pub struct RuntimeBuilder<T> {
    period: Duration,
    segment: Option<String>,
    retain: Option<PathBuf>,
    retain_interval: Duration,
    backend: Box<dyn IoBackend<T> + Send>,
    realtime: Option<i32>,
    max_cycles: Option<u64>,
    signals: bool,
    stop: StopHandle,
}

/// Runs a program's cycle: exchange I/O, unpack bits, apply mailbox writes, the program's
/// tick, pack bits, publish to shared memory, hand changed nonvolatile values to the retain
/// writer.
///
/// ```no_run
/// use plc_core::GlobalMemory;
/// use plc_io::Runtime;
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
///     .build()
///     .run(|ctx| ctx.gm.count += 1)?;
/// # Ok::<(), plc_io::RuntimeError>(())
/// ```
pub struct Runtime<T> {
    settings: RuntimeBuilder<T>,
}

impl<T: GlobalMemory + Default + Clone + Send + 'static> Runtime<T> {
    /// Settings with a 10 ms period, no segment, no retain file, no I/O, Ctrl-C/SIGTERM handled.
    pub fn builder() -> RuntimeBuilder<T> {
        RuntimeBuilder {
            period: Duration::from_millis(10),
            segment: None,
            retain: None,
            retain_interval: Duration::from_millis(1000),
            backend: Box::new(NoIo),
            realtime: None,
            max_cycles: None,
            signals: true,
            stop: StopHandle::default(),
        }
    }
}

impl<T: GlobalMemory + Default + Clone + Send + 'static> RuntimeBuilder<T> {
    /// The cycle period.
    pub fn period(mut self, period: Duration) -> Self {
        self.period = period;
        self
    }
    /// Publishes the variables in shared-memory segment `name`.
    pub fn segment(mut self, name: impl Into<String>) -> Self {
        self.segment = Some(name.into());
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
    /// The I/O backend (default: none).
    pub fn backend(mut self, backend: impl IoBackend<T> + Send + 'static) -> Self {
        self.backend = Box::new(backend);
        self
    }
    /// Runs the cycle thread with SCHED_FIFO at this priority (1..=99).
    pub fn realtime_priority(mut self, priority: i32) -> Self {
        self.realtime = Some(priority);
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
    /// A handle that stops the runtime.
    pub fn stop_handle(&self) -> StopHandle {
        self.stop.clone()
    }
    /// The runtime.
    pub fn build(self) -> Runtime<T> {
        Runtime { settings: self }
    }
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
pub fn zero_outputs<T: GlobalMemory>(gm: &mut T) {
    for (i, v) in T::VARIABLES.iter().enumerate() {
        if v.direction != Direction::Output {
            continue;
        }
        let zero = match v.iec_type.family() {
            TypeFamily::Bool => Value::Bool(false),
            TypeFamily::Real => Value::Real(0.0),
            TypeFamily::String => Value::Text(Default::default()),
            _ if v.iec_type == IecType::String => Value::Text(Default::default()),
            _ => Value::UInt(0),
        };
        for e in 0..v.elements() {
            let _ = gm.set(i, e, zero);
        }
    }
}

fn bus_code(name: &str) -> u8 {
    BUS_STATES.iter().position(|s| *s == name).unwrap_or(0) as u8
}

impl<T: GlobalMemory + Default + Clone + Send + 'static> Runtime<T>
where
    T::Image: Send,
{
    /// The stop handle of this runtime.
    pub fn stop_handle(&self) -> StopHandle {
        self.settings.stop.clone()
    }

    /// Runs `tick` every period until stopped (handle, signal or `max_cycles`). Returns the
    /// variables as they were at the end.
    pub fn run(self, mut tick: impl FnMut(&mut Context<T>)) -> Result<T, RuntimeError> {
        let mut s = self.settings;
        if let Some(p) = s.realtime {
            set_realtime(p)?;
        }
        if s.signals {
            // Without the handlers Ctrl-C still stops the program, only not cleanly.
            let _ = s.stop.stop_on_signals();
        }
        let mut gm = T::default();
        let retain = match &s.retain {
            Some(path) => {
                let store = RetainStore::new(path);
                let report: RetainReport = store.load(&mut gm).map_err(RuntimeError::Retain)?;
                report.log(path);
                Some(RetainWriter::spawn::<T>(store, s.retain_interval))
            }
            None => None,
        };
        let mut shm = match &s.segment {
            Some(name) => Some(SharedGlobalMemory::<T>::create(name).map_err(RuntimeError::Shm)?),
            None => None,
        };
        let mut ctx = Context::for_test(gm);
        ctx.cycle = 0;
        ctx.stats.period = s.period;
        // On a cache line: the image type has alignment 1, and the word copies into shared
        // memory cost up to three times as much from a buffer that straddles lines.
        let mut image_buf = Box::new(Aligned(ctx.gm.to_image()));
        let image = &mut image_buf.0;
        let mut retained = RetainedBytes::new::<T>(image);
        // The initial and restored values go out before the bus starts (which can take
        // seconds): a tool attaching meanwhile reads them, not a zeroed image.
        if let Some(shm) = &shm {
            // Cannot fail: the runtime created the segment, so it is its owner.
            let _ = shm.publish_image(image);
        }
        s.backend.start().map_err(RuntimeError::Io)?;
        if let Some(shm) = &shm {
            shm.set_run_state(RunState::Running);
        }
        let mut next = Instant::now();
        let result = loop {
            if s.stop.is_stopped() || s.max_cycles.is_some_and(|m| ctx.cycle >= m) {
                break Ok(());
            }
            let start = Instant::now();
            ctx.cycle += 1;
            let io = s.backend.exchange(&mut ctx.gm);
            ctx.inputs_valid = io.inputs_valid;
            ctx.bus_fault = io.bus_fault;
            ctx.bus_state = io.bus_state;
            ctx.gm.unpack_bits();
            // The mailbox is applied under the same protection as the tick: whatever a write
            // does, a panic still zeroes the outputs and puts the bus in a safe state.
            let step = catch_unwind(AssertUnwindSafe(|| {
                if let Some(shm) = shm.as_mut() {
                    shm.apply_mailbox(&mut ctx.gm);
                }
                tick(&mut ctx)
            }));
            if let Err(panic) = step {
                let message = panic
                    .downcast_ref::<&str>()
                    .map(|s| s.to_string())
                    .or_else(|| panic.downcast_ref::<String>().cloned())
                    .unwrap_or_else(|| "(no message)".into());
                zero_outputs(&mut ctx.gm);
                ctx.gm.pack_bits();
                s.backend.fault(&mut ctx.gm);
                if let Some(shm) = &shm {
                    let _ = shm.publish(&ctx.gm);
                    shm.set_run_state(RunState::Faulted);
                }
                break Err(RuntimeError::Panicked {
                    cycle: ctx.cycle,
                    message,
                });
            }
            ctx.gm.pack_bits();
            ctx.gm.store_image(image);
            if let Some(shm) = &shm {
                let _ = shm.publish_image(image); // the owner's: cannot fail
            }
            if let Some(writer) = &retain
                && retained.changed(image)
            {
                writer.offer(*image);
            }
            let took = start.elapsed();
            ctx.stats.add(took, ctx.cycle);
            if let Some(shm) = &shm {
                shm.report(&CycleReport {
                    period: s.period,
                    cycle_count: ctx.cycle,
                    last: ctx.stats.last,
                    min: ctx.stats.min,
                    max: ctx.stats.max,
                    mean: ctx.stats.mean,
                    overruns: ctx.stats.overruns,
                    bus_state: bus_code(io.bus_state),
                    bus_fault: io.bus_fault,
                    inputs_valid: io.inputs_valid,
                });
                if let Some(writer) = &retain {
                    shm.set_retain_failures(writer.failed_saves());
                }
            }
            next += s.period;
            let now = Instant::now();
            if next > now {
                std::thread::sleep(next - now);
            } else {
                // Late: start the next cycle now, from now (no burst of catch-up cycles).
                next = now;
            }
        };
        s.backend.stop();
        let saved = match retain {
            // `image` is the last completed cycle's. After a panic `gm` holds a half-done tick
            // and zeroed outputs, which must not become the values the next start restores.
            Some(writer) => {
                let before = writer.failed_saves();
                let saved = writer.finish(Some(*image));
                if let Some(shm) = &shm {
                    shm.set_retain_failures(before + u64::from(saved.is_err()));
                }
                saved
            }
            None => Ok(()),
        };
        if let Some(shm) = &shm {
            shm.set_run_state(if result.is_ok() {
                RunState::Stopped
            } else {
                RunState::Faulted
            });
        }
        drop(shm);
        // A panic is the first thing to report; a lost final save comes next.
        result?;
        saved.map_err(RuntimeError::RetainNotSaved)?;
        Ok(ctx.gm)
    }
}

/// An image on a cache-line boundary.
#[repr(C, align(64))]
struct Aligned<I>(I);

/// The image bytes of the nonvolatile variables as last handed to the retain writer, to notice
/// a change without decoding. Their ranges are found once, so a cycle compares bytes in place
/// and neither walks `VARIABLES` nor allocates.
struct RetainedBytes {
    ranges: Vec<std::ops::Range<usize>>,
    last: Vec<u8>,
}

impl RetainedBytes {
    fn new<T: GlobalMemory>(image: &T::Image) -> Self {
        let ranges: Vec<_> = T::VARIABLES
            .iter()
            .filter(|v| v.nonvolatile)
            .map(|v| v.offset..v.offset + v.size)
            .collect();
        let bytes = image.as_bytes();
        let last = ranges
            .iter()
            .flat_map(|r| bytes[r.clone()].iter().copied())
            .collect();
        RetainedBytes { ranges, last }
    }

    /// Whether the nonvolatile bytes of `image` differ from the last ones (then remembered).
    fn changed<I: IntoBytes + Immutable>(&mut self, image: &I) -> bool {
        let bytes = image.as_bytes();
        let mut at = 0;
        let mut changed = false;
        for r in &self.ranges {
            let (now, was) = (&bytes[r.clone()], &mut self.last[at..at + r.len()]);
            if now != was {
                was.copy_from_slice(now);
                changed = true;
            }
            at += r.len();
        }
        changed
    }
}
