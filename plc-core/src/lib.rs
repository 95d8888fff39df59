//! Runtime types of plc-vars: declare the variables of a PLC-style control program as a plain
//! Rust struct, and get a fixed shared-memory layout, bit packing, metadata and compile-time
//! checked declarations from `#[derive(GlobalMemory)]`.
//!
//! ```
//! use plc_core::{FixedString, GlobalMemory};
//!
//! #[derive(GlobalMemory, Debug, Clone)]
//! pub struct Gm {
//!     /// Digital inputs of the IO module
//!     #[plc(link = "ethercat.impact67_0.digital_inputs", direction = "input")]
//!     pub impact67_0_digital_inputs: u16,
//!     #[plc(source = "impact67_0_digital_inputs", bit = 0)]
//!     pub ls_centering_neg: bool,
//!     #[plc(initial = "TEST-001", description = "Test identifier")]
//!     pub info_test_id: FixedString<64>,
//!     #[plc(nonvolatile, initial = 12.5)]
//!     pub press_home_offset_mm: f64,
//! }
//!
//! let mut gm = Gm::default();
//! assert_eq!(gm.info_test_id, "TEST-001");
//! gm.impact67_0_digital_inputs = 1;
//! gm.unpack_bits();
//! assert!(gm.ls_centering_neg);
//! assert_eq!(Gm::VARIABLES[3].initial, Some("12.5"));
//! ```
//!
//! Durations are [`Time`] (IEC 61131-3 `LTIME`, nanoseconds, literals such as `T#1s500ms`);
//! the standard function blocks (TON, TOF, TP, R_TRIG, F_TRIG, CTU, CTD, CTUD, SR, RS) are in
//! [`fb`].
//!
//! Crate features: `std` (default; error types implement `std::error::Error`), `derive`
//! (default; re-exports `#[derive(GlobalMemory)]`), `serde` (serde for `FixedString`, `Time`
//! as its literal, `IecType`, `Access`, `Direction`). Without default features the crate is
//! `no_std` and needs no allocator.
#![cfg_attr(not(any(feature = "std", test)), no_std)]
#![deny(missing_docs)]

pub mod alarm;
pub mod convert;
pub mod fb;
mod fixed_string;
mod global_memory;
mod image_bytes;
pub mod memory;
pub mod motion;
pub mod place;
mod plc_type;
mod process_image;
mod raw_bits;
mod value;
pub mod write;

#[doc(hidden)]
#[path = "private.rs"]
#[allow(missing_docs)]
pub mod __private;

/// This crate's version: part of the fingerprint a program module and its host compare, since
/// both must agree on the image format it defines.
pub const VERSION: &str = env!("CARGO_PKG_VERSION");

pub use fixed_string::{FixedString, Truncated};
pub use global_memory::{
    Access, BitMapping, BusSource, Direction, GlobalMemory, Location, SetError, VarInfo,
    layout_hash,
};
pub use plc_rules::{
    AddressError, AddressErrorKind, Area, IecAddress, IecType, Size, Time, TimeError, TypeFamily,
    UnknownType,
};

/// The declaration rules the derive applies, for tools that check what a user typed before it
/// reaches a declaration: [`names`](rules::names) (the variable-editor rules), [`link`](rules::link),
/// [`address`](rules::address), [`capacity`](rules::capacity), [`widening`](rules::widening)
/// and [`layout`](rules::layout), with their error types ([`NameError`](rules::NameError),
/// [`LinkError`](rules::LinkError), [`AddressErrorKind`]). This is the `plc-rules` crate, so a
/// program needs no dependency of its own to name them.
///
/// ```
/// use plc_core::rules::{Link, LinkError, NameError, names};
/// assert_eq!(names::check_name("motor__speed"), Err(NameError::DoubleUnderscore));
/// assert_eq!(Link::parse("ethercat.io_0.inputs").map(|l| l.entry), Ok("inputs"));
/// assert_eq!(Link::parse("modbus.io_0.inputs"), Err(LinkError::UnknownBus));
/// ```
pub use plc_rules as rules;
pub use plc_type::{BitSource, ElementError, PlcScalar, PlcType};
pub use process_image::{ByteOrder, ProcessImage, ProcessImageError, ProcessValue};
pub use value::{Value, ValueError};

/// `#[derive(GlobalMemory)]`: see [`GlobalMemory`] and the crate documentation.
#[cfg(feature = "derive")]
pub use plc_derive::GlobalMemory;

/// `#[derive(PlcStruct)]`: a structure type for the fields of a `GlobalMemory` or of another
/// structure; see the crate documentation.
#[cfg(feature = "derive")]
pub use plc_derive::PlcStruct;
