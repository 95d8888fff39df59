//! Who may write a variable: its [`Access`] and its [`Direction`], and the facts tools derive
//! from a variable's shape (elements, string capacity) so that every reader of a variable list
//! (the generated metadata, the segment's descriptor, the `plc` command, retain) answers them
//! the same way.

use crate::IecType;
use core::fmt;

/// Whether tools may write a variable.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Access {
    /// Tools may write it (`plc set`, an HMI), subject to its direction.
    ReadWrite,
    /// `#[plc(read_only)]`: tools may only read it (the variable editor's "Read Only").
    ReadOnly,
}

/// Where a variable's value comes from, which decides who may write it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Direction {
    /// Written by the hardware each cycle (`%I`, an input PDO entry); tools may not write it.
    Input,
    /// Written by the program and sent to the hardware (`%Q`, an output PDO entry).
    Output,
    /// A request from outside (HMI setpoints, commands) that the program reads.
    Command,
    /// A report from the program to the outside; tools may not write it.
    Status,
    /// The program's own variable (the default).
    Internal,
}

impl Direction {
    /// Every direction, in the order messages list them.
    pub const ALL: [Direction; 5] = [
        Direction::Input,
        Direction::Output,
        Direction::Command,
        Direction::Status,
        Direction::Internal,
    ];

    /// The name used in `#[plc(direction = "...")]` and in JSON.
    pub const fn name(self) -> &'static str {
        match self {
            Direction::Input => "input",
            Direction::Output => "output",
            Direction::Command => "command",
            Direction::Status => "status",
            Direction::Internal => "internal",
        }
    }

    /// Parses a direction name.
    ///
    /// ```
    /// use plc_rules::Direction;
    /// assert_eq!(Direction::from_name("status"), Some(Direction::Status));
    /// assert_eq!(Direction::from_name("in"), None);
    /// ```
    pub fn from_name(name: &str) -> Option<Direction> {
        Direction::ALL.into_iter().find(|d| d.name() == name)
    }

    /// Whether tools may write a variable of this direction (not inputs, not status).
    pub const fn writable_from_outside(self) -> bool {
        !matches!(self, Direction::Input | Direction::Status)
    }
}

impl fmt::Display for Direction {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(self.name())
    }
}

/// Whether tools may write a variable: read-write, and neither an input nor a status.
///
/// ```
/// use plc_rules::{Access, Direction, access::writable_from_outside};
/// assert!(writable_from_outside(Access::ReadWrite, Direction::Command));
/// assert!(!writable_from_outside(Access::ReadWrite, Direction::Input));
/// assert!(!writable_from_outside(Access::ReadOnly, Direction::Internal));
/// ```
pub const fn writable_from_outside(access: Access, direction: Direction) -> bool {
    matches!(access, Access::ReadWrite) && direction.writable_from_outside()
}

/// Number of elements of a variable with these dimensions: their product, 1 for a scalar.
///
/// ```
/// assert_eq!(plc_rules::access::elements(&[3, 4]), 12);
/// assert_eq!(plc_rules::access::elements(&[]), 1);
/// ```
pub const fn elements(dims: &[usize]) -> usize {
    let mut n = 1usize;
    let mut i = 0;
    while i < dims.len() {
        n = n.saturating_mul(dims[i]);
        i += 1;
    }
    n
}

/// Bytes of one element of a variable of `size` bytes in all (0 when it has no elements).
pub const fn element_size(size: usize, dims: &[usize]) -> usize {
    match elements(dims) {
        0 => 0,
        n => size / n,
    }
}

/// Capacity in bytes of each `STRING` element of a variable (0 for other types): a string's
/// image is its capacity, so the capacity is the size of one element.
///
/// ```
/// use plc_rules::{IecType, access::string_capacity};
/// assert_eq!(string_capacity(IecType::String, 128, &[2]), 64);
/// assert_eq!(string_capacity(IecType::Uint, 2, &[]), 0);
/// ```
pub const fn string_capacity(iec_type: IecType, size: usize, dims: &[usize]) -> usize {
    match iec_type {
        IecType::String => element_size(size, dims),
        _ => 0,
    }
}
