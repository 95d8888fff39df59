//! Alarms declared with the variables (`#[plc(alarm = "...")]`, a list's `"alarm"`), as
//! IEC 62682 (alarm management) describes them: [`AlarmDecl`], what the declaration says of
//! each alarm, and the pure evaluator ([`Alarms`], with `std`) that turns values into states
//! and transitions.
//!
//! ```
//! use plc_core::GlobalMemory;
//! use plc_core::alarm::{AlarmKind, Level};
//!
//! #[derive(GlobalMemory, Debug, Clone)]
//! struct Gm {
//!     #[plc(alarm = "Guard door open")]
//!     door: bool,
//!     #[plc(alarm(text = "Oil temperature", high = 80.0, high_high = 95.0, deadband = 1.0,
//!                 delay = "2s", severity = 600))]
//!     oil: f32,
//! }
//! assert_eq!(Gm::ALARMS.len(), 2);
//! assert_eq!((Gm::ALARMS[0].text, Gm::ALARMS[0].severity), ("Guard door open", 500));
//! let AlarmKind::Limit(limits) = Gm::ALARMS[1].condition.kind else { unreachable!() };
//! assert_eq!((limits.high, limits.deadband), (Some(80.0), 1.0));
//! assert_eq!(Level::HighHigh.to_string(), "high-high");
//! ```

mod decl;
#[cfg(feature = "std")]
mod eval;
#[cfg(feature = "std")]
mod names;
#[cfg(feature = "std")]
mod state;
#[doc(hidden)]
pub mod table;
#[cfg(all(test, feature = "std"))]
mod tests;

pub use decl::{AlarmDecl, AlarmKind, Condition, Level, Limits, SuppressWhen};
#[cfg(feature = "std")]
pub use eval::{Alarms, DEFAULT_MAX_SHELVE, Sample};
#[cfg(feature = "std")]
pub use names::{alarm_paths, resolve_suppress};
#[cfg(feature = "std")]
pub use state::{ActionError, AlarmEvent, AlarmState, EventKind, Shelf, Snapshot};
