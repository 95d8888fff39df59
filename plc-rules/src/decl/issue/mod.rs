//! Every problem the checker finds, as a typed value, and its one wording. Each message states
//! the rule and the fix; the repository's `docs/rules.md` lists them with examples.
//!
//! Here is [`Issue`], one problem found; its kinds ([`IssueKind`], the rules and their names)
//! are in `kind`, the message texts in `message`, and what a front end chooses ([`Wording`])
//! in `wording`.

mod kind;
mod message;
mod wording;

pub use kind::{Expected, IssueKind, KIND_NAMES};
pub use wording::Wording;

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
}
