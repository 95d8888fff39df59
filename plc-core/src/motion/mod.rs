//! Motion: CiA 402 servo axes driven as PLCopen Motion Control drives them.
//!
//! - [`Cia402`]: a drive's process data (controlword, statusword, modes, target and actual
//!   position and velocity, following error, error code) and its state machine
//!   ([`DriveState`]).
//! - [`Axis`]: PLCopen's `AXIS_REF`: the drive, the scale from increments to user units, the
//!   PLCopen state ([`AxisState`]) and the set point, advanced once per cycle by
//!   [`Axis::cycle`] with a trapezoidal profile at the cycle's period, written to the drive in
//!   cyclic synchronous position mode.
//! - The function blocks with PLCopen's names and members: [`McPower`], [`McHome`],
//!   [`McMoveAbsolute`], [`McMoveRelative`], [`McMoveVelocity`], [`McStop`], [`McReset`],
//!   [`McReadActualPosition`]. A move started while another runs takes the axis over from
//!   where it is (the other reports `CommandAborted`); errors carry an `ErrorID`
//!   ([`error`]).
//!
//! Every member is in the program's image, so tools and OPC UA see `axis.state` and
//! `power.Status`:
//!
//! ```
//! use plc_core::GlobalMemory;
//! use plc_core::motion::{Axis, McMoveAbsolute, McPower};
//!
//! #[derive(GlobalMemory, Debug, Clone)]
//! pub struct Press {
//!     /// The ram's servo axis, in mm.
//!     #[plc(quantity = "length")]
//!     pub ram: Axis,
//!     pub power: McPower,
//!     pub to_top: McMoveAbsolute,
//! }
//!
//! let gm = Press::default();
//! for path in ["ram.drive.statusword", "ram.actual_position", "power.Status", "to_top.Busy"] {
//!     assert!(Press::find(path).is_some(), "{path}");
//! }
//! assert_eq!(gm.ram.scale, 1000.0);
//! ```
//!
//! A cycle of a program with one axis:
//!
//! ```
//! use plc_core::motion::{Axis, McMoveAbsolute, McPower};
//! # use plc_core::motion::DriveState;
//! let mut axis = Axis::default();
//! let (mut power, mut to) = (McPower::default(), McMoveAbsolute::default());
//! # axis.drive.statusword = DriveState::OperationEnabled.statusword_bits();
//! // Each cycle: the drive's inputs copied into `axis.drive`, then
//! axis.read_drive();
//! power.call(&mut axis, true);
//! to.call(&mut axis, power.Status, 120.0, 50.0, 500.0, 500.0);
//! axis.cycle(0.001);
//! // ... and `axis.drive`'s outputs copied to the drive.
//! assert!(to.Busy);
//! ```

mod axis;
mod blocks;
mod cia402;
pub mod error;
mod profile;

pub use axis::{Axis, AxisState};
pub use blocks::{
    McHome, McMoveAbsolute, McMoveRelative, McMoveVelocity, McPower, McReadActualPosition, McReset,
    McStop,
};
pub use cia402::{Cia402, DriveState, ENTRIES, command, mode};
pub use profile::{Limits, SetPoint};

#[cfg(test)]
mod tests;
