//! Every problem the checker finds, as a typed value, and its one wording. Each message states
//! the rule and the fix; `docs/rules.md` lists them with examples.

use crate::address::{AddressError, IecAddress, Size};
use crate::capacity::{MAX_ARRAY_DIMS, MAX_ARRAY_ITEMS, MAX_STRING_CAPACITY};
use crate::{Direction, IecType, LinkError, NameError, TimeError};
use std::format;
use std::string::{String, ToString};

/// How a front end writes names and other places in messages: the words are the checker's.
pub trait Wording<L> {
    /// A name as the user's format quotes it: `` `speed` `` in Rust, `"speed"` in JSON.
    fn name(&self, name: &str) -> String;
    /// Where another declaration is, to follow its name: `" (line 12)"`, or `""` where the
    /// format has nothing better than the name.
    fn place(&self, at: &L) -> String;
    /// How to allow a misaligned address, where the format can (after "move it").
    fn allow_unaligned(&self) -> &'static str {
        ""
    }
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
    /// A link shared by two variables (a warning).
    SharedLink {
        /// The link.
        link: String,
        /// The first variable with it.
        first: String,
    },
}

/// The name of every [`IssueKind`], as [`IssueKind::name`] gives it: the rules of
/// `docs/rules.md`, one each.
pub const KIND_NAMES: &[&str] = &[
    "BadName",
    "DuplicateName",
    "BadCapacity",
    "DimensionCount",
    "TooManyItems",
    "EmptyDimension",
    "IecTypeMismatch",
    "BadLink",
    "BadAddress",
    "AddressInMemoryArea",
    "AddressNotScalar",
    "AddressWidth",
    "Misaligned",
    "AddressOverlap",
    "UnknownDirection",
    "DirectionContradictsAddress",
    "DirectionContradictsSource",
    "IoInStructure",
    "DirectionInStructure",
    "SourceWithoutBit",
    "BitWithoutSource",
    "BadBit",
    "MappedNotBool",
    "SourceIsSelf",
    "SourceUnknown",
    "SourceNotInteger",
    "BitOutOfRange",
    "BitTaken",
    "InitialWrongKind",
    "InitialOutOfRange",
    "InitialBadTime",
    "InitialTooLong",
    "SharedLink",
];

impl IssueKind {
    /// The variant's name (`"BitOutOfRange"`), as `docs/rules.md` and tests name the rule.
    pub fn name(&self) -> &'static str {
        match self {
            IssueKind::BadName { .. } => "BadName",
            IssueKind::DuplicateName { .. } => "DuplicateName",
            IssueKind::BadCapacity { .. } => "BadCapacity",
            IssueKind::DimensionCount { .. } => "DimensionCount",
            IssueKind::TooManyItems { .. } => "TooManyItems",
            IssueKind::EmptyDimension => "EmptyDimension",
            IssueKind::IecTypeMismatch { .. } => "IecTypeMismatch",
            IssueKind::BadLink { .. } => "BadLink",
            IssueKind::BadAddress { .. } => "BadAddress",
            IssueKind::AddressInMemoryArea { .. } => "AddressInMemoryArea",
            IssueKind::AddressNotScalar { .. } => "AddressNotScalar",
            IssueKind::AddressWidth { .. } => "AddressWidth",
            IssueKind::Misaligned { .. } => "Misaligned",
            IssueKind::AddressOverlap { .. } => "AddressOverlap",
            IssueKind::UnknownDirection { .. } => "UnknownDirection",
            IssueKind::DirectionContradictsAddress { .. } => "DirectionContradictsAddress",
            IssueKind::DirectionContradictsSource { .. } => "DirectionContradictsSource",
            IssueKind::IoInStructure { .. } => "IoInStructure",
            IssueKind::DirectionInStructure { .. } => "DirectionInStructure",
            IssueKind::SourceWithoutBit => "SourceWithoutBit",
            IssueKind::BitWithoutSource => "BitWithoutSource",
            IssueKind::BadBit { .. } => "BadBit",
            IssueKind::MappedNotBool { .. } => "MappedNotBool",
            IssueKind::SourceIsSelf { .. } => "SourceIsSelf",
            IssueKind::SourceUnknown { .. } => "SourceUnknown",
            IssueKind::SourceNotInteger { .. } => "SourceNotInteger",
            IssueKind::BitOutOfRange { .. } => "BitOutOfRange",
            IssueKind::BitTaken { .. } => "BitTaken",
            IssueKind::InitialWrongKind { .. } => "InitialWrongKind",
            IssueKind::InitialOutOfRange { .. } => "InitialOutOfRange",
            IssueKind::InitialBadTime { .. } => "InitialBadTime",
            IssueKind::InitialTooLong { .. } => "InitialTooLong",
            IssueKind::SharedLink { .. } => "SharedLink",
        }
    }
}

/// One problem: its kind, where it is, and the other declaration it clashes with (if one).
#[derive(Clone, Debug, PartialEq)]
pub struct Issue<L> {
    /// What is wrong.
    pub kind: IssueKind,
    /// Where: the attribute or type to change.
    pub at: L,
    /// The earlier declaration it clashes with.
    pub related: Option<L>,
}

impl<L> Issue<L> {
    /// An issue at one place.
    pub fn new(kind: IssueKind, at: L) -> Issue<L> {
        Issue {
            kind,
            at,
            related: None,
        }
    }

    /// Whether it is a warning (the declaration is still valid) rather than an error.
    pub fn is_warning(&self) -> bool {
        matches!(self.kind, IssueKind::SharedLink { .. })
    }

    /// The message: the rule broken and what to do, in the front end's quoting.
    pub fn message(&self, w: &impl Wording<L>) -> String {
        let q = |n: &str| w.name(n);
        let place = self
            .related
            .as_ref()
            .map_or_else(String::new, |r| w.place(r));
        match &self.kind {
            IssueKind::BadName { name, error } => {
                format!("invalid variable name {}: {error}", q(name))
            }
            IssueKind::DuplicateName { name, first } => format!(
                "declared twice: {} is already used by {}{place}, and names are \
                 case-insensitive; rename one",
                q(name),
                q(first)
            ),
            IssueKind::BadCapacity { text } => {
                format!("{text} is not a capacity of 1..={MAX_STRING_CAPACITY} bytes")
            }
            IssueKind::DimensionCount { count } => {
                format!("{count} dimensions given: an array has 1 to {MAX_ARRAY_DIMS} dimensions")
            }
            IssueKind::TooManyItems { items } => format!(
                "an array holds at most {MAX_ARRAY_ITEMS} items in all dimensions, this one \
                 holds {}",
                items.map_or_else(|| "more than 2^64".to_string(), |n| n.to_string())
            ),
            IssueKind::EmptyDimension => {
                "an array needs at least one item in each dimension".to_string()
            }
            IssueKind::IecTypeMismatch {
                var,
                declared,
                ty,
                fits,
            } => format!(
                "`iec_type = \"{declared}\"` does not fit {} ({ty}): {declared} is stored as {}; \
                 use {fits}, or change the type to {}",
                q(var),
                declared.rust_name(),
                declared.rust_name()
            ),
            IssueKind::BadLink { link, error } => format!("invalid link {link:?}: {error}"),
            IssueKind::BadAddress { error } => format!("invalid address {error}"),
            IssueKind::AddressInMemoryArea { at } => format!(
                "{at:?} is in the M area: `at` locates I/O channels, so use %I (input) or %Q \
                 (output); internal variables need no address"
            ),
            IssueKind::AddressNotScalar { string } => format!(
                "{} cannot be located: `at` locates one I/O channel of a basic type (only \
                 internal variables have dimensions, and there are no string channels); remove \
                 `at`",
                if *string { "a STRING" } else { "an array" }
            ),
            IssueKind::AddressWidth {
                at,
                size,
                iec,
                suggestion,
            } => format!(
                "{at:?} is {} but a {iec} has {}: write \"{suggestion}\"",
                bits_text(size.bits()),
                if *iec == IecType::Bool { 1 } else { iec.bits() }
            ),
            IssueKind::Misaligned { at, size } => format!(
                "{at:?} is not aligned: a {} starts at a multiple of {} bytes; move it{}",
                size_name(*size),
                size.bytes(),
                w.allow_unaligned()
            ),
            IssueKind::AddressOverlap {
                at,
                other_at,
                other,
            } => format!(
                "{at} overlaps {other_at} of {}{place}: each channel has its own bits",
                q(other)
            ),
            IssueKind::UnknownDirection { text } => format!(
                "unknown direction {text:?}: use \"input\", \"output\", \"command\", \"status\" \
                 or \"internal\""
            ),
            IssueKind::DirectionContradictsAddress {
                given,
                at,
                var,
                implied,
            } => format!(
                "{:?} contradicts `at` {at:?}, which makes {} an {implied}: remove `direction` \
                 or change the address",
                given.name(),
                q(var)
            ),
            IssueKind::DirectionContradictsSource {
                given,
                source,
                source_direction,
            } => format!(
                "{:?} contradicts the source {}, which is {source_direction}: a bit-mapped bool \
                 takes its source's direction; remove `direction`",
                given.name(),
                q(source)
            ),
            IssueKind::IoInStructure { key } => format!(
                "`{key}` cannot be given inside a structure: physical I/O is declared at the top \
                 level, with a basic type; link a top-level variable and copy it into the member"
            ),
            IssueKind::DirectionInStructure { given } => format!(
                "`{given}` is no direction inside a structure: a member is an IN parameter \
                 (`direction = \"input\"`), an OUT parameter (`\"output\"`) or, without a \
                 direction, internal"
            ),
            IssueKind::SourceWithoutBit => "needs `bit`, the bit of the source word (0 = least \
                                            significant) that this bool maps to"
                .to_string(),
            IssueKind::BitWithoutSource => {
                "needs `source`, the integer variable that holds the bit".to_string()
            }
            IssueKind::BadBit { text } => {
                format!("{text} is not a bit number 0..=63 (0 = least significant)")
            }
            IssueKind::MappedNotBool {
                var,
                bit,
                source,
                ty,
            } => format!(
                "{} is mapped to bit {bit} of {}, so it must be bool, not {ty}",
                q(var),
                q(source)
            ),
            IssueKind::SourceIsSelf { var } => format!(
                "{} cannot be its own source: name the integer variable that holds the bit",
                q(var)
            ),
            IssueKind::SourceUnknown { source, hint } => format!(
                "{} names no variable{}: name the integer variable that holds the bit",
                q(source),
                hint.as_ref()
                    .map_or_else(String::new, |h| format!(" (did you mean {}?)", q(h)))
            ),
            IssueKind::SourceNotInteger { source, ty } => format!(
                "the source {} is {ty}, but a source must be an integer: u8, u16, u32, u64, i8, \
                 i16, i32 or i64",
                q(source)
            ),
            IssueKind::BitOutOfRange {
                bit,
                source,
                ty,
                width,
            } => format!(
                "{bit} is out of range for source {} ({ty} has bits 0..={})",
                q(source),
                width.saturating_sub(1)
            ),
            IssueKind::BitTaken { bit, source, first } => format!(
                "bit {bit} of {} is already mapped to {}{place}: two bools cannot share a bit",
                q(source),
                q(first)
            ),
            IssueKind::InitialWrongKind {
                text,
                iec,
                expected,
            } => match expected {
                Expected::Bool => {
                    format!("{text} is not a {iec} value: `initial` must be `true` or `false`")
                }
                Expected::WholeNumber => {
                    format!("{text} is not a {iec} value: `initial` must be a whole number")
                }
                Expected::NotReal => format!(
                    "{text} is not a whole number, which a {iec} needs (real to integer is \
                     never implicit)"
                ),
                Expected::Number => {
                    format!("{text} is not a {iec} value: `initial` must be a number")
                }
                Expected::Text => format!(
                    "{text} is not a {iec} value: `initial` must be text in double quotes, such \
                     as \"TEST-001\""
                ),
                Expected::Duration => format!(
                    "{text} is not a {iec} value: `initial` must be a duration literal in double \
                     quotes, such as \"T#5s\" or \"T#1m30s\""
                ),
            },
            IssueKind::InitialBadTime { text, error } => {
                format!("{text} is not a duration literal: {error}")
            }
            IssueKind::InitialOutOfRange {
                text,
                iec,
                ty,
                range,
            } => format!("{text} is out of range for {iec} ({ty} holds {range})"),
            IssueKind::InitialTooLong { len, capacity } => format!(
                "{len} bytes do not fit max_length {capacity} (a FixedString<{capacity}>): \
                 shorten the text or raise the capacity"
            ),
            IssueKind::SharedLink { link, first } => format!(
                "{link:?} is also linked by {}: fine for an input; two variables writing one \
                 output entry are refused when the bus starts",
                q(first)
            ),
        }
    }
}

fn bits_text(bits: u32) -> String {
    if bits == 1 {
        "1 bit".to_string()
    } else {
        format!("{bits} bits")
    }
}

fn size_name(s: Size) -> &'static str {
    match s {
        Size::Bit => "bit",
        Size::Byte => "byte",
        Size::Word => "word",
        Size::DoubleWord => "double word",
        Size::LongWord => "long word",
    }
}
