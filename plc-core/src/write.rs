//! One write from a tool to the running program, and the one check it passes.
//!
//! A [`Write`] names a basic value by its variable's index and its leaf number (an array's
//! element, or a value inside a structure; see `plc_rules::path`) and carries the new value.
//! [`check`] decides whether it may be applied, against any description of the variables (the
//! program's own [`VarInfo`](crate::VarInfo) table, or a segment's descriptor in a tool): the
//! variable exists and is writable from outside, the leaf exists and is writable, and the
//! value fits its type. A REAL or LREAL takes only finite numbers from a tool: NaN and the
//! infinities are refused here and nowhere else, with one message on every path.
//!
//! The tool checks before it sends, the owner checks again when the request arrives (it trusts
//! no other process), and the OPC UA server goes through the same tool side: one function.
//!
//! ```
//! use plc_core::write::{check, Write};
//! use plc_core::{GlobalMemory, Value};
//!
//! #[derive(GlobalMemory, Debug, Clone)]
//! struct Gm {
//!     #[plc(direction = "command")]
//!     speed: f32,
//!     #[plc(direction = "input")]
//!     pressure: f32,
//! }
//!
//! let ok = check(Gm::VARIABLES, Write { index: 0, leaf: 0, value: Value::Int(2) }).unwrap();
//! assert_eq!(ok.write().value, Value::Real(2.0));
//! let nan = Write { index: 0, leaf: 0, value: Value::Real(f64::NAN) };
//! assert_eq!(
//!     check(Gm::VARIABLES, nan).unwrap_err().to_string(),
//!     "`speed`: not a finite number: REAL takes no NaN or infinity from a tool"
//! );
//! let input = Write { index: 1, leaf: 0, value: Value::Real(1.0) };
//! assert_eq!(
//!     check(Gm::VARIABLES, input).unwrap_err().to_string(),
//!     "`pressure` cannot be written: it is an input: the hardware writes it every cycle"
//! );
//! ```

use crate::{Direction, IecType, TypeFamily, Value, ValueError};
use core::fmt;
use plc_rules::access::{Access, writable_from_outside};
use plc_rules::path::{self, Node};

/// One write: the basic value numbered `leaf` of variable `index` becomes `value`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Write {
    /// The variable's index in the program's declaration.
    pub index: usize,
    /// The basic value inside it: 0 for a scalar, the element of an array of basic values, a
    /// leaf of a structure (row-major over elements, members in declaration order).
    pub leaf: usize,
    /// The new value, as given (fitted to the variable's type by [`check`]).
    pub value: Value,
}

/// A [`Write`] that passed [`check`], its value fitted to the variable's type. Only `check`
/// makes one, so a queue of these holds nothing unchecked.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Checked(Write);

impl Checked {
    /// The write, as it will be applied.
    pub fn write(&self) -> &Write {
        &self.0
    }

    /// Takes it apart. A test of the program's own checks (a hostile tool) makes one from a
    /// write nobody checked: only behind the crate's hidden API.
    #[doc(hidden)]
    pub fn __unchecked(write: Write) -> Checked {
        Checked(write)
    }
}

/// What a variable description gives the check beyond the path's navigation.
pub trait Target: Node {
    /// Its IEC type (of one element).
    fn iec_type(&self) -> IecType;
    /// A STRING's capacity in bytes (0 for other types).
    fn string_capacity(&self) -> usize;
}

/// Why a write was refused, naming the variable (or `variable.member`) and the reason.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Refusal<'a, N> {
    /// No variable has this index.
    NoVariable {
        /// The index asked for.
        index: usize,
        /// How many variables there are.
        count: usize,
    },
    /// The variable (or the member inside it) is read-only, an input or a status.
    NotWritable {
        /// The variable.
        var: &'a N,
        /// The basic value asked for (a value inside a structure is named by its path).
        leaf: usize,
        /// Why, as [`not_writable_reason`] says it.
        reason: &'static str,
    },
    /// The leaf is beyond the variable's basic values.
    NoElement {
        /// The variable.
        var: &'a N,
        /// The leaf asked for.
        leaf: usize,
        /// Its basic values.
        len: usize,
    },
    /// The value does not fit the variable's type (kind, range, capacity, a NaN or infinity).
    Value {
        /// The variable.
        var: &'a N,
        /// The basic value asked for (a value inside a structure is named by its path).
        leaf: usize,
        /// What is wrong.
        error: ValueError,
    },
}

impl<N: Node> Refusal<'_, N> {
    /// What messages name: the variable, or for a value inside a structure its path
    /// (`axes[1].pos`), as `plc get` takes it (empty for [`NoVariable`](Refusal::NoVariable)).
    pub fn label(&self) -> Label<'_, N> {
        match *self {
            Refusal::NoVariable { .. } => Label {
                var: None,
                leaf: None,
            },
            // The leaf is none of the variable's: the variable itself, not its first value.
            Refusal::NoElement { var, .. } => Label {
                var: Some(var),
                leaf: None,
            },
            Refusal::NotWritable { var, leaf, .. } | Refusal::Value { var, leaf, .. } => Label {
                var: Some(var),
                leaf: Some(leaf),
            },
        }
    }
}

/// A variable's name, or the path of a value inside a structure, shown without allocating.
pub struct Label<'a, N> {
    var: Option<&'a N>,
    /// `None`: the variable as a whole.
    leaf: Option<usize>,
}

/// The name of basic value `leaf` of variable `index` as messages and logs give it: the
/// variable's name, or the path of a value inside a structure (`axes[1].pos`); an array's
/// element is not named (empty if there is no such variable).
///
/// ```
/// use plc_core::{GlobalMemory, write::label};
///
/// #[derive(GlobalMemory, Debug, Clone)]
/// struct Gm {
///     lamp: bool,
/// }
///
/// assert_eq!(label(Gm::VARIABLES, 0, 0).to_string(), "lamp");
/// ```
pub fn label<N: Node>(vars: &[N], index: usize, leaf: usize) -> Label<'_, N> {
    Label {
        var: vars.get(index),
        leaf: Some(leaf),
    }
}

impl<N: Node> fmt::Display for Label<'_, N> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let Some(var) = self.var else { return Ok(()) };
        f.write_str(var.name())?;
        let Some(leaf) = self.leaf else {
            return Ok(());
        };
        // Down the structures to the leaf: each level's element (of an array of structures)
        // and the member holding it. A basic variable is named alone, its element apart.
        let (mut node, mut leaf) = (var, leaf);
        while !node.members().is_empty() {
            let per_element = path::element_leaves(node).max(1);
            if !node.dims().is_empty() {
                f.write_str("[")?;
                write_coordinates(f, leaf / per_element, node.dims())?;
                f.write_str("]")?;
            }
            leaf %= per_element;
            let mut inside = None;
            for m in node.members() {
                let n = path::leaves(m);
                if leaf < n {
                    inside = Some(m);
                    break;
                }
                leaf -= n;
            }
            let Some(member) = inside else { break };
            write!(f, ".{}", member.name())?;
            node = member;
        }
        Ok(())
    }
}

/// Row-major element `flat` of an array of `dims` as a path writes it (`1,2`).
fn write_coordinates(f: &mut fmt::Formatter<'_>, flat: usize, dims: &[usize]) -> fmt::Result {
    let mut stride: usize = dims.iter().product();
    for (i, &d) in dims.iter().enumerate() {
        stride /= d.max(1);
        let c = (flat / stride.max(1)) % d.max(1);
        if i > 0 {
            f.write_str(",")?;
        }
        write!(f, "{c}")?;
    }
    Ok(())
}

impl<N: Node> fmt::Display for Refusal<'_, N> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let label = self.label();
        match self {
            Refusal::NoVariable { index, count } => write!(
                f,
                "there is no variable number {index}: the program has {count}"
            ),
            Refusal::NotWritable { reason, .. } => {
                write!(f, "`{label}` cannot be written: {reason}")
            }
            Refusal::NoElement { leaf, len, .. } => write!(
                f,
                "`{label}` has {len} elements: element {leaf} is out of range 0..{len}"
            ),
            Refusal::Value { error, .. } => write!(f, "`{label}`: {error}"),
        }
    }
}

#[cfg(feature = "std")]
impl<N: Node + fmt::Debug> std::error::Error for Refusal<'_, N> {}

/// Why a variable that is read-only, an input or a status cannot be written from outside.
pub fn not_writable_reason(read_only: bool, direction: Direction) -> &'static str {
    if read_only {
        "it is read-only"
    } else if direction == Direction::Input {
        "it is an input: the hardware writes it every cycle"
    } else {
        "it is a status variable: the program reports it"
    }
}

/// Checks `write` against the variables `vars`: the write as it will be applied (its value
/// fitted to the type), or why not.
pub fn check<N: Target>(vars: &[N], write: Write) -> Result<Checked, Refusal<'_, N>> {
    check_with(vars, write, true)
}

/// Checks a force (`plc force`): as [`check`], except that any basic value may be forced,
/// inputs, status and read-only values included, as TwinCAT and CODESYS force: the variable
/// and leaf exist and the value fits (finite for REAL and LREAL). Who may force is the write
/// policy's to decide.
///
/// ```
/// use plc_core::write::{check, check_force, Write};
/// use plc_core::{GlobalMemory, Value};
///
/// #[derive(GlobalMemory, Debug, Clone)]
/// struct Gm {
///     #[plc(direction = "input")]
///     door_closed: bool,
/// }
///
/// let force = Write { index: 0, leaf: 0, value: Value::Bool(true) };
/// assert!(check(Gm::VARIABLES, force).is_err());
/// assert_eq!(check_force(Gm::VARIABLES, force).unwrap().write().value, Value::Bool(true));
/// ```
pub fn check_force<N: Target>(vars: &[N], write: Write) -> Result<Checked, Refusal<'_, N>> {
    check_with(vars, write, false)
}

fn check_with<N: Target>(
    vars: &[N],
    write: Write,
    from_outside: bool,
) -> Result<Checked, Refusal<'_, N>> {
    let Some(var) = vars.get(write.index) else {
        return Err(Refusal::NoVariable {
            index: write.index,
            count: vars.len(),
        });
    };
    if from_outside && !writable_from_outside(var.access(), var.direction()) {
        return Err(Refusal::NotWritable {
            var,
            leaf: write.leaf,
            reason: not_writable_reason(var.access() == Access::ReadOnly, var.direction()),
        });
    }
    let Some(found) = path::leaf(vars, write.index, write.leaf) else {
        return Err(Refusal::NoElement {
            var,
            leaf: write.leaf,
            len: path::leaves(var),
        });
    };
    // A value inside a structure is its member's, with the member's own access and type.
    let leaf = found.node;
    if from_outside && !found.writable {
        return Err(Refusal::NotWritable {
            var,
            leaf: write.leaf,
            reason: not_writable_reason(true, leaf.direction()),
        });
    }
    let refuse = |error| Refusal::Value {
        var,
        leaf: write.leaf,
        error,
    };
    let value = write
        .value
        .fit(leaf.iec_type(), leaf.string_capacity())
        .map_err(refuse)?;
    if let Value::Real(r) = value
        && leaf.iec_type().family() == TypeFamily::Real
        && !r.is_finite()
    {
        return Err(refuse(ValueError::NotFinite {
            expected: leaf.iec_type(),
        }));
    }
    Ok(Checked(Write { value, ..write }))
}

impl Target for crate::VarInfo {
    fn iec_type(&self) -> IecType {
        self.iec_type
    }

    fn string_capacity(&self) -> usize {
        crate::VarInfo::string_capacity(self)
    }
}
