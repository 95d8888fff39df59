//! Declaration rules of plc-vars, free of dependencies so that the derive macro (at expansion),
//! `plc-core` (at compile time of the user's program) and `plc-io` (at run time) apply exactly the
//! same rules.
//!
//! - [`IecType`]: the IEC 61131-3 elementary types and their Rust equivalents (the JSON variable-list format's type table).
//! - [`widening`]: IEC 61131-3's implicit widening matrices.
//! - [`names`]: the variable-editor naming rules.
//! - [`link`]: `ethercat.<device>.<entry>` hardware links.
//! - [`address`]: IEC 61131-3 direct addresses such as `%IX100.4`.
//! - [`capacity`]: the limits on strings and arrays.
//! - [`layout`]: the layout hash that lets a reader detect a changed declaration.
//! - [`path`]: paths such as `axes[1].pos` that name one value inside the variables.
//! - [`time`]: [`Time`] (`LTIME`) and the IEC duration literal grammar (`T#1s500ms`).
//!
//! ```
//! use plc_rules::{IecType, widening::can_widen};
//! let t: IecType = "i16".parse().unwrap();
//! assert_eq!(t, IecType::Int);
//! assert!(can_widen(t, IecType::Dint));
//! ```
#![cfg_attr(not(any(feature = "std", test)), no_std)]
#![deny(missing_docs)]

pub mod access;
pub mod address;
#[cfg(feature = "bus")]
pub mod bus;
pub mod capacity;
#[cfg(feature = "std")]
pub mod decl;
mod iec_type;
pub mod layout;
pub mod link;
pub mod names;
pub mod path;
pub mod time;
pub mod widening;

pub use access::{Access, Direction};
pub use address::{AddressError, AddressErrorKind, Area, IecAddress, Size};
pub use iec_type::{IecType, TypeFamily, UnknownType};
pub use link::{Link, LinkError};
pub use names::NameError;
pub use time::{Time, TimeError};
pub use widening::WideningOptions;
