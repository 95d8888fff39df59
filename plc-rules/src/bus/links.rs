//! Link resolution: each `link = "ethercat.<device>.<entry>"` of a declaration turned into a
//! place in a SubDevice's process data, with every problem reported at once. plc-io applies it
//! before the bus starts; the derive applies it while compiling, for a struct that names its
//! bus description (`#[plc(bus = "...")]`), so a bad link is a compile error under it.
//!
//! Rules:
//! - the device and the entry must exist in the bus description (names compare
//!   case-insensitively, as links do); a name close to one that exists is suggested;
//! - directions: an input entry feeds a variable declared `direction = "input"`, an output
//!   entry is fed by one declared `direction = "output"`; a linked variable left `internal`
//!   (the default, e.g. from a JSON variable list, which has no directions) takes the entry's
//!   direction. `command` and `status` variables cannot be linked.
//! - types: an input widens from the entry's type to the variable's, an output from the
//!   variable's type to the entry's, as [`can_widen`] allows (IEC 61131-3);
//! - one variable per output entry (two writers would fight); any number per input entry;
//! - only scalar variables, not strings or arrays.

use super::{BusLayout, EntryLayout, PdoDirection};
use crate::link::Link;
use crate::widening::can_widen;
use crate::{Direction, IecType};
use std::format;
use std::string::{String, ToString};
use std::vec::Vec;

/// A linked variable, as far as its link is concerned.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LinkedVar<'a> {
    /// Its name, for messages.
    pub name: &'a str,
    /// The link text.
    pub link: &'a str,
    /// Its IEC type, if known (the derive does not know an alias's).
    pub iec_type: Option<IecType>,
    /// Whether it is an array (which cannot be linked, nor can a string), if known.
    pub array: Option<bool>,
    /// Its effective direction.
    pub direction: Direction,
}

/// One problem with one variable's link.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LinkIssue {
    /// Index of the variable in the list given to [`resolve_links`].
    pub var: usize,
    /// What is wrong and what to do.
    pub message: String,
}

/// Resolves the links of `vars` (those with `Some`) on `layout`: for each, the entry it moves
/// to or from where the link is good, and every problem.
pub fn resolve_links(
    vars: &[Option<LinkedVar>],
    layout: &BusLayout,
) -> (Vec<Option<EntryLayout>>, Vec<LinkIssue>) {
    let mut entries = Vec::with_capacity(vars.len());
    let mut issues = Vec::new();
    // Every output variable linked to an output entry, whether or not its link has other
    // problems (its type): a second writer is reported even when the first one is wrong in
    // another way too, so the user sees all problems of one run at once.
    let mut writers: Vec<(usize, usize, &str)> = Vec::new();
    for (index, v) in vars.iter().enumerate() {
        let Some(v) = v else {
            entries.push(None);
            continue;
        };
        let mut problems = Vec::new();
        let entry = check_one(v, layout, &mut problems);
        if let Some(entry) = entry
            && entry.direction == PdoDirection::Output
            && direction_fits(entry.direction, v.direction)
        {
            // A variable declared for the other direction does not write the entry: its
            // problem is the direction, not a second writer.
            match writers
                .iter()
                .find(|(d, e, _)| *d == entry.device && *e == entry.entry)
            {
                Some(&(_, _, other)) => problems.push(format!(
                    "`{other}` is written to this output entry already: an output has one \
                     writer; link one variable and copy or bit-map the others from it in the \
                     program"
                )),
                None => writers.push((entry.device, entry.entry, v.name)),
            }
        }
        entries.push(entry.filter(|_| problems.is_empty()).cloned());
        issues.extend(problems.into_iter().map(|message| LinkIssue {
            var: index,
            message,
        }));
    }
    (entries, issues)
}

fn direction_fits(entry: PdoDirection, var: Direction) -> bool {
    matches!(
        (entry, var),
        (PdoDirection::Input, Direction::Input | Direction::Internal)
            | (
                PdoDirection::Output,
                Direction::Output | Direction::Internal
            )
    )
}

/// The rules of one link on its own; returns the entry it names if it exists.
fn check_one<'l>(
    v: &LinkedVar,
    layout: &'l BusLayout,
    problems: &mut Vec<String>,
) -> Option<&'l EntryLayout> {
    let parsed = match Link::parse(v.link) {
        Ok(l) => l,
        Err(e) => {
            problems.push(e.to_string());
            return None;
        }
    };
    if !layout
        .names
        .iter()
        .any(|n| n.eq_ignore_ascii_case(parsed.device))
    {
        let names: Vec<&str> = unique(&layout.names).collect();
        problems.push(format!(
            "the bus has no device `{}`{}: use one of {} or add the device to the bus \
             description",
            parsed.device,
            did_you_mean(parsed.device, &names),
            list(names.iter().copied())
        ));
        return None;
    }
    let Some(entry) = layout.entry(parsed.device, parsed.entry) else {
        let names: Vec<&str> = layout
            .entries
            .iter()
            .filter(|e| layout.names[e.device].eq_ignore_ascii_case(parsed.device))
            .map(|e| e.name.as_str())
            .collect();
        problems.push(if names.is_empty() {
            format!(
                "device `{}` has no process data (a coupler?): link an entry of an I/O \
                 terminal",
                parsed.device
            )
        } else {
            format!(
                "device `{}` has no entry `{}`{}: use one of {}",
                parsed.device,
                parsed.entry,
                did_you_mean(parsed.entry, &names),
                list(names.iter().copied())
            )
        });
        return None;
    };
    if let Some(ty) = v.iec_type
        && (v.array == Some(true) || ty == IecType::String)
    {
        problems.push(format!(
            "only scalar numbers and bools can be linked, this is a {ty}{}: link a scalar \
             variable",
            if v.array == Some(true) { " array" } else { "" }
        ));
        return None;
    }
    if !direction_fits(entry.direction, v.direction) {
        problems.push(format!(
            "`{}` is an {} entry, but the variable is declared `direction = \"{}\"`: declare \
             `direction = \"{}\"` or link an {} entry",
            parsed.entry,
            entry.direction,
            v.direction,
            entry.direction,
            if entry.direction == PdoDirection::Input {
                "output"
            } else {
                "input"
            }
        ));
    }
    if let Some(ty) = v.iec_type {
        let (from, to) = match entry.direction {
            PdoDirection::Input => (entry.iec_type, ty),
            PdoDirection::Output => (ty, entry.iec_type),
        };
        if !can_widen(from, to) {
            let suggestion = match entry.iec_type {
                IecType::Bool => "declare it `bool`".to_string(),
                // The same Rust type (`u16` is UINT, WORD is `u16` too): the IEC type says it.
                t if t.rust_name() == ty.rust_name() => format!(
                    "declare it with `iec_type = \"{t}\"`, or give the entry the type {ty} in \
                     the bus description"
                ),
                t => format!(
                    "declare it `{}` (or a type it widens {} implicitly)",
                    t.rust_name(),
                    if entry.direction == PdoDirection::Input {
                        "to"
                    } else {
                        "from"
                    }
                ),
            };
            problems.push(format!(
                "the variable is {ty} and the {} entry is {} ({} bit{}); {from} does not widen \
                 implicitly to {to} (IEC 61131-3): {suggestion}",
                entry.direction,
                entry.iec_type,
                entry.bits,
                if entry.bits == 1 { "" } else { "s" },
            ));
        }
    }
    Some(entry)
}

/// ` (did you mean `x`?)` for the name of `names` nearest `wrong`, if one is near (a typo or
/// two), else nothing.
fn did_you_mean(wrong: &str, names: &[&str]) -> String {
    crate::names::nearest(wrong, names.iter().copied())
        .map_or_else(String::new, |n| format!(" (did you mean `{n}`?)"))
}

fn unique(names: &[String]) -> impl Iterator<Item = &str> {
    names
        .iter()
        .enumerate()
        .filter(|(i, n)| *i == 0 || names[i - 1] != **n)
        .map(|(_, n)| n.as_str())
}

fn list<'a>(names: impl Iterator<Item = &'a str>) -> String {
    let names: Vec<String> = names.map(|n| format!("`{n}`")).collect();
    if names.is_empty() {
        "(none)".into()
    } else {
        names.join(", ")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn near_names_are_suggested_and_far_ones_not() {
        let names = ["digital_inputs", "digital_outputs", "analog_in"];
        assert_eq!(
            did_you_mean("digtal_inputs", &names),
            " (did you mean `digital_inputs`?)"
        );
        assert_eq!(
            did_you_mean("Digital_Input", &names),
            " (did you mean `digital_inputs`?)"
        );
        assert_eq!(did_you_mean("speed", &names), "");
    }
}
