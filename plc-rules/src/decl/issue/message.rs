//! The message of each [`Issue`]: the rule broken and the fix, in one wording per rule.

use super::Issue;
use super::kind::{Expected, IssueKind};
use super::wording::Wording;
use crate::address::Size;
use crate::capacity::{MAX_ARRAY_DIMS, MAX_ARRAY_ITEMS, MAX_STRING_CAPACITY};
use crate::decl::{MAX_UNIT_CHARS, UnitProblem};
use crate::{IecType, TypeFamily};
use std::format;
use std::string::{String, ToString};

impl<L> Issue<L> {
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
            IssueKind::AlarmEmptyText => "an alarm needs text: the message operators see \
                                          when it is raised (IEC 62682), such as \"Guard door \
                                          open\""
                .to_string(),
            IssueKind::AlarmSeverity { value } => format!(
                "severity {value} is out of range: an alarm's severity is 1..=1000 (OPC UA, IEC \
                 62541-9; 1 the least urgent, 500 when not given)"
            ),
            IssueKind::AlarmBadDelay { text, error } => {
                format!("{text:?} is not a delay: {error}")
            }
            IssueKind::AlarmNegativeDeadband { value } => format!(
                "deadband {value} is negative: a deadband is how far a value must come back past \
                 a limit before its level clears, 0 or more"
            ),
            IssueKind::AlarmOnType { ty, iec } => format!(
                "no alarm can be declared on {ty} ({iec}): an alarm watches a bool, or a number \
                 against limits (see the repository's docs/alarms.md)"
            ),
            IssueKind::AlarmLimitOnBool { key } => format!(
                "`{key}` is for alarms on numbers: a bool's alarm is active when it is true (or \
                 false, with `alarm_when = false`); remove `{key}`"
            ),
            IssueKind::AlarmWhenOnNumber { iec } => format!(
                "`alarm_when` is for alarms on bools: an alarm on a number ({iec}) is active \
                 beyond its limits; remove `alarm_when`"
            ),
            IssueKind::AlarmWithoutLimits { iec } => format!(
                "an alarm on a number ({iec}) needs limits: give `high`, `high_high`, `low` \
                 or `low_low`, the values that raise it"
            ),
            IssueKind::AlarmLimitOrder {
                key,
                value,
                below,
                below_value,
            } => format!(
                "`{key} = {value}` must be {} `{below} = {below_value}`: limits go low_low <= \
                 low < high <= high_high",
                if below.starts_with("low") && key.starts_with("high") {
                    "above"
                } else {
                    "at least"
                }
            ),
            IssueKind::AlarmSuppressUnknown {
                path,
                structure,
                why,
            } => {
                if let Some(why) = why {
                    format!(
                        "{} names no bool: {why}; `suppress_when` names a bool variable or an \
                         element of a bool array",
                        q(path)
                    )
                } else if *structure {
                    format!(
                        "{} names no member of this structure: inside a structure, \
                         `suppress_when` names a bool member of the same structure",
                        q(path)
                    )
                } else {
                    format!(
                        "{} names no variable: `suppress_when` names a bool variable (a path \
                         such as `stations[2].out_of_service` is checked when the program starts)",
                        q(path)
                    )
                }
            }
            IssueKind::AlarmSuppressNotBool {
                path,
                ty,
                past: Some(past),
            } => format!(
                "{} goes past {}, a {ty}, which has no members: `suppress_when` names a bool \
                 variable or an element of a bool array",
                q(path),
                q(past)
            ),
            IssueKind::AlarmSuppressNotBool {
                path,
                ty,
                past: None,
            } => format!(
                "{} is {ty}, not a bool: `suppress_when` names a bool that is true while the \
                 equipment is out of service",
                q(path)
            ),
            IssueKind::BadUnit { var, unit, problem } => match problem {
                UnitProblem::Empty => format!(
                    "the `unit` of {} is empty: give the engineering unit of its value, such as \
                     \"mm\" or \"kN\", or remove `unit`",
                    q(var)
                ),
                UnitProblem::TooLong { chars } => format!(
                    "the `unit` of {} has {chars} characters, more than {MAX_UNIT_CHARS}: give \
                     the unit's symbol, such as \"mm/s\", and say more in the description",
                    q(var)
                ),
                UnitProblem::Control => format!(
                    "the `unit` of {} ({unit:?}) holds a control character, such as a line break \
                     or a tab: a unit is one line of printable text, such as \"°C\"",
                    q(var)
                ),
            },
            IssueKind::UnitOnType { var, ty, iec } => format!(
                "`unit` cannot be declared on {} ({ty}, {iec}): {}; remove `unit` (an \
                 engineering unit is for integers, REAL and LREAL)",
                q(var),
                not_a_quantity(*iec, "unit")
            ),
            IssueKind::NegativeDeadband { var, value } => format!(
                "`deadband = {value}` on {} is {}: the reporting deadband is how far a number \
                 must move before a change is published (0: every change); give 0 or more, or \
                 remove it for the publisher's default",
                q(var),
                if *value < 0.0 {
                    "negative"
                } else {
                    "not a finite number"
                }
            ),
            IssueKind::DeadbandOnType { var, ty, iec } => format!(
                "`deadband` cannot be declared on {} ({ty}, {iec}): {}, and each of its changes \
                 is published; remove `deadband` (a reporting deadband is for integers, REAL and \
                 LREAL)",
                q(var),
                not_a_quantity(*iec, "deadband")
            ),
            IssueKind::SharedLink { link, first } => format!(
                "{link:?} is also linked by {}: fine for an input; two variables writing one \
                 output entry are refused when the bus starts",
                q(first)
            ),
        }
    }
}

/// Why a value of type `iec` takes no `key` (`unit` or `deadband`): it is not a quantity.
fn not_a_quantity(iec: IecType, key: &str) -> String {
    match iec.family() {
        TypeFamily::Bool => "a bool is true or false, not a quantity".to_string(),
        TypeFamily::String => "a STRING is text, not a quantity".to_string(),
        TypeFamily::BitString => format!(
            "{iec} is a bit string, a set of bits rather than a quantity (declared without \
             `iec_type`, the variable is an integer)"
        ),
        TypeFamily::Time if key == "unit" => {
            "a duration's unit is fixed: LTIME counts nanoseconds, shown as `ns`".to_string()
        }
        TypeFamily::Time => "a duration is not a quantity with a unit".to_string(),
        TypeFamily::SignedInt | TypeFamily::UnsignedInt | TypeFamily::Real => {
            format!("{iec} is a number")
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
