//! The one declaration model: what the derive reads from a struct and the importer from a JSON
//! or CSV variable list, and the one [`check`] that applies every declaration rule to it.
//!
//! Each front end builds a [`Decl`] whose attributes carry a location `L` of its own (a span in
//! the derive, a variable and field in the importer), calls [`check`], and words each
//! [`Issue`] with [`Issue::message`], choosing only how names are quoted and how another place
//! is named ([`Wording`]). So a rule is written once, and a Rust struct and the same variables
//! as JSON get the same errors in the same words. The repository's `docs/rules.md` lists
//! every rule.
//!
//! ```
//! use plc_rules::decl::{self, Decl, KnownType, Located, Var, Wording};
//! use plc_rules::IecType;
//!
//! // Locations here are plain strings; the derive uses spans, the importer JSON paths.
//! let known = |iec, at| Located::new(KnownType::scalar(iec).into(), at);
//! let inputs = Var::new(Located::new("inputs".into(), "inputs"), "inputs", known(IecType::Uint, "inputs"));
//! let mut flag = Var::new(Located::new("flag".into(), "flag"), "flag", known(IecType::Bool, "flag"));
//! flag.source = Some(Located::new("inputs".to_string(), "flag.source"));
//! flag.bit = Some(Located::new(16, "flag.bit"));
//! let checked = decl::check(&Decl { vars: vec![inputs, flag], unaligned: false, structure: false });
//!
//! struct Plain;
//! impl Wording<&'static str> for Plain {
//!     fn name(&self, name: &str) -> String { format!("`{name}`") }
//!     fn place(&self, _: &&'static str) -> String { String::new() }
//! }
//! let issue = &checked.issues[0];
//! assert_eq!(issue.at, "flag.bit");
//! assert_eq!(issue.message(&Plain), "16 is out of range for source `inputs` (u16 has bits 0..=15)");
//! ```

mod alarm;
mod check;
mod initial;
mod issue;
mod keys;
mod report;

pub use alarm::{Alarm, DEFAULT_SEVERITY, DelayError, LIMIT_KEYS, parse_delay};
pub use check::{Checked, Resolved, check, type_rules};
pub use initial::initial_misfit;
pub use issue::{Expected, Issue, IssueKind, KIND_NAMES, Wording};
pub use report::{MAX_UNIT_CHARS, UnitProblem};

use crate::IecType;
pub use crate::access::{Access, Direction};
use std::string::String;
use std::vec::Vec;

/// A value and where the user wrote it.
#[derive(Clone, Debug, PartialEq)]
pub struct Located<T, L> {
    /// The value.
    pub value: T,
    /// Where it was written.
    pub at: L,
}

impl<T, L> Located<T, L> {
    /// A value at a location.
    pub fn new(value: T, at: L) -> Self {
        Located { value, at }
    }
}

/// A variable's type where the declaration shows it: the element type, a string's capacity and
/// the array dimensions (outermost first).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct KnownType {
    /// IEC type of one element, as its Rust type maps it (`u16` is `UINT`).
    pub iec: IecType,
    /// A string's capacity in bytes (`FixedString<N>`, `max_length`).
    pub capacity: Option<u64>,
    /// Array dimensions, outermost first; empty for a scalar.
    pub dims: Vec<u64>,
}

impl KnownType {
    /// A scalar of type `iec` (a string gets no capacity: set it).
    pub fn scalar(iec: IecType) -> KnownType {
        KnownType {
            iec,
            capacity: None,
            dims: Vec::new(),
        }
    }

    /// Whether it is a scalar (no dimensions).
    pub fn is_scalar(&self) -> bool {
        self.dims.is_empty()
    }

    /// The Rust type of one element, as messages and generated code write it: `u16`,
    /// `FixedString<64>`.
    pub fn element_name(&self) -> String {
        match self.capacity {
            Some(n) => format!("FixedString<{n}>"),
            None => String::from(self.iec.rust_name()),
        }
    }

    /// The whole Rust type, arrays included: `[[f32; 4]; 3]`.
    pub fn rust_type(&self) -> String {
        self.dims
            .iter()
            .rev()
            .fold(self.element_name(), |inner, d| format!("[{inner}; {d}]"))
    }
}

/// What the declaration tells of a variable's type.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum DeclType {
    /// Visible in the declaration: every rule about it is checked here.
    Known(KnownType),
    /// Not visible: a type alias (the compiler checks it, through the derive's assertions), or
    /// a type that is missing or unknown (its own error is reported). The rules that need the
    /// type are skipped, so one mistake does not cascade into others.
    Unknown,
}

impl From<KnownType> for DeclType {
    fn from(k: KnownType) -> Self {
        DeclType::Known(k)
    }
}

impl DeclType {
    /// The type, if the declaration shows it.
    pub fn known(&self) -> Option<&KnownType> {
        match self {
            DeclType::Known(k) => Some(k),
            DeclType::Unknown => None,
        }
    }
}

/// An initial value as written.
#[derive(Clone, Debug, PartialEq)]
pub enum InitialValue {
    /// `true` or `false`.
    Bool(bool),
    /// A whole number.
    Int(i128),
    /// A whole number beyond `i128`: only a REAL or LREAL can hold it.
    BigInt(f64),
    /// A number with a fraction or an exponent.
    Float(f64),
    /// Text.
    Text(String),
    /// Something that is none of these (a JSON list, object or `null`).
    Other,
}

/// `initial = ...`: the value and its text as the user wrote it, for messages.
#[derive(Clone, Debug, PartialEq)]
pub struct Initial {
    /// The value.
    pub value: InitialValue,
    /// The text as written (`-3`, `12.5`, `"TEST-001"`).
    pub text: String,
}

/// One variable of a declaration.
#[derive(Clone, Debug, PartialEq)]
pub struct Var<L> {
    /// The symbol name (`name = ".."`, the field name, the JSON key).
    pub name: Located<String, L>,
    /// Whether `name` is surely the variable's name. The derive says no when a field's
    /// attribute did not parse far enough to read its `name = ".."`: such a field is not
    /// name-checked, rather than blamed for a name the user may not have given it.
    pub name_known: bool,
    /// What `source` refers to: the Rust field name in the derive, the name in a list.
    pub field: String,
    /// The type, and where it is written.
    pub ty: Located<DeclType, L>,
    /// Where the string capacity is written, where apart from the type (a list's
    /// `max_length`).
    pub capacity_at: Option<L>,
    /// Where the dimensions are written, where apart from the type (a list's `dims`).
    pub dims_at: Option<L>,
    /// `link = "ethercat.<device>.<entry>"`.
    pub link: Option<Located<String, L>>,
    /// `source = "<variable>"` of a bit-mapped bool.
    pub source: Option<Located<String, L>>,
    /// `bit = N` of a bit-mapped bool.
    pub bit: Option<Located<i64, L>>,
    /// `at = "%IW4"`, as written.
    pub at: Option<Located<String, L>>,
    /// `initial = ...`.
    pub initial: Option<Located<Initial, L>>,
    /// `direction = "..."`, as given.
    pub direction: Option<Located<Direction, L>>,
    /// `iec_type = "WORD"`: the bit-string type declared instead of the integer one.
    pub iec_type: Option<Located<IecType, L>>,
    /// `nonvolatile` (or `retain`).
    pub nonvolatile: bool,
    /// `read_only`.
    pub read_only: bool,
    /// The description (`description = ".."` or the doc comment).
    pub description: String,
    /// `ux`: the variable is meant for an operator UI.
    pub ux: bool,
    /// `quantity = "force"`: the physical quantity a display uses to pick units.
    pub quantity: Option<Located<String, L>>,
    /// `unit = "mm"`: the engineering unit the value is in, as tools show it beside the
    /// value (a number's only).
    pub unit: Option<Located<String, L>>,
    /// `deadband = 0.5`: the reporting deadband, how far a number must move before a change
    /// is published (data by exception); not the deadband of a limit alarm, which is
    /// `alarm(deadband = ...)`.
    pub deadband: Option<Located<f64, L>>,
    /// `alarm = ".."` or `alarm(...)`: an alarm on the variable (for an array of bools, one
    /// per element; on a structure's member, one per instance).
    pub alarm: Option<Alarm<L>>,
}

impl<L> Var<L> {
    /// A variable with only a name (and where it is written), the name `source` refers to it
    /// by, and a type; no attributes.
    pub fn new(name: Located<String, L>, field: &str, ty: Located<DeclType, L>) -> Var<L> {
        Var {
            name,
            name_known: true,
            field: String::from(field),
            ty,
            capacity_at: None,
            dims_at: None,
            link: None,
            source: None,
            bit: None,
            at: None,
            initial: None,
            direction: None,
            iec_type: None,
            nonvolatile: false,
            read_only: false,
            description: String::new(),
            ux: false,
            quantity: None,
            unit: None,
            deadband: None,
            alarm: None,
        }
    }
}

/// The attribute keys every declaration format has (the derive's `#[plc(...)]` keys and a
/// variable list's fields add their own: `name` and `iec_type`; `type`, `max_length` and
/// `dims`). `retain` is another name for `nonvolatile`.
pub const ATTRIBUTE_KEYS: &[&str] = &[
    "link",
    "source",
    "bit",
    "at",
    "initial",
    "nonvolatile",
    "retain",
    "description",
    "read_only",
    "direction",
    "ux",
    "quantity",
    "unit",
    "deadband",
    "alarm",
];

/// A whole declaration: the variables in order, and the settings that rules depend on.
#[derive(Clone, Debug, PartialEq)]
pub struct Decl<L> {
    /// The variables, in declaration order.
    pub vars: Vec<Var<L>>,
    /// `#[plc(unaligned)]`: located W/D/L variables may start at any byte.
    pub unaligned: bool,
    /// The members of a structure type (`#[derive(PlcStruct)]`, a type of the JSON list's
    /// `types`) rather than a program's variables: no physical I/O (`link`, `at`), and
    /// `direction` marks IN and OUT parameters only.
    pub structure: bool,
}

#[cfg(test)]
mod agreement {
    include!("agreement_table.rs");

    use super::KIND_NAMES;

    #[test]
    fn every_rule_has_a_row_of_the_agreement_table_and_a_section_in_the_docs() {
        let docs = include_str!("../../../docs/rules.md");
        for kind in KIND_NAMES {
            assert!(
                ROWS.iter().any(|r| r.kinds.contains(kind)),
                "no row of the agreement table gives {kind}"
            );
            assert!(
                docs.contains(&format!("### `{kind}`")),
                "docs/rules.md has no section for {kind}"
            );
        }
        for row in ROWS {
            assert!(row.rust.starts_with("struct") || row.rust.starts_with("#["));
            // A row without a JSON form says why in its rule.
            assert!(row.json.is_some() || row.rule.contains('('), "{}", row.rule);
            for kind in sorted(row.kinds.iter().copied()) {
                assert!(KIND_NAMES.contains(&kind), "{kind} is no issue kind");
            }
        }
        assert!(ROWS.len() >= 40, "{} rows", ROWS.len());
    }
}
