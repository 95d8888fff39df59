//! The rules of a variable's `initial` value and its `iec_type`: the value must be of the
//! variable's kind and within its type's range (IEC 61131-3's literals and implicit widening),
//! and a declared bit-string type must have the storage of the field's type.

use super::issue::{Expected, Issue, IssueKind};
use super::{Decl, DeclType, InitialValue, KnownType};
use crate::{IecType, Time, TimeError, TypeFamily};
use std::format;
use std::string::{String, ToString};
use std::vec::Vec;

pub(super) fn initial_and_iec_type<L: Clone>(decl: &Decl<L>, issues: &mut Vec<Issue<L>>) {
    for v in &decl.vars {
        let DeclType::Known(k) = &v.ty.value else {
            continue;
        };
        if let Some(t) = &v.iec_type
            && !t.value.same_storage(k.iec)
        {
            let fits: Vec<&str> = IecType::ALL
                .iter()
                .filter(|x| x.same_storage(k.iec))
                .map(|x| x.name())
                .collect();
            issues.push(Issue::new(
                IssueKind::IecTypeMismatch {
                    var: v.field.clone(),
                    declared: t.value,
                    ty: k.element_name(),
                    fits: fits.join(" or "),
                },
                t.at.clone(),
            ));
        }
        if let Some(init) = &v.initial {
            let iec = v.iec_type.as_ref().map_or(k.iec, |t| t.value);
            if let Some(kind) = initial_misfit(&init.value.value, &init.value.text, k, iec) {
                issues.push(Issue::new(kind, init.at.clone()));
            }
        }
    }
}

/// Why an initial value does not fit a variable of type `k` (declared as `iec`), if it does
/// not. A bare integer is fine for REAL and LREAL (IEC 61131-3: integer to real widening); an
/// LTIME takes a duration literal as text (`"T#5s"`), never a bare number, whose unit would
/// be a guess.
pub fn initial_misfit(
    value: &InitialValue,
    text: &str,
    k: &KnownType,
    iec: IecType,
) -> Option<IssueKind> {
    let wrong = |expected| {
        Some(IssueKind::InitialWrongKind {
            text: text.to_string(),
            iec,
            expected,
        })
    };
    let out_of_range = |range: String| {
        Some(IssueKind::InitialOutOfRange {
            text: text.to_string(),
            iec,
            ty: k.element_name(),
            range,
        })
    };
    let int_range = || {
        let (lo, hi) = k.iec.int_range().unwrap_or((0, 0));
        format!("{lo}..={hi}")
    };
    let family = k.iec.family();
    match value {
        InitialValue::Bool(_) if family == TypeFamily::Bool => None,
        _ if family == TypeFamily::Bool => wrong(Expected::Bool),
        InitialValue::Int(n) if k.iec.is_integer() => {
            let (lo, hi) = k.iec.int_range().unwrap_or((0, 0));
            if (lo..=hi).contains(n) {
                None
            } else {
                out_of_range(int_range())
            }
        }
        InitialValue::BigInt(_) if k.iec.is_integer() => out_of_range(int_range()),
        InitialValue::Int(_) if family == TypeFamily::Real => None,
        InitialValue::Float(v) | InitialValue::BigInt(v) if family == TypeFamily::Real => {
            if k.iec == IecType::Real && v.abs() > f32::MAX as f64 {
                out_of_range(format!("up to {:e} either side of 0", f32::MAX))
            } else {
                None
            }
        }
        InitialValue::Text(s) if family == TypeFamily::String => {
            let capacity = k.capacity.unwrap_or(u64::MAX);
            (s.len() as u64 > capacity).then_some(IssueKind::InitialTooLong {
                len: s.len(),
                capacity,
            })
        }
        _ if family == TypeFamily::String => wrong(Expected::Text),
        InitialValue::Text(s) if family == TypeFamily::Time => match Time::parse(s) {
            Ok(_) => None,
            Err(TimeError::Overflow) => out_of_range(format!("{}..={}", Time::MIN, Time::MAX)),
            Err(error) => Some(IssueKind::InitialBadTime {
                text: text.to_string(),
                error,
            }),
        },
        _ if family == TypeFamily::Time => wrong(Expected::Duration),
        InitialValue::Float(_) if k.iec.is_integer() => wrong(Expected::NotReal),
        _ if k.iec.is_integer() => wrong(Expected::WholeNumber),
        _ => wrong(Expected::Number),
    }
}
