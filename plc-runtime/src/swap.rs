//! How the cycle makes an online change (the types are in `change`): between two cycles it
//! runs the conversion, and when the layout differs, follows the new variables with the I/O's
//! bindings, the segment, the retain writer and the alarms; a panic on probation swaps the
//! previous program back.

use super::change::{Convert, Probation, Swap, SwapEvent};
use super::cycle::Cycle;
use super::{IoBackend, RuntimeError};
use crate::alarms::RuntimeAlarms;
use crate::retain::{RetainStore, RetainWriter};
use plc_core::memory::Memory;
use plc_shm::ShmOwner;

impl<T: Memory> Cycle<T> {
    /// Between two cycles: ends a probation that passed, and makes the change waiting, if
    /// any (one at a time: a change that comes during another's probation is refused).
    pub(super) fn take_swap(
        &mut self,
        swaps: Option<&std::sync::mpsc::Receiver<Swap<T>>>,
        backend: &mut (dyn IoBackend<T> + Send),
    ) {
        let cycle = self.ctx.cycle;
        if self.probation.as_ref().is_some_and(|p| cycle >= p.until)
            && let Some(p) = self.probation.take()
        {
            let _ = p.report.send(SwapEvent::Kept { cycle });
        }
        let Some(swap) = swaps.and_then(|rx| rx.try_recv().ok()) else {
            return;
        };
        if self.probation.is_some() {
            let _ = swap.report.send(SwapEvent::Refused(
                "the last change is still on probation: try again once it passed".into(),
            ));
            return;
        }
        let started = std::time::Instant::now();
        match self.install(backend, swap.convert) {
            Ok((relaid, released_forces)) => {
                let _ = swap.report.send(SwapEvent::Swapped {
                    cycle: cycle + 1,
                    took: started.elapsed(),
                    relaid,
                    released_forces,
                });
                self.probation = Some(Probation {
                    until: cycle + swap.probation.max(1),
                    back: swap.back,
                    report: swap.report,
                });
            }
            Err(why) => {
                let _ = swap.report.send(SwapEvent::Refused(why));
            }
        }
    }

    /// A panic in this cycle's tick: swaps the previous program back if the running one is
    /// on probation (`Ok`: the cycle goes on with it), else the program's fault.
    pub(super) fn on_panic(
        &mut self,
        backend: &mut (dyn IoBackend<T> + Send),
        panic: Box<dyn std::any::Any + Send>,
    ) -> Result<(), RuntimeError> {
        let Some(p) = self.probation.take() else {
            return Err(self.fault(backend, panic));
        };
        let message = super::cycle::panic_message(&*panic);
        match self.install(backend, p.back) {
            Ok(_) => {
                log::error!(target: "plc_io::runtime",
                    "the new program panicked in cycle {} of its probation: {message}; the \
                     previous program was swapped back", self.ctx.cycle);
                let _ = p.report.send(SwapEvent::SwappedBack {
                    cycle: self.ctx.cycle,
                    message,
                });
                Ok(())
            }
            Err(why) => {
                log::error!(target: "plc_io::runtime", "the previous program could not be swapped back: {why}");
                Err(self.fault(backend, panic))
            }
        }
    }

    /// Puts the variables `convert` makes in place of the running ones; whether their layout
    /// changed, and the forces it released. Refused without a change if the conversion or
    /// the I/O's bindings are.
    fn install(
        &mut self,
        backend: &mut (dyn IoBackend<T> + Send),
        convert: Convert<T>,
    ) -> Result<(bool, Vec<String>), String> {
        let mut new = convert(&self.ctx.gm)?;
        let schema = new.schema();
        let relaid = schema != self.ctx.gm.schema();
        let mut released = Vec::new();
        if relaid {
            backend.rebind(&schema).map_err(|e| {
                format!(
                    "the change is refused, the running program goes on: the new build's \
                         links do not fit the running bus (a new device or PDO needs a restart): \
                         {e}"
                )
            })?;
            released = self.relay(&mut new)?;
        }
        self.ctx.gm = new;
        self.ctx.gm.store_image(&mut self.image.0);
        if relaid {
            // The new retain writer saves at the next offer: every retained byte counts as new.
            self.retained = super::cycle::RetainedBytes::changed_from_nothing(
                &schema,
                T::image_bytes(&self.image.0),
            );
        }
        Ok((relaid, released))
    }

    /// Follows a new layout with the segment (the forces whose paths remain held again), the
    /// retain writer and the alarms; the paths of the forces released.
    fn relay(&mut self, new: &mut T) -> Result<Vec<String>, String> {
        let schema = new.schema();
        let mut released = Vec::new();
        if let Some(old) = self.shm.take() {
            let name = old.name().to_string();
            let forces = old.held_forces();
            drop(old);
            let made = ShmOwner::create(&name, &self.remake.sharing, schema);
            let owner = made.map_err(|e| format!("segment `{name}` was not made again: {e}"))?;
            released = owner.carry_forces(new, forces);
            self.shm = Some(owner);
        }
        if let Some((path, interval)) = &self.remake.retain {
            // The old writer's last save happens off the cycle; the new one saves the converted
            // values, offered right after this swap, once that save is done.
            let before = self.retain.take().map(|old| {
                std::thread::spawn(move || {
                    let _ = old.finish(None);
                })
            });
            self.retain = Some(RetainWriter::spawn_after(
                RetainStore::new(path),
                *interval,
                new.clone(),
                before,
            ));
        }
        let mut alarms = RuntimeAlarms::of(&schema)?;
        alarms.set_max_shelve(self.remake.max_shelve);
        if let Some(journal) = &self.journal {
            alarms.attach(journal.sender(alarms.path_table()));
        }
        self.ctx.alarms = alarms;
        Ok(released)
    }
}
