//! The steps of [`Runtime::run`](super::Runtime::run): start, one cycle repeated at the period,
//! stop. Each step is a method of [`Cycle`], which owns what lives from start to stop.

use super::clock::{CycleClock, monotonic_ns};
use super::placement::CpuPlacement;
use super::schedule::Schedule;
use super::stats::{self, RunningMean};
use super::{
    Context, IoBackend, IoStatus, RuntimeBuilder, RuntimeError, set_realtime, zero_outputs,
};
use crate::alarm_journal::AlarmJournal;
use crate::alarms::RuntimeAlarms;
use crate::change::{Probation, Remake};
use crate::retain::{RetainStore, RetainWriter};
use crate::started::Started;
use plc_core::Time;
use plc_core::memory::Memory;
use plc_shm::{RunState, ShmOwner};
use std::any::Any;
use std::panic::{AssertUnwindSafe, catch_unwind};
#[cfg(feature = "cycle-probe")]
use std::time::Instant;

/// What a running program owns besides its settings.
pub(super) struct Cycle<T: Memory> {
    pub(super) ctx: Context<T>,
    /// The last completed cycle's image. On a cache line: the image type has alignment 1, and
    /// the word copies into shared memory cost up to three times as much from a buffer that
    /// straddles lines.
    pub(super) image: Box<Aligned<T::Image>>,
    pub(super) retained: RetainedBytes,
    pub(super) retain: Option<RetainWriter<T::Image>>,
    /// The alarm journal's writer, if the program has alarms and a journal file.
    pub(super) journal: Option<AlarmJournal>,
    pub(super) shm: Option<ShmOwner<T>>,
    /// The line to log after the first cycle.
    started: Option<Started>,
    /// A change on probation.
    pub(super) probation: Option<Probation<T>>,
    /// How to follow a change of layout.
    pub(super) remake: Remake,
    /// The cycle's clock (`Context::now`'s, the schedule's, the published values' time).
    clock: CycleClock,
    /// The mean of all cycles' times.
    mean: RunningMean,
    /// Called with each cycle's timestamps (benchmarks only).
    #[cfg(feature = "cycle-probe")]
    probe: Option<super::probe::Probe>,
    /// The cycle's CPU, if one was asked for; dropped with the cycle, it gives the calling
    /// thread its CPUs back.
    placement: Option<CpuPlacement>,
}

impl<T: Memory> Cycle<T> {
    /// The CPU checked, realtime priority and signals as asked, retained values loaded, the
    /// segment created and the initial image published, the cycle moved to its CPU, then the
    /// I/O started.
    pub(super) fn start(s: &mut RuntimeBuilder<T>) -> Result<Self, RuntimeError> {
        // First, so that a CPU the process may not use is refused before anything is made,
        // and the helper threads below start on the other CPUs.
        let placement = s.cpu.map(CpuPlacement::keep_free).transpose()?;
        if let Some(p) = s.realtime {
            set_realtime(p)?;
        }
        if s.signals
            && let Err(e) = s.stop.stop_on_signals()
        {
            // Ctrl-C still ends the program, only without the clean stop.
            log::warn!(target: "plc_io::runtime", "Ctrl-C and SIGTERM will end the program without a clean stop: {e}");
        }
        let mut gm = s.initial.clone();
        let mut loaded = None;
        let schema = gm.schema();
        let retain = match &s.retain {
            Some(path) => {
                let store = RetainStore::new(path);
                let report = store.load(&mut gm).map_err(RuntimeError::Retain)?;
                report.log(path);
                loaded = Some((path.clone(), report.restored.len() + report.converted.len()));
                Some(RetainWriter::spawn_for(
                    store,
                    s.retain_interval,
                    gm.clone(),
                ))
            }
            None => None,
        };
        let (alarms, journal) = start_alarms(s, &schema)?;
        // Tools learn where the alarm history is from the segment (`plc alarms --history`).
        let sharing = match (&journal, s.alarm_journal_path()) {
            (Some(_), Some(path)) => s
                .sharing
                .clone()
                .alarm_history(std::path::absolute(&path).unwrap_or(path), s.alarm_capacity),
            _ => s.sharing.clone(),
        };
        let shm = match &s.segment {
            Some(name) => {
                Some(ShmOwner::create(name, &sharing, schema).map_err(RuntimeError::Shm)?)
            }
            None => None,
        };
        let mut image = Box::new(Aligned(gm.new_image()));
        gm.store_image(&mut image.0);
        let cycle = Cycle {
            retained: RetainedBytes::new(&schema, T::image_bytes(&image.0)),
            ctx: Context::before_first_cycle(gm, s.period, alarms),
            image,
            retain,
            journal,
            shm,
            probation: None,
            started: Some(Started {
                segment: s.segment.clone(),
                retain: loaded,
            }),
            remake: Remake {
                retain: s.retain.clone().map(|path| (path, s.retain_interval)),
                sharing,
                max_shelve: s.max_shelve,
            },
            clock: CycleClock::start(),
            mean: RunningMean::default(),
            #[cfg(feature = "cycle-probe")]
            probe: s.probe.take(),
            placement,
        };
        // The initial and restored values go out before the bus starts (which can take
        // seconds): a tool attaching meanwhile reads them, not a zeroed image.
        cycle.publish_image(monotonic_ns());
        // The helpers have started; the I/O's threads, started next, run with the cycle.
        if let Some(placement) = &cycle.placement {
            placement.pin_cycle()?;
        }
        s.backend.start().map_err(RuntimeError::Io)?;
        if let Some(shm) = &cycle.shm {
            shm.set_run_state(RunState::Running);
        }
        #[cfg(feature = "cycle-probe")]
        super::probe::arm(cycle.probe.is_some());
        Ok(cycle)
    }

    /// Cycles every period until a stop is asked for, `max_cycles` are done or the tick
    /// panics. A late cycle is followed at once by the next, timed from then: no burst of
    /// catch-up cycles. The deadlines are absolute (`schedule`), and follow the I/O's own
    /// clock when it has one ([`IoBackend::cycle_phase`]).
    pub(super) fn repeat(
        &mut self,
        s: &mut RuntimeBuilder<T>,
        tick: &mut impl FnMut(&mut Context<T>),
    ) -> Result<(), RuntimeError> {
        let mut schedule = Schedule::start(s.period);
        let mut start = monotonic_ns();
        while !s.stop.is_stopped() && s.max_cycles.is_none_or(|m| self.ctx.cycle < m) {
            let end = self.once(start, &mut *s.backend, tick)?;
            // Between two cycles: a change of the program, if one waits (`swap`).
            self.take_swap(s.swaps.as_ref(), &mut *s.backend);
            // Where the exchange fell against the I/O's own clock (EtherCAT: SYNC0), if it
            // keeps one: the next deadline moves a little towards it (`schedule`).
            let phase = s.backend.cycle_phase();
            // A cycle that follows at once (period zero, or the last one overran) starts
            // where the last one ended: its report, a few nanoseconds, counts in its time, and
            // a cycle running flat out reads the clock once instead of twice.
            start = if schedule.wait(end, phase) {
                monotonic_ns()
            } else {
                end
            };
        }
        Ok(())
    }

    /// One cycle, started at `start`: exchange, unpack bits, writes from outside, forces, tick,
    /// forces again, pack bits, publish, trace, retain, report. Returns when its work ended (before the report). Both
    /// times are CLOCK_MONOTONIC nanoseconds; the cycle reads the clock once, at its end.
    fn once(
        &mut self,
        start: u64,
        backend: &mut (dyn IoBackend<T> + Send),
        tick: &mut impl FnMut(&mut Context<T>),
    ) -> Result<u64, RuntimeError> {
        #[cfg(feature = "cycle-probe")]
        let probing = self.probe.is_some();
        #[cfg(feature = "cycle-probe")]
        let exchange_start = probing.then(Instant::now);
        let ctx = &mut self.ctx;
        ctx.cycle += 1;
        let since_start = self.clock.since_start(start);
        let alarmed = !ctx.alarms().is_empty();
        if alarmed {
            // What happens to alarms in this cycle, an operator's action in the tick
            // included, has the cycle's start as its time.
            let utc = self.clock.utc_ns(start);
            ctx.alarms_mut()
                .set_now(i64::try_from(utc).unwrap_or(i64::MAX));
        }
        // Beyond LTIME only after 292 years of running.
        ctx.set_now(Time::from_nanos(
            i64::try_from(since_start).unwrap_or(i64::MAX),
        ));
        let io = backend.exchange(&mut ctx.gm);
        #[cfg(feature = "cycle-probe")]
        let exchange_end = probing.then(Instant::now);
        ctx.inputs_valid = io.inputs_valid;
        ctx.bus_fault = io.bus_fault;
        ctx.bus_state = io.bus_state;
        ctx.gm.unpack_bits();
        // Writes from outside are applied under the same protection as the tick: whatever a write
        // does, a panic still zeroes the outputs and puts the bus in a safe state.
        let shm = &mut self.shm;
        #[cfg(feature = "cycle-probe")]
        let mut tick_times = None;
        let step = catch_unwind(AssertUnwindSafe(|| {
            // Forces after the writes: a forced value is what the program reads, whatever
            // the bus or a tool gave it.
            if let Some(shm) = shm.as_mut() {
                // Operators' actions on alarms come with the writes, in their order (a
                // program without alarms gets none: its socket refuses them).
                let alarms = &mut ctx.alarms;
                shm.apply_requests_with_alarms(&mut ctx.gm, |_, _| {}, |c| alarms.command(c));
                shm.apply_forces(&mut ctx.gm);
            }
            #[cfg(feature = "cycle-probe")]
            let tick_start = probing.then(Instant::now);
            tick(ctx);
            #[cfg(feature = "cycle-probe")]
            if let Some(t) = tick_start {
                tick_times = Some((t, Instant::now()));
            }
            // And again before the outputs are packed: the bus and the tools get the forced
            // value, whatever the program wrote.
            if let Some(shm) = shm.as_ref() {
                shm.apply_forces(&mut ctx.gm);
            }
        }));
        if let Err(panic) = step {
            // On probation, the previous program comes back and the cycle goes on with it.
            self.on_panic(backend, panic)?;
        }
        let ctx = &mut self.ctx;
        // After the tick and the forces, from the values the cycle publishes: the program
        // writes nothing for its alarms.
        if alarmed {
            ctx.alarms.evaluate(&ctx.gm);
            if let Some(shm) = &self.shm {
                // Before the image: a tool answered "applied" after it reads what it did.
                if ctx.alarms.has_changed() {
                    shm.publish_alarms(ctx.alarms.drain_changed());
                }
                if let Some((active, unacknowledged)) = ctx.alarms.counts_to_publish() {
                    shm.set_alarm_counts(active as u64, unacknowledged as u64);
                }
            }
        }
        ctx.gm.pack_bits();
        ctx.gm.store_image(&mut self.image.0);
        self.publish_image(start);
        if let Some(shm) = &self.shm {
            shm.record_traces(&self.image.0, self.ctx.cycle, since_start);
        }
        if let Some(writer) = &self.retain
            && self.retained.changed(T::image_bytes(&self.image.0))
        {
            writer.offer(self.image.0.clone());
        }
        let end = monotonic_ns();
        self.report(start, end, &io);
        if let Some(started) = self.started.take() {
            started.log(&io);
        }
        #[cfg(feature = "cycle-probe")]
        if let (Some(probe), Some(bus), Some(exchange_end), Some((tick_start, tick_end))) = (
            self.probe.as_mut(),
            exchange_start,
            exchange_end,
            tick_times,
        ) {
            // The backend's own stamps of its frame exchange, if it made them; otherwise the
            // whole exchange counts as the bus's.
            let (bus_start, bus_end) = super::probe::take_bus().unwrap_or((bus, exchange_end));
            probe(&super::probe::CycleTimes {
                start: self.clock.instant(start),
                bus_start,
                bus_end,
                tick_start,
                tick_end,
                end: self.clock.instant(end),
            });
        }
        Ok(end)
    }

    /// The tick panicked: outputs to zero, on the bus and in the segment, and the I/O in its
    /// safe state.
    pub(super) fn fault(
        &mut self,
        backend: &mut (dyn IoBackend<T> + Send),
        panic: Box<dyn Any + Send>,
    ) -> RuntimeError {
        let message = panic_message(&*panic);
        let gm = &mut self.ctx.gm;
        zero_outputs(gm);
        gm.pack_bits();
        backend.fault(gm);
        if let Some(shm) = &self.shm {
            if let Err(e) = shm.publish(gm) {
                log::error!(target: "plc_io::runtime",
                    "segment `{}`: the zeroed outputs were not published: {e}",
                    shm.name()
                );
            }
            shm.set_run_state(RunState::Faulted);
        }
        RuntimeError::Panicked {
            cycle: self.ctx.cycle,
            message,
        }
    }

    /// The I/O stopped, the last completed cycle's retained values saved, the segment marked
    /// stopped (or faulted) and removed; the variables, or the error `repeat` ended with.
    pub(super) fn stop(
        self,
        backend: &mut (dyn IoBackend<T> + Send),
        result: Result<(), RuntimeError>,
    ) -> Result<T, RuntimeError> {
        backend.stop();
        #[cfg(feature = "cycle-probe")]
        super::probe::arm(false);
        let saved = match self.retain {
            // The last completed cycle's image. After a panic `gm` holds a half-done tick and
            // zeroed outputs, which must not become the values the next start restores.
            Some(writer) => {
                let before = writer.failed_saves();
                let saved = writer.finish(Some(self.image.0));
                if let Some(shm) = &self.shm {
                    shm.set_retain_failures(before + u64::from(saved.is_err()));
                }
                saved
            }
            None => Ok(()),
        };
        // Every transition to the last cycle's on disk before the program is reported stopped.
        if let Some(journal) = self.journal
            && let Err(e) = journal.finish()
        {
            log::error!(target: "plc_io::runtime", "{e}; the journal holds what was synced before");
        }
        if let Some(shm) = &self.shm {
            shm.set_run_state(if result.is_ok() {
                RunState::Stopped
            } else {
                RunState::Faulted
            });
        }
        drop(self.shm);
        // A panic is the first thing to report; a lost final save comes next.
        result?;
        saved.map_err(RuntimeError::RetainNotSaved)?;
        Ok(self.ctx.gm)
    }

    /// The last cycle's image out, with a heartbeat of `now` (CLOCK_MONOTONIC nanoseconds).
    fn publish_image(&self, now: u64) {
        if let Some(shm) = &self.shm
            && let Err(e) = shm.publish_image_at(&self.image.0, now)
        {
            // The runtime created the segment, so it owns it and the publish succeeds; were
            // that ever not so, tools would see stale values: say so rather than hide it.
            log::error!(target: "plc_io::runtime",
                "segment `{}`: this cycle's values were not published: {e}",
                shm.name()
            );
        }
    }

    /// The cycle's figures, and the time of its values: its end, when they were published.
    fn report(&mut self, start: u64, end: u64, io: &IoStatus) {
        let cycle = self.ctx.cycle;
        let took_ns = end.saturating_sub(start);
        stats::add(&mut self.ctx.stats, took_ns, cycle, &mut self.mean);
        if let Some(shm) = &self.shm {
            shm.report_published(cycle, &self.ctx.stats, io, self.clock.utc_ns(end));
            if let Some(writer) = &self.retain {
                shm.set_retain_failures(writer.failed_saves());
            }
        }
    }
}

/// The program's alarms, each given its state from the journal if there is one (opened,
/// with its writer started); none and no journal for a program without alarms.
fn start_alarms<T: Memory>(
    s: &RuntimeBuilder<T>,
    schema: &plc_core::memory::Schema,
) -> Result<(RuntimeAlarms, Option<AlarmJournal>), RuntimeError> {
    let mut alarms = RuntimeAlarms::of(schema).map_err(RuntimeError::Alarm)?;
    alarms.set_max_shelve(s.max_shelve);
    let path = match s.alarm_journal_path() {
        Some(path) if !alarms.is_empty() => path,
        _ => return Ok((alarms, None)),
    };
    let journal =
        AlarmJournal::open(&path, s.alarm_capacity).map_err(RuntimeError::AlarmJournal)?;
    alarms.restore(journal.contents().states(), &path);
    alarms.attach(journal.sender(alarms.path_table()));
    Ok((alarms, Some(journal)))
}

/// A panic's message, when it has one.
pub(super) fn panic_message(panic: &(dyn Any + Send)) -> String {
    panic
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| panic.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "(no message)".into())
}

/// An image on a cache-line boundary.
#[repr(C, align(64))]
pub(super) struct Aligned<I>(pub(super) I);

/// The image bytes of the nonvolatile variables as last handed to the retain writer, to notice
/// a change without decoding. Their ranges are found once, so a cycle compares bytes in place
/// and neither walks `VARIABLES` nor allocates.
pub(super) struct RetainedBytes {
    ranges: Vec<std::ops::Range<usize>>,
    last: Vec<u8>,
}

impl RetainedBytes {
    fn new(schema: &plc_core::memory::Schema, bytes: &[u8]) -> Self {
        let ranges: Vec<_> = schema
            .variables
            .iter()
            .filter(|v| v.nonvolatile)
            .map(|v| v.offset..v.offset + v.size)
            .collect();
        let last = ranges
            .iter()
            .flat_map(|r| bytes[r.clone()].iter().copied())
            .collect();
        RetainedBytes { ranges, last }
    }

    /// As [`new`](Self::new), but the first comparison finds every value changed: after a
    /// change of the program, whose new retain writer must save at once.
    pub(super) fn changed_from_nothing(schema: &plc_core::memory::Schema, bytes: &[u8]) -> Self {
        let mut r = RetainedBytes::new(schema, bytes);
        r.last.iter_mut().for_each(|b| *b = !*b);
        r
    }

    /// Whether the nonvolatile bytes of `image` differ from the last ones (then remembered).
    fn changed(&mut self, bytes: &[u8]) -> bool {
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

#[cfg(test)]
mod tests {
    use super::{RetainedBytes, panic_message};
    use plc_core::GlobalMemory;
    use zerocopy::IntoBytes;

    #[derive(GlobalMemory, Clone, Debug)]
    #[plc(crate = "plc_core")]
    struct Gm {
        #[plc(nonvolatile)]
        kept: u16,
        scratch: u16,
    }

    #[test]
    fn only_a_change_of_a_nonvolatile_variable_counts() {
        let mut gm = Gm::default();
        let schema = plc_core::memory::Schema::of::<Gm>();
        let mut retained = RetainedBytes::new(&schema, gm.to_image().as_bytes());
        gm.scratch = 5;
        assert!(!retained.changed(gm.to_image().as_bytes()));
        gm.kept = 1;
        assert!(retained.changed(gm.to_image().as_bytes()));
        assert!(
            !retained.changed(gm.to_image().as_bytes()),
            "the change is remembered"
        );
    }

    #[test]
    fn panic_messages_of_both_kinds_are_read() {
        let text = std::panic::catch_unwind(|| panic!("at {}", 3)).unwrap_err();
        assert_eq!(panic_message(&*text), "at 3");
        let literal = std::panic::catch_unwind(|| panic!("plain")).unwrap_err();
        assert_eq!(panic_message(&*literal), "plain");
    }
}
