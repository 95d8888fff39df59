//! The standard function blocks of IEC 61131-3: timers ([`Ton`], [`Tof`], [`Tp`]), edge
//! detection ([`RTrig`], [`FTrig`]), counters ([`Ctu`], [`Ctd`], [`Ctud`]) and bistables
//! ([`Sr`], [`Rs`]).
//!
//! Each block is a plain `Copy` struct whose public fields carry the IEC 61131-3 member names
//! (`IN`, `PT`, `Q`, `ET`, `CLK`, `CU`, `CV`, ...), so a program reads `delay.Q` or
//! `parts.CV` as in Structured Text. Inputs are the arguments of `call`, which also stores
//! them in the input members (so a tool watching the block sees what it was called with),
//! and returns the main output. The state a block keeps between calls (the previous input of
//! an edge, a timer's start) is in ordinary documented fields of type `bool` or
//! [`Time`](crate::Time) too: no heap, no clock, nothing hidden, so a whole block can live in a
//! variable image and be retained or inspected. `Default` is the state IEC 61131-3 starts
//! a block in: every member zero or `FALSE`.
//!
//! Timers take the time as an argument: pass `ctx.now()` (plc-io's `Context`), the time of the
//! cycle's start, so every timer of one cycle sees the same instant and a test can drive the
//! clock.
//!
//! ```
//! use plc_core::Time;
//! use plc_core::fb::{RTrig, Ton};
//!
//! let mut button = RTrig::default();
//! let mut delay = Ton::default();
//! let pt = Time::from_millis(500);
//! // Cycle at 0 ms: the button is pressed.
//! assert!(button.call(true));
//! assert!(!delay.call(Time::ZERO, true, pt));
//! // Cycle at 500 ms: still pressed; no new edge, and the delay has run out.
//! assert!(!button.call(true));
//! assert!(delay.call(Time::from_millis(500), true, pt));
//! assert_eq!(delay.ET, pt);
//! ```

mod bistables;
mod counters;
mod timers;
mod triggers;

pub use bistables::{Rs, Sr};
pub use counters::{Ctd, Ctu, Ctud};
pub use timers::{Tof, Ton, Tp};
pub use triggers::{FTrig, RTrig};
