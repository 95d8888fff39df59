//! The variable-editor naming rules for variables (and link identifiers).
//!
//! A name begins with a letter or an underscore, followed by letters, digits or underscores
//! (ASCII), has no two consecutive underscores, is not a reserved keyword, an IEC type name, or
//! the name of a standard function or function block, and is compared case-insensitively.
//!
//! ```
//! use plc_rules::names::{check_name, NameError};
//! assert_eq!(check_name("ls_centering_neg"), Ok(()));
//! assert_eq!(check_name("motor__speed"), Err(NameError::DoubleUnderscore));
//! assert_eq!(check_name("ton"), Err(NameError::Reserved("TON")));
//! assert!(plc_rules::names::same_name("Speed", "SPEED"));
//! ```

// The reserved words (the tables and `reserved_word`) are in `reserved`; the rules a name must
// follow, `NameError` and comparing names in `check`, which uses `reserved`.
mod check;
mod reserved;
#[cfg(test)]
mod tests;

#[cfg(feature = "std")]
pub use check::nearest;
pub use check::{NameError, check_name, same_name};
pub use reserved::{KEYWORDS, STANDARD_FUNCTIONS, TYPE_NAMES, reserved_word};
