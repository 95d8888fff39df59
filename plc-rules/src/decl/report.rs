//! How a variable is reported to the tools that publish it: `unit`, the engineering unit its
//! value is in (a Sparkplug B metric's `engUnit`), and `deadband`, how far a number must move
//! before a change is published (Sparkplug B's data by exception). Both are for numbers only:
//! integers, REAL and LREAL. A bool, a STRING and a bit string (BYTE..LWORD, IEC 61131-3's
//! sets of bits) are no quantity, and a duration's unit is fixed (LTIME counts nanoseconds).
//!
//! The reporting deadband is not the deadband of a limit alarm (`alarm(deadband = ...)`, in
//! `alarm`): that one says how far a value must come back past a limit before its level
//! clears.

use super::issue::{Issue, IssueKind};
use super::{Decl, DeclType, Var};
use crate::{IecType, TypeFamily};
use std::string::ToString;
use std::vec::Vec;

/// The most characters a `unit` may have: a unit's symbol (`"mm/s"`, `"kN·m"`, `"°C"`), not a
/// description.
pub const MAX_UNIT_CHARS: usize = 32;

/// Why a `unit` is not one.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UnitProblem {
    /// Empty, or only spaces.
    Empty,
    /// More than [`MAX_UNIT_CHARS`] characters.
    TooLong {
        /// Characters given.
        chars: usize,
    },
    /// A control character (a line break, a tab): a unit is one line of printable text.
    Control,
}

/// What is wrong with `unit` as text, if anything.
fn unit_problem(unit: &str) -> Option<UnitProblem> {
    let chars = unit.chars().count();
    if unit.trim().is_empty() {
        Some(UnitProblem::Empty)
    } else if unit.chars().any(char::is_control) {
        Some(UnitProblem::Control)
    } else if chars > MAX_UNIT_CHARS {
        Some(UnitProblem::TooLong { chars })
    } else {
        None
    }
}

/// The IEC type a variable's value has, where the declaration shows it: its `iec_type`, else
/// its type's. `None` for a type only the compiler knows (the derive asserts those).
fn value_type<L>(v: &Var<L>) -> Option<IecType> {
    match (&v.iec_type, &v.ty.value) {
        (Some(t), _) => Some(t.value),
        (None, DeclType::Known(k)) => Some(k.iec),
        (None, DeclType::Unknown) => None,
    }
}

/// Whether values of `iec` are numbers a unit and a deadband make sense for.
fn is_number(iec: IecType) -> bool {
    matches!(
        iec.family(),
        TypeFamily::SignedInt | TypeFamily::UnsignedInt | TypeFamily::Real
    )
}

/// Applies the rules of `unit` and `deadband` to every variable of `decl` that declares one.
pub(super) fn reporting<L: Clone>(decl: &Decl<L>, issues: &mut Vec<Issue<L>>) {
    for v in &decl.vars {
        let not_a_number = value_type(v).filter(|&iec| !is_number(iec));
        let ty = || match &v.ty.value {
            DeclType::Known(k) => k.element_name(),
            DeclType::Unknown => v.iec_type.as_ref().map_or_else(
                || "its type".to_string(),
                |t| t.value.rust_name().to_string(),
            ),
        };
        if let Some(u) = &v.unit {
            let var = v.field.clone();
            if let Some(iec) = not_a_number {
                let kind = IssueKind::UnitOnType { var, ty: ty(), iec };
                issues.push(Issue::new(kind, u.at.clone()));
            } else if let Some(problem) = unit_problem(&u.value) {
                let unit = u.value.clone();
                let kind = IssueKind::BadUnit { var, unit, problem };
                issues.push(Issue::new(kind, u.at.clone()));
            }
        }
        if let Some(d) = &v.deadband {
            let var = v.field.clone();
            if let Some(iec) = not_a_number {
                let kind = IssueKind::DeadbandOnType { var, ty: ty(), iec };
                issues.push(Issue::new(kind, d.at.clone()));
            } else if !(d.value >= 0.0 && d.value.is_finite()) {
                let kind = IssueKind::NegativeDeadband {
                    var,
                    value: d.value,
                };
                issues.push(Issue::new(kind, d.at.clone()));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::{Decl, KnownType, Located, Var, check};
    use super::{MAX_UNIT_CHARS, UnitProblem, unit_problem};
    use crate::IecType;
    use std::string::String;
    use std::vec::Vec;

    fn var(iec: IecType, unit: Option<&str>, deadband: Option<f64>) -> Var<&'static str> {
        let mut v = Var::new(
            Located::new("x".into(), "x"),
            "x",
            Located::new(KnownType::scalar(iec).into(), "x.type"),
        );
        v.unit = unit.map(|u| Located::new(String::from(u), "x.unit"));
        v.deadband = deadband.map(|d| Located::new(d, "x.deadband"));
        v
    }

    fn kinds(v: Var<&'static str>) -> Vec<&'static str> {
        let decl = Decl {
            vars: std::vec![v],
            unaligned: false,
            structure: false,
        };
        check(&decl).issues.iter().map(|i| i.kind.name()).collect()
    }

    #[test]
    fn a_unit_is_one_short_line_of_printable_text() {
        assert_eq!(unit_problem("mm"), None);
        assert_eq!(unit_problem("°C"), None);
        assert_eq!(unit_problem(&"µ".repeat(MAX_UNIT_CHARS)), None);
        assert_eq!(unit_problem(""), Some(UnitProblem::Empty));
        assert_eq!(unit_problem("  "), Some(UnitProblem::Empty));
        assert_eq!(unit_problem("m\nm"), Some(UnitProblem::Control));
        assert_eq!(
            unit_problem(&"m".repeat(MAX_UNIT_CHARS + 1)),
            Some(UnitProblem::TooLong {
                chars: MAX_UNIT_CHARS + 1
            })
        );
    }

    #[test]
    fn units_and_deadbands_go_on_integers_and_reals_only() {
        for iec in [IecType::Sint, IecType::Udint, IecType::Real, IecType::Lreal] {
            assert!(kinds(var(iec, Some("mm"), Some(0.5))).is_empty(), "{iec}");
        }
        for iec in [IecType::Bool, IecType::String, IecType::Ltime] {
            assert_eq!(
                kinds(var(iec, Some("mm"), Some(0.5))),
                ["UnitOnType", "DeadbandOnType"],
                "{iec}"
            );
        }
        // A u16 declared as a WORD is a bit string.
        let mut word = var(IecType::Uint, Some("mm"), None);
        word.iec_type = Some(Located::new(IecType::Word, "x.iec_type"));
        assert_eq!(kinds(word), ["UnitOnType"]);
    }

    #[test]
    fn a_deadband_is_zero_or_more_and_a_key_on_the_wrong_type_is_one_mistake() {
        assert!(kinds(var(IecType::Real, None, Some(0.0))).is_empty());
        assert_eq!(
            kinds(var(IecType::Real, None, Some(-0.5))),
            ["NegativeDeadband"]
        );
        assert_eq!(
            kinds(var(IecType::Real, None, Some(f64::NAN))),
            ["NegativeDeadband"]
        );
        // On a bool the one mistake told is the key itself (remove it), not also its value.
        assert_eq!(
            kinds(var(IecType::Bool, Some(""), Some(-1.0))),
            ["UnitOnType", "DeadbandOnType"]
        );
    }
}
