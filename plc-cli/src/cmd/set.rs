//! `plc set <segment> name=value...`: every assignment is parsed and checked first (type,
//! range, string capacity, read-only, input, status), and the mailbox must have room for all
//! of them; only then are they posted, in order. Then it waits (bounded) for the program to
//! take them and reports each one it did not apply.
//!
//! The room check and the posts are not one atomic step: if another tool fills the mailbox in
//! between, the writes posted before that are named, and so are those that were not.

use super::{Error, is_path, resolve};
use plc_core::Value;
use plc_io::shm::mailbox::{Outcome, Ticket};
use plc_io::shm::{DynSegment, OwnerState};
use std::time::{Duration, Instant};

/// A checked assignment: what the user named, the variable's index, the element (a leaf
/// inside a structure) and the value.
#[derive(Clone, Debug)]
pub struct Target {
    pub label: String,
    pub element: usize,
    pub value: Value,
    /// Where, for a value named by its path.
    pub at: Option<plc_io::shm::PathLocation>,
}

impl Target {
    /// Posts the write; its ticket.
    pub fn post(&self, seg: &DynSegment) -> Result<Ticket, plc_io::shm::ShmError> {
        match &self.at {
            Some(at) => seg.post_location(at, self.value),
            None => seg.post_element(&self.label, self.element, self.value),
        }
    }
}

type Checked = Target;

/// Parses and checks `name=value` against the segment, as the owner would.
pub fn check(seg: &DynSegment, assignment: &str) -> Result<Checked, Error> {
    let (spec, text) = assignment
        .split_once('=')
        .ok_or_else(|| format!("`{assignment}`: write `name=value`"))?;
    if is_path(seg, spec) {
        let at = seg.locate(spec)?;
        let value =
            Value::parse(text, at.var.iec_type).map_err(|e| format!("`{}`: {e}", at.path))?;
        let value = seg.check_location(&at, value)?;
        return Ok(Target {
            label: at.path.clone(),
            element: at.leaf,
            value,
            at: Some(at),
        });
    }
    let (_, var, element) = resolve(seg, spec.trim())?;
    let element = element.unwrap_or(0);
    // Parsed as the variable's type; every other check is the library's, as the owner makes it.
    let value = Value::parse(text, var.iec_type).map_err(|e| format!("`{}`: {e}", var.name))?;
    let value = seg.check(&var.name, element, value)?;
    Ok(Target {
        label: var.name.clone(),
        element,
        value,
        at: None,
    })
}

/// How long to wait for the program to take the writes: fifty of its cycles, at least a second
/// (a busy machine), at most ten (a person is waiting at the terminal).
fn patience(seg: &DynSegment) -> Duration {
    (seg.status().stats.period * 50).clamp(Duration::from_secs(1), Duration::from_secs(10))
}

pub fn run(segment: &str, assignments: &[String]) -> Result<(), Error> {
    let seg = DynSegment::attach(segment)?;
    let checked: Vec<Checked> = assignments
        .iter()
        .map(|a| check(&seg, a))
        .collect::<Result<_, _>>()?;
    let free = seg.mailbox_free();
    if checked.len() > free {
        return Err(format!(
            "the mailbox of segment `{}` has room for {free} writes, not {}: nothing was \
             written; try again, with fewer at once (is the program running? `plc list` shows \
             its state)",
            seg.name(),
            checked.len()
        )
        .into());
    }
    let mut posted: Vec<(&Checked, Ticket)> = Vec::new();
    for (i, c) in checked.iter().enumerate() {
        match c.post(&seg) {
            Ok(ticket) => posted.push((c, ticket)),
            Err(e) => {
                let quote = |c: &Checked| format!("`{}`", c.label);
                let done: Vec<String> = posted.iter().map(|p| quote(p.0)).collect();
                let left: Vec<String> = checked[i..].iter().map(quote).collect();
                return Err(format!(
                    "{e}\nposted before that: {}; not written: {}",
                    if done.is_empty() {
                        "none".to_string()
                    } else {
                        done.join(", ")
                    },
                    left.join(", ")
                )
                .into());
            }
        }
    }
    let limit = patience(&seg);
    let start = Instant::now();
    let (outcomes, gone) = loop {
        let outcomes: Vec<Outcome> = posted.iter().map(|&(_, t)| seg.outcome(t)).collect();
        let gone = seg.owner_state() == OwnerState::Gone;
        if !outcomes.contains(&Outcome::Pending) || gone || start.elapsed() > limit {
            break (outcomes, gone);
        }
        std::thread::sleep(Duration::from_millis(2));
    };
    let mut problems = Vec::new();
    for (
        &(
            Target {
                label: name, value, ..
            },
            _,
        ),
        outcome,
    ) in posted.iter().zip(outcomes)
    {
        match outcome {
            Outcome::Applied => println!("{name} <- {value}"),
            // Taken, but so many writes followed that its slot was reused before we looked.
            Outcome::Unknown => println!("{name} <- {value} (taken by the program)"),
            Outcome::Rejected => problems.push(format!(
                "`{name}` was refused by the program: it may not be written from outside, or \
                 the program refused the value"
            )),
            Outcome::Discarded => problems.push(format!(
                "`{name}` was damaged in the mailbox by another writer and dropped: write it again"
            )),
            Outcome::Pending if gone => problems.push(format!(
                "`{name}` is posted, but the program stopped before it took it"
            )),
            Outcome::Pending => problems.push(format!(
                "`{name}` is posted, but the program did not take it within {:.1} s (is it \
                 running? `plc list` shows its state); it is applied when the program takes it",
                limit.as_secs_f64()
            )),
        }
    }
    if problems.is_empty() {
        Ok(())
    } else {
        Err(problems.join("\n").into())
    }
}
