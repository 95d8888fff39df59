//! An online change prepared off the cycle thread: the plans both ways between the running
//! module's variables and a new module's, the new module's initial image, and the [`Swap`]
//! the cycle makes with them. The running variables at the change are kept: a return
//! (`--back`, or the probation's) starts from them, so a value the new program lacks comes
//! back with its value at the change.

use super::memory::ModuleMemory;
use crate::Module;
use plc_runtime::{Convert, Swap, SwapEvent};
use plc_shm::LayoutDescriptor;
use plc_shm::change::{ChangePlan, Direction, Refused};
use std::sync::mpsc::{Receiver, channel};
use std::sync::{Arc, Mutex};

/// The running variables at the moment of a change, for a return to them.
pub type AtChange = Arc<Mutex<Option<ModuleMemory>>>;

/// A change ready to be made: its plan (the report) and the swap to hand the cycle.
pub struct Prepared {
    /// What happens to each value.
    pub plan: ChangePlan,
    /// The swap to send to the runtime.
    pub swap: Swap<ModuleMemory>,
    /// What the cycle says of it.
    pub events: Receiver<SwapEvent>,
    /// The running variables at the change, once it is made.
    pub at_change: AtChange,
}

/// Plans a change from the program `running` describes to `new`, resetting what `resets`
/// names, with `probation` cycles on probation. Refused, naming every value, if a value can
/// be neither kept, converted nor reset.
pub fn prepare(
    running: &LayoutDescriptor,
    new: Arc<Module>,
    resets: &[String],
    probation: u64,
) -> Result<Prepared, Vec<Refused>> {
    let plan = ChangePlan::new(running, new.descriptor(), resets, Direction::Forward)?;
    let back = plan_back(new.descriptor(), running);
    let start = ModuleMemory::initial(new).map_err(|fault| {
        vec![Refused {
            path: "(its initial values)".into(),
            why: fault.to_string(),
        }]
    })?;
    // Once here, off the cycle: the conversion's code is then in memory when the cycle runs
    // it (its first run there took a few hundred microseconds more, in page faults).
    let _ = plan.apply(&vec![0; running.image_size], start.image());
    let _ = back.apply(start.image(), &vec![0; running.image_size]);
    let at_change: AtChange = Arc::default();
    let keep = at_change.clone();
    let forward = plan.clone();
    let convert: Convert<ModuleMemory> = Box::new(move |old: &ModuleMemory| {
        let mem = converted(&forward, old.image(), start)?;
        if let Ok(mut slot) = keep.lock() {
            *slot = Some(old.clone());
        }
        Ok(mem)
    });
    let (report, events) = channel();
    Ok(Prepared {
        plan,
        swap: Swap {
            convert,
            back: returning(back, at_change.clone()),
            probation,
            report,
        },
        events,
        at_change,
    })
}

/// A return to the variables `at_change` holds (`--back`): the values the program has now
/// carried back, narrowed where they fit; `None` if no change was made.
pub fn prepare_back(
    running: &LayoutDescriptor,
    at_change: &AtChange,
    probation: u64,
) -> Option<(ChangePlan, Swap<ModuleMemory>, Receiver<SwapEvent>)> {
    let previous = at_change.lock().ok()?.clone()?;
    let plan = plan_back(running, previous.module().descriptor());
    let (report, events) = channel();
    let forward = plan.clone();
    let convert: Convert<ModuleMemory> =
        Box::new(move |now: &ModuleMemory| converted(&forward, now.image(), previous));
    let refused: Convert<ModuleMemory> =
        Box::new(|_| Err("a return has no return of its own".into()));
    let swap = Swap {
        convert,
        back: refused,
        probation,
        report,
    };
    Some((plan, swap, events))
}

/// The plan from `from` back to `to`: every value carried back where it can be, the others
/// starting from their value at the change.
fn plan_back(from: &LayoutDescriptor, to: &LayoutDescriptor) -> ChangePlan {
    match ChangePlan::new(from, to, &[], Direction::Back) {
        Ok(plan) => plan,
        Err(refused) => {
            let resets: Vec<String> = refused.into_iter().map(|r| r.path).collect();
            ChangePlan::new(from, to, &resets, Direction::Back).unwrap_or_default()
        }
    }
}

/// The probation's way back: to the variables at the change, the values now carried back.
fn returning(plan: ChangePlan, at_change: AtChange) -> Convert<ModuleMemory> {
    Box::new(move |now: &ModuleMemory| {
        let previous = at_change
            .lock()
            .ok()
            .and_then(|slot| slot.clone())
            .ok_or("the variables before the change are gone")?;
        converted(&plan, now.image(), previous)
    })
}

/// `base` with the values of `image` carried over by `plan`.
fn converted(
    plan: &ChangePlan,
    image: &[u8],
    mut base: ModuleMemory,
) -> Result<ModuleMemory, String> {
    let new = plan.apply(image, base.image()).map_err(|refused| {
        let named: Vec<String> = refused.iter().map(ToString::to_string).collect();
        named.join("; ")
    })?;
    base.image_mut().copy_from_slice(&new);
    Ok(base)
}
