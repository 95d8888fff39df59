//! The declaration rules as [`IssueKind`], each with what its message needs, and the rule
//! names ([`IssueKind::name`], [`KIND_NAMES`]) taken from the one list of its variants.

use crate::address::{AddressError, IecAddress, Size};
use crate::decl::{DelayError, UnitProblem};
use crate::path::PathError;
use crate::{Direction, IecType, LinkError, NameError, TimeError};
use std::string::String;

/// Declares [`IssueKind`] from the one list of its variants below, and from that same list
/// [`KIND_NAMES`] and [`IssueKind::name`]: a rule's name is written once, as its variant.
macro_rules! issue_kinds {
    (
        $(#[$attr:meta])*
        pub enum IssueKind {
            $(
                $(#[$doc:meta])*
                $kind:ident $({ $($fields:tt)* })?,
            )*
        }
    ) => {
        $(#[$attr])*
        pub enum IssueKind {
            $(
                $(#[$doc])*
                $kind $({ $($fields)* })?,
            )*
        }

        /// The name of every [`IssueKind`], as [`IssueKind::name`] gives it: the rules of
        /// the repository's `docs/rules.md`, one each.
        pub const KIND_NAMES: &[&str] = &[$(stringify!($kind)),*];

        impl IssueKind {
            /// The variant's name (`"BitOutOfRange"`), as the repository's `docs/rules.md` and
            /// tests name it.
            pub fn name(&self) -> &'static str {
                match self {
                    $(IssueKind::$kind { .. } => stringify!($kind),)*
                }
            }
        }
    };
}

/// What an `initial` value should have been.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Expected {
    /// `true` or `false`.
    Bool,
    /// A whole number (for an integer or bit-string type).
    WholeNumber,
    /// A whole number where a real number was given.
    NotReal,
    /// A number (for REAL and LREAL).
    Number,
    /// Text (for STRING).
    Text,
    /// A duration literal in double quotes (for LTIME).
    Duration,
}

issue_kinds! {
    /// One kind of problem, with what its message needs. The variants are the declaration rules.
    #[derive(Clone, Debug, PartialEq)]
    #[non_exhaustive]
    pub enum IssueKind {
        /// A name breaks the naming rules.
        BadName {
            /// The name.
            name: String,
            /// Which rule.
            error: NameError,
        },
        /// A second variable of the same name, compared case-insensitively.
        DuplicateName {
            /// The second name.
            name: String,
            /// The first one's name.
            first: String,
        },
        /// A string capacity outside 1..=255.
        BadCapacity {
            /// The capacity as written.
            text: String,
        },
        /// An array of no or more than three dimensions.
        DimensionCount {
            /// Dimensions given.
            count: usize,
        },
        /// An array of more than 65,535 items (`None`: more than 2^64).
        TooManyItems {
            /// Items in all dimensions.
            items: Option<u64>,
        },
        /// An array dimension of 0 items.
        EmptyDimension,
        /// `iec_type` of another width or family than the field's type.
        IecTypeMismatch {
            /// The variable.
            var: String,
            /// The declared IEC type.
            declared: IecType,
            /// The field's Rust type.
            ty: String,
            /// The IEC types that would fit, joined by " or ".
            fits: String,
        },
        /// A link that is not `ethercat.<device>.<entry>`.
        BadLink {
            /// The link.
            link: String,
            /// What is wrong.
            error: LinkError,
        },
        /// An address that does not parse.
        BadAddress {
            /// What is wrong.
            error: AddressError,
        },
        /// `at` in the M area.
        AddressInMemoryArea {
            /// The address as written.
            at: String,
        },
        /// `at` on an array or a string.
        AddressNotScalar {
            /// Whether it is a string (else an array).
            string: bool,
        },
        /// An address whose size does not match the type.
        AddressWidth {
            /// The address as written.
            at: String,
            /// The address's size.
            size: Size,
            /// The variable's IEC type.
            iec: IecType,
            /// The address of the right size at the same byte.
            suggestion: IecAddress,
        },
        /// A W/D/L address not at a multiple of its size.
        Misaligned {
            /// The address as written.
            at: String,
            /// Its size.
            size: Size,
        },
        /// Two addresses that share bits.
        AddressOverlap {
            /// This address.
            at: IecAddress,
            /// The other address.
            other_at: IecAddress,
            /// The other variable.
            other: String,
        },
        /// A direction that is none of the five.
        UnknownDirection {
            /// The text given.
            text: String,
        },
        /// A direction other than the one `at` implies.
        DirectionContradictsAddress {
            /// The direction given.
            given: Direction,
            /// The address as written.
            at: String,
            /// The variable.
            var: String,
            /// The direction the address implies.
            implied: Direction,
        },
        /// A bit-mapped bool's direction other than its source's.
        DirectionContradictsSource {
            /// The direction given.
            given: Direction,
            /// The source.
            source: String,
            /// The source's direction.
            source_direction: Direction,
        },
        /// `link` or `at` on a member of a structure.
        IoInStructure {
            /// `link` or `at`.
            key: &'static str,
        },
        /// A direction other than input (IN) or output (OUT) on a member of a structure.
        DirectionInStructure {
            /// The direction given.
            given: Direction,
        },
        /// `source` without `bit`.
        SourceWithoutBit,
        /// `bit` without `source`.
        BitWithoutSource,
        /// A bit number outside 0..=63 (or not a number).
        BadBit {
            /// The bit as written.
            text: String,
        },
        /// A bit-mapped variable that is not a bool.
        MappedNotBool {
            /// The variable.
            var: String,
            /// Its bit.
            bit: i64,
            /// Its source.
            source: String,
            /// Its type.
            ty: String,
        },
        /// `source` naming the variable itself.
        SourceIsSelf {
            /// The variable.
            var: String,
        },
        /// `source` naming no variable (`hint`: one that differs only in case).
        SourceUnknown {
            /// The name given.
            source: String,
            /// A variable of that name in another case.
            hint: Option<String>,
        },
        /// A source that is not a scalar integer.
        SourceNotInteger {
            /// The source.
            source: String,
            /// Its type.
            ty: String,
        },
        /// A bit beyond the source's width.
        BitOutOfRange {
            /// The bit.
            bit: i64,
            /// The source.
            source: String,
            /// The source's type.
            ty: String,
            /// The source's width in bits.
            width: u32,
        },
        /// Two bools on one bit of one source.
        BitTaken {
            /// The bit.
            bit: i64,
            /// The source.
            source: String,
            /// The bool that has it.
            first: String,
        },
        /// An initial value of the wrong kind.
        InitialWrongKind {
            /// The value as written.
            text: String,
            /// The variable's IEC type.
            iec: IecType,
            /// What it should have been.
            expected: Expected,
        },
        /// An initial number beyond the type's range.
        InitialOutOfRange {
            /// The value as written.
            text: String,
            /// The variable's IEC type.
            iec: IecType,
            /// Its Rust type.
            ty: String,
            /// What the type holds, as text (`0..=255`).
            range: String,
        },
        /// An initial duration that is not a valid IEC duration literal (one beyond `LTIME`'s
        /// range is [`InitialOutOfRange`](Self::InitialOutOfRange)).
        InitialBadTime {
            /// The value as written.
            text: String,
            /// What is wrong with it.
            error: TimeError,
        },
        /// Initial text longer than the string's capacity.
        InitialTooLong {
            /// Bytes of the text.
            len: usize,
            /// The capacity.
            capacity: u64,
        },
        /// An alarm with empty text: operators would see an alarm without a message.
        AlarmEmptyText,
        /// A severity outside OPC UA's 1..=1000.
        AlarmSeverity {
            /// The severity given.
            value: i64,
        },
        /// A `delay` that is not a duration of 0 or more.
        AlarmBadDelay {
            /// The delay as written.
            text: String,
            /// What is wrong.
            error: DelayError,
        },
        /// A negative `deadband`.
        AlarmNegativeDeadband {
            /// The deadband given.
            value: f64,
        },
        /// An alarm on a STRING or a duration, which has no active state or limits.
        AlarmOnType {
            /// The element's Rust type.
            ty: String,
            /// Its IEC type.
            iec: IecType,
        },
        /// A limit or a deadband on a bool, whose alarm is its value.
        AlarmLimitOnBool {
            /// The key given (`high`, `deadband`).
            key: &'static str,
        },
        /// `alarm_when` on a number, whose alarm is its limits.
        AlarmWhenOnNumber {
            /// The variable's IEC type.
            iec: IecType,
        },
        /// An alarm on a number without limits.
        AlarmWithoutLimits {
            /// The variable's IEC type.
            iec: IecType,
        },
        /// A limit not above the one below it (low_low <= low < high <= high_high).
        AlarmLimitOrder {
            /// The limit's key.
            key: &'static str,
            /// Its value.
            value: f64,
            /// The key of the nearest limit below it.
            below: &'static str,
            /// That limit's value.
            below_value: f64,
        },
        /// `suppress_when` naming no variable (in a structure: no member of it), or an element
        /// of a bool array that is not there.
        AlarmSuppressUnknown {
            /// The path given.
            path: String,
            /// Whether the alarm is on a structure's member.
            structure: bool,
            /// What is wrong with the path, where it is more than an unknown name.
            why: Option<PathError>,
        },
        /// `suppress_when` naming a variable that is not a bool.
        AlarmSuppressNotBool {
            /// The path given.
            path: String,
            /// The variable's Rust type.
            ty: String,
            /// The basic variable the path goes past (`mode` of `mode.x`), if it does.
            past: Option<String>,
        },
        /// A `unit` that is empty, longer than 32 characters or not printable.
        BadUnit {
            /// The variable.
            var: String,
            /// The unit as written.
            unit: String,
            /// What is wrong with it.
            problem: UnitProblem,
        },
        /// A `unit` on a variable that is not a number (a bool, a STRING, a bit string, a
        /// duration).
        UnitOnType {
            /// The variable.
            var: String,
            /// The element's Rust type.
            ty: String,
            /// Its IEC type (the declared `iec_type`, if one).
            iec: IecType,
        },
        /// A reporting `deadband` below 0 (or not a finite number).
        NegativeDeadband {
            /// The variable.
            var: String,
            /// The deadband given.
            value: f64,
        },
        /// A reporting `deadband` on a variable that is not a number.
        DeadbandOnType {
            /// The variable.
            var: String,
            /// The element's Rust type.
            ty: String,
            /// Its IEC type (the declared `iec_type`, if one).
            iec: IecType,
        },
        /// A link shared by two variables (a warning).
        SharedLink {
            /// The link.
            link: String,
            /// The first variable with it.
            first: String,
        },
    }
}
