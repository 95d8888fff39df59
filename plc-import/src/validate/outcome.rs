//! What checking a list gives: where each problem is, the problems, and the checked
//! declarations (the list's variables and its types), as the emitter and the error report
//! read them.

use plc_rules::decl::Decl;
use std::borrow::Cow;

/// Where something is in a variable list: the structure type the variable is a member of
/// (`None` for the list's own variables), the variable (its index in that group's
/// declaration) and the field (JSON key, CSV column), `None` for the variable as a whole.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ListAt {
    /// The type (index into [`Checked::types`]), `None` for the list's variables.
    pub ty: Option<usize>,
    /// The variable.
    pub var: usize,
    /// The field (owned only for a field the format does not know).
    pub field: Option<Cow<'static, str>>,
}

/// One worded problem and where it is.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Problem {
    /// Where.
    pub at: ListAt,
    /// What is wrong and what to do.
    pub message: String,
    /// The declaration rule broken (`IssueKind::name`), `None` for the format's own.
    pub kind: Option<&'static str>,
}

/// A variable of a structure type: the type (index into [`Checked::types`]) and the array
/// dimensions, outermost first (empty for one structure).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct StructUse {
    /// The type.
    pub ty: usize,
    /// The dimensions.
    pub dims: Vec<u64>,
}

/// One declaration: the variables in file order, then the names given twice.
pub struct Group {
    pub decl: Decl<ListAt>,
    /// How many of `decl`'s variables are the list's own; the rest are the second uses of a
    /// name, declared to be reported, not generated.
    pub declared: usize,
    /// For each variable, its structure type, if it has one (its `decl` type is then
    /// [`DeclType::Unknown`](plc_rules::decl::DeclType::Unknown): the rules of basic types
    /// do not apply to it).
    pub structured: Vec<Option<StructUse>>,
}

/// One type of the `types` section, checked.
pub struct CheckedType {
    /// The type's name, as the list gives it and tools show it.
    pub name: String,
    /// Its description ("" if none).
    pub description: String,
    /// Its members.
    pub group: Group,
    /// Whether an earlier type has the same name (in any case): checked, not generated.
    pub duplicate: bool,
    /// For a standard function block (`TON`), the Rust type the generated code names: the
    /// list uses it without declaring it, and it is not generated.
    pub standard: Option<&'static str>,
}

/// A problem of a type as a whole (its name, its fields), by type index and field.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TypeProblem {
    /// The type (index into [`Checked::types`]).
    pub ty: usize,
    /// The field (`description`, `variables`), `None` for the type's name.
    pub field: Option<String>,
    /// What is wrong and what to do.
    pub message: String,
}

/// The outcome: the list's variables, its types, every error (type problems, then the members'
/// and variables' in file order) and warnings.
pub struct Checked {
    /// The list's own variables.
    pub top: Group,
    /// The types, in file order.
    pub types: Vec<CheckedType>,
    /// The types in dependency order (a type after every type its members use), as they are
    /// generated.
    pub order: Vec<usize>,
    /// Bytes of the whole image (saturating): below 2^32 for a valid list.
    pub image_bytes: u64,
    pub type_errors: Vec<TypeProblem>,
    pub errors: Vec<Problem>,
    pub warnings: Vec<Problem>,
}

impl Checked {
    /// The group a location is in.
    pub fn group(&self, ty: Option<usize>) -> &Group {
        match ty {
            Some(t) => &self.types[t].group,
            None => &self.top,
        }
    }

    /// The types the list declares (not the standard function blocks), with their indexes.
    pub fn listed(&self) -> impl Iterator<Item = (usize, &CheckedType)> + Clone {
        self.types
            .iter()
            .enumerate()
            .filter(|(_, t)| t.standard.is_none())
    }

    /// The name of the variable at `at`.
    pub fn var_name(&self, at: &ListAt) -> &str {
        &self.group(at.ty).decl.vars[at.var].name.value
    }
}
