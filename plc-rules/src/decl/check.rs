//! The checker: every declaration rule applied to a [`Decl`], each problem an [`Issue`] at the
//! attribute or type to change. Lookups go through maps, so a 10,000-variable list is checked
//! in linear time.

use super::issue::{Issue, IssueKind};
use super::keys::{FnvMap, NoCase};
use super::{Decl, DeclType, Direction, KnownType, Var};
use crate::address::{Area, IecAddress, Size};
use crate::capacity::{MAX_ARRAY_DIMS, MAX_ARRAY_ITEMS};
use crate::link::Link;
use crate::{IecType, names};
use std::string::{String, ToString};
use std::vec::Vec;

/// What the checker works out for each variable, for the front ends to generate from.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Resolved {
    /// The source variable (index into the declaration) and bit of a bit-mapped bool.
    pub mapped: Option<(usize, u8)>,
    /// The effective direction: as given, else implied by `at`, else the source's for a
    /// bit-mapped bool, else internal.
    pub direction: Direction,
    /// The parsed `at`, where it is a valid I/O address.
    pub address: Option<IecAddress>,
}

/// The outcome of [`check`]: every issue, errors and warnings in declaration order of the
/// rules, and one [`Resolved`] per variable.
#[derive(Clone, Debug)]
pub struct Checked<L> {
    /// Errors and warnings ([`Issue::is_warning`]).
    pub issues: Vec<Issue<L>>,
    /// One per variable, in order.
    pub vars: Vec<Resolved>,
}

impl<L> Checked<L> {
    /// Whether any issue is an error.
    pub fn has_errors(&self) -> bool {
        self.issues.iter().any(|i| !i.is_warning())
    }
}

/// Applies every declaration rule to `decl`.
pub fn check<L: Clone>(decl: &Decl<L>) -> Checked<L> {
    let mut issues = Vec::new();
    let mut vars: Vec<Resolved> = decl
        .vars
        .iter()
        .map(|v| Resolved {
            mapped: None,
            direction: Direction::Internal,
            address: if decl.structure {
                structure_rules(v, &mut issues);
                None
            } else {
                own_rules(v, &mut issues)
            },
        })
        .collect();
    duplicate_names(decl, &mut issues);
    bit_mappings(decl, &mut vars, &mut issues);
    addresses(decl, &vars, &mut issues);
    directions(decl, &mut vars, &mut issues);
    super::initial::initial_and_iec_type(decl, &mut issues);
    shared_links(decl, &mut issues);
    super::report::reporting(decl, &mut issues);
    super::alarm::alarms(decl, &mut issues);
    Checked { issues, vars }
}

/// The rules of one member of a structure: those of a variable, but physical I/O is declared
/// at the top level (a structure's members have no place on a bus or in the I/O areas), and
/// only IN and OUT parameters have a direction.
fn structure_rules<L: Clone>(v: &Var<L>, issues: &mut Vec<Issue<L>>) {
    let mut plain = v.clone();
    for (key, at) in [("link", plain.link.take()), ("at", plain.at.take())] {
        if let Some(at) = at {
            issues.push(Issue::new(IssueKind::IoInStructure { key }, at.at));
        }
    }
    if let Some(d) = &v.direction
        && matches!(d.value, Direction::Command | Direction::Status)
    {
        issues.push(Issue::new(
            IssueKind::DirectionInStructure { given: d.value },
            d.at.clone(),
        ));
    }
    own_rules(&plain, issues);
}

/// The rules of one variable on its own; returns its address if valid.
fn own_rules<L: Clone>(v: &Var<L>, issues: &mut Vec<Issue<L>>) -> Option<IecAddress> {
    if v.name_known
        && let Err(error) = names::check_name(&v.name.value)
    {
        issues.push(Issue::new(
            IssueKind::BadName {
                name: v.name.value.clone(),
                error,
            },
            v.name.at.clone(),
        ));
    }
    if let DeclType::Known(k) = &v.ty.value {
        for kind in type_rules(k) {
            let at = match kind {
                IssueKind::BadCapacity { .. } => v.capacity_at.as_ref(),
                _ => v.dims_at.as_ref(),
            };
            issues.push(Issue::new(kind, at.unwrap_or(&v.ty.at).clone()));
        }
    }
    if let Some(link) = &v.link
        && let Err(error) = Link::parse(&link.value)
    {
        issues.push(Issue::new(
            IssueKind::BadLink {
                link: link.value.clone(),
                error,
            },
            link.at.clone(),
        ));
    }
    match (&v.source, &v.bit) {
        (Some(s), None) => issues.push(Issue::new(IssueKind::SourceWithoutBit, s.at.clone())),
        (None, Some(b)) => issues.push(Issue::new(IssueKind::BitWithoutSource, b.at.clone())),
        _ => {}
    }
    if let Some(b) = &v.bit
        && !(0..=63).contains(&b.value)
    {
        issues.push(Issue::new(
            IssueKind::BadBit {
                text: b.value.to_string(),
            },
            b.at.clone(),
        ));
    }
    let at = v.at.as_ref()?;
    match at.value.parse::<IecAddress>() {
        Err(error) => {
            issues.push(Issue::new(IssueKind::BadAddress { error }, at.at.clone()));
            None
        }
        Ok(a) if a.area == Area::Memory => {
            issues.push(Issue::new(
                IssueKind::AddressInMemoryArea {
                    at: at.value.clone(),
                },
                at.at.clone(),
            ));
            None
        }
        Ok(a) => Some(a),
    }
}

/// The limits on a type: string capacity, dimensions, items.
pub fn type_rules(k: &KnownType) -> Vec<IssueKind> {
    let mut kinds = Vec::new();
    if let Some(n) = k.capacity
        && !usize::try_from(n).is_ok_and(crate::capacity::is_valid_string_capacity)
    {
        kinds.push(IssueKind::BadCapacity {
            text: n.to_string(),
        });
    }
    if k.dims.len() > MAX_ARRAY_DIMS {
        kinds.push(IssueKind::DimensionCount {
            count: k.dims.len(),
        });
    }
    let items = k.dims.iter().try_fold(1u64, |a, &d| a.checked_mul(d));
    if items.is_none_or(|n| n > MAX_ARRAY_ITEMS as u64) {
        kinds.push(IssueKind::TooManyItems { items });
    }
    if k.dims.contains(&0) {
        kinds.push(IssueKind::EmptyDimension);
    }
    kinds
}

fn duplicate_names<L: Clone>(decl: &Decl<L>, issues: &mut Vec<Issue<L>>) {
    let mut first: FnvMap<NoCase, usize> = FnvMap::default();
    first.reserve(decl.vars.len());
    for (i, v) in decl.vars.iter().enumerate().filter(|(_, v)| v.name_known) {
        match first.get(&NoCase(&v.name.value)) {
            Some(&f) => {
                let f = &decl.vars[f];
                issues.push(Issue {
                    kind: IssueKind::DuplicateName {
                        name: v.name.value.clone(),
                        first: f.name.value.clone(),
                    },
                    at: v.name.at.clone(),
                    related: Some(f.name.at.clone()),
                });
            }
            None => {
                first.insert(NoCase(&v.name.value), i);
            }
        }
    }
}

fn bit_mappings<L: Clone>(decl: &Decl<L>, vars: &mut [Resolved], issues: &mut Vec<Issue<L>>) {
    if decl
        .vars
        .iter()
        .all(|v| v.source.is_none() || v.bit.is_none())
    {
        return;
    }
    let by_field: FnvMap<&str, usize> = decl
        .vars
        .iter()
        .enumerate()
        .map(|(i, v)| (v.field.as_str(), i))
        .collect();
    let mut taken: FnvMap<(usize, i64), usize> = FnvMap::default();
    for (i, v) in decl.vars.iter().enumerate() {
        let (Some(source), Some(bit)) = (&v.source, &v.bit) else {
            continue;
        };
        if let DeclType::Known(k) = &v.ty.value
            && !(k.is_scalar() && k.iec == IecType::Bool)
        {
            issues.push(Issue::new(
                IssueKind::MappedNotBool {
                    var: v.field.clone(),
                    bit: bit.value,
                    source: source.value.clone(),
                    ty: k.rust_type(),
                },
                v.ty.at.clone(),
            ));
        }
        let Some(&s) = by_field.get(source.value.as_str()) else {
            let hint = decl
                .vars
                .iter()
                .find(|w| w.field.eq_ignore_ascii_case(&source.value))
                .map(|w| w.field.clone());
            issues.push(Issue::new(
                IssueKind::SourceUnknown {
                    source: source.value.clone(),
                    hint,
                },
                source.at.clone(),
            ));
            continue;
        };
        if s == i {
            issues.push(Issue::new(
                IssueKind::SourceIsSelf {
                    var: v.field.clone(),
                },
                source.at.clone(),
            ));
            continue;
        }
        if let DeclType::Known(k) = &decl.vars[s].ty.value {
            if !(k.is_scalar() && k.iec.is_integer()) {
                issues.push(Issue::new(
                    IssueKind::SourceNotInteger {
                        source: source.value.clone(),
                        ty: k.rust_type(),
                    },
                    source.at.clone(),
                ));
                continue;
            }
            // A bit outside 0..=63 is reported as such, not also as beyond the width.
            if (0..=63).contains(&bit.value) && bit.value >= i64::from(k.iec.bits()) {
                issues.push(Issue::new(
                    IssueKind::BitOutOfRange {
                        bit: bit.value,
                        source: source.value.clone(),
                        ty: k.rust_type(),
                        width: k.iec.bits(),
                    },
                    bit.at.clone(),
                ));
                continue;
            }
        }
        if !(0..=63).contains(&bit.value) {
            continue;
        }
        if let Some(&first) = taken.get(&(s, bit.value)) {
            issues.push(Issue {
                kind: IssueKind::BitTaken {
                    bit: bit.value,
                    source: source.value.clone(),
                    first: decl.vars[first].field.clone(),
                },
                at: bit.at.clone(),
                related: decl.vars[first].bit.as_ref().map(|b| b.at.clone()),
            });
            continue;
        }
        taken.insert((s, bit.value), i);
        vars[i].mapped = Some((s, bit.value as u8));
    }
}

fn addresses<L: Clone>(decl: &Decl<L>, vars: &[Resolved], issues: &mut Vec<Issue<L>>) {
    // The earlier addresses on each byte: an address covers at most 8 bytes, so finding what
    // it overlaps is a few lookups, not a pass over every located variable.
    let mut on_byte: FnvMap<(Area, usize), Vec<usize>> = FnvMap::default();
    for (i, (v, r)) in decl.vars.iter().zip(vars).enumerate() {
        let (Some(a), Some(at)) = (r.address, &v.at) else {
            continue;
        };
        if let DeclType::Known(k) = &v.ty.value {
            if !k.is_scalar() || k.iec == IecType::String {
                issues.push(Issue::new(
                    IssueKind::AddressNotScalar {
                        string: k.is_scalar(),
                    },
                    at.at.clone(),
                ));
                continue;
            }
            let needed = Size::from_bits(k.iec.bits());
            if let Some(needed) = needed
                && needed != a.size
            {
                let bit = (needed == Size::Bit).then_some(0);
                issues.push(Issue::new(
                    IssueKind::AddressWidth {
                        at: at.value.clone(),
                        size: a.size,
                        iec: v.iec_type.as_ref().map_or(k.iec, |t| t.value),
                        suggestion: IecAddress::new(a.area, needed, a.byte, bit),
                    },
                    at.at.clone(),
                ));
                continue;
            }
        }
        if !decl.unaligned && !a.is_aligned() {
            issues.push(Issue::new(
                IssueKind::Misaligned {
                    at: at.value.clone(),
                    size: a.size,
                },
                at.at.clone(),
            ));
        }
        let first = a
            .byte_range()
            .filter_map(|b| on_byte.get(&(a.area, b)))
            .flatten()
            .copied()
            .filter(|&j| vars[j].address.is_some_and(|o| o.overlaps(&a)))
            .min();
        if let Some(j) = first
            && let (Some(other_at), Some(other)) = (vars[j].address, &decl.vars[j].at)
        {
            issues.push(Issue {
                kind: IssueKind::AddressOverlap {
                    at: a,
                    other_at,
                    other: decl.vars[j].field.clone(),
                },
                at: at.at.clone(),
                related: Some(other.at.clone()),
            });
        }
        for b in a.byte_range() {
            on_byte.entry((a.area, b)).or_default().push(i);
        }
    }
}

fn directions<L: Clone>(decl: &Decl<L>, vars: &mut [Resolved], issues: &mut Vec<Issue<L>>) {
    // Located and unmapped variables first; bit-mapped bools then take their source's.
    for (v, r) in decl.vars.iter().zip(vars.iter_mut()) {
        let implied = r.address.map(|a| match a.area {
            Area::Input => Direction::Input,
            _ => Direction::Output,
        });
        r.direction = match (&v.direction, implied) {
            (Some(d), Some(implied)) if d.value != implied => {
                issues.push(Issue::new(
                    IssueKind::DirectionContradictsAddress {
                        given: d.value,
                        at: v.at.as_ref().map_or_else(String::new, |a| a.value.clone()),
                        var: v.field.clone(),
                        implied,
                    },
                    d.at.clone(),
                ));
                implied
            }
            (Some(d), _) => d.value,
            (None, Some(implied)) => implied,
            (None, None) => Direction::Internal,
        };
    }
    for i in 0..vars.len() {
        let Some((s, _)) = vars[i].mapped else {
            continue;
        };
        let source_direction = vars[s].direction;
        let v = &decl.vars[i];
        match &v.direction {
            Some(d) if d.value != source_direction => issues.push(Issue::new(
                IssueKind::DirectionContradictsSource {
                    given: d.value,
                    source: v
                        .source
                        .as_ref()
                        .map_or_else(String::new, |x| x.value.clone()),
                    source_direction,
                },
                d.at.clone(),
            )),
            _ => vars[i].direction = source_direction,
        }
    }
}

fn shared_links<L: Clone>(decl: &Decl<L>, issues: &mut Vec<Issue<L>>) {
    // Links compare case-insensitively, as the bus description's names do.
    let mut first: FnvMap<NoCase, &str> = FnvMap::default();
    for v in &decl.vars {
        let Some(link) = &v.link else { continue };
        match first.get(&NoCase(&link.value)) {
            Some(f) => issues.push(Issue::new(
                IssueKind::SharedLink {
                    link: link.value.clone(),
                    first: (*f).to_string(),
                },
                link.at.clone(),
            )),
            None => {
                first.insert(NoCase(&link.value), &v.name.value);
            }
        }
    }
}
