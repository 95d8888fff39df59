//! Link resolution for a `GlobalMemory` type: its `VARIABLES` put through the bus
//! description's rules ([`plc_rules::bus::links`], which the derive applies too, while
//! compiling, to a struct that names its bus description), each good link a [`Binding`].

use super::layout::{BusLayout, EntryLayout};
use plc_core::{GlobalMemory, IecType, VarInfo};
use plc_rules::bus::{LinkedVar, resolve_links};
use std::fmt;

/// One resolved link: a variable and the process data it moves to or from.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Binding {
    /// Index of the variable in `VARIABLES`.
    pub var: usize,
    /// The variable's name.
    pub var_name: &'static str,
    /// The variable's IEC type.
    pub var_type: IecType,
    /// The link text.
    pub link: &'static str,
    /// Where the entry sits.
    pub entry: EntryLayout,
}

/// One problem with one variable's link.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LinkProblem {
    /// The variable.
    pub variable: &'static str,
    /// Its link.
    pub link: &'static str,
    /// What is wrong and what to do.
    pub message: String,
}

/// The links of a `GlobalMemory` type do not fit the bus description: every problem.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ResolveError {
    /// One per problem, in declaration order.
    pub problems: Vec<LinkProblem>,
}

impl fmt::Display for ResolveError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} link problem{} (nothing was sent to the bus):",
            self.problems.len(),
            if self.problems.len() == 1 { "" } else { "s" }
        )?;
        for p in &self.problems {
            write!(
                f,
                "\n  - `{}` (link `{}`): {}",
                p.variable, p.link, p.message
            )?;
        }
        Ok(())
    }
}

impl std::error::Error for ResolveError {}

/// Resolves the links of `T` against a bus layout.
pub fn resolve<T: GlobalMemory>(layout: &BusLayout) -> Result<Vec<Binding>, ResolveError> {
    resolve_vars(T::VARIABLES, layout)
}

/// Resolves the links of a variable list (what [`resolve`] does for `T::VARIABLES`).
pub fn resolve_vars(vars: &[VarInfo], layout: &BusLayout) -> Result<Vec<Binding>, ResolveError> {
    let linked: Vec<Option<LinkedVar>> = vars
        .iter()
        .map(|v| {
            Some(LinkedVar {
                name: v.name,
                link: v.link?,
                iec_type: Some(v.iec_type),
                array: Some(!v.dims.is_empty()),
                direction: v.direction,
            })
        })
        .collect();
    let (entries, issues) = resolve_links(&linked, layout);
    if !issues.is_empty() {
        return Err(ResolveError {
            problems: issues
                .into_iter()
                .map(|i| LinkProblem {
                    variable: vars[i.var].name,
                    link: vars[i.var].link.unwrap_or_default(),
                    message: i.message,
                })
                .collect(),
        });
    }
    Ok(entries
        .into_iter()
        .enumerate()
        .filter_map(|(var, entry)| {
            let v = &vars[var];
            Some(Binding {
                var,
                var_name: v.name,
                var_type: v.iec_type,
                link: v.link?,
                entry: entry?,
            })
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{BusConfig, PdoDirection, PdoEntry, devices};
    use plc_core::Direction;

    /// A variable the derive would refuse to link (so a test can reach the runtime's own
    /// check): a BOOL's description, its type, direction and link set by hand.
    fn var(name: &'static str, ty: IecType, dir: Direction, link: &'static str) -> VarInfo {
        let mut v = plc_core::__private::var::<bool>(name, ty.rust_name(), 0, 1);
        v.iec_type = ty;
        v.size = ty.image_size().max(1);
        v.link = Some(link);
        v.direction = dir;
        v
    }

    /// Resolving `vars` on [`layout`] fails with exactly these problems (each a part of the
    /// message).
    fn assert_problems(vars: &[VarInfo], needles: &[&str]) {
        let err = resolve_vars(vars, &layout()).unwrap_err();
        let text = err.to_string();
        assert_eq!(err.problems.len(), needles.len(), "{text}");
        for needle in needles {
            assert!(text.contains(needle), "missing {needle:?} in\n{text}");
        }
    }

    fn layout() -> BusLayout {
        BusLayout::new(&BusConfig {
            devices: vec![
                devices::ek1100("coupler"),
                devices::el1004("di"),
                devices::el2889("dq").grouped(PdoDirection::Output, "word", IecType::Uint),
            ],
        })
    }

    /// Links compare case-insensitively, as the framework's tools compare them: one entry by two
    /// spellings is one entry, so two writers of it are refused.
    #[test]
    fn links_that_differ_only_in_case_are_one_link() {
        let vars = [
            var("a", IecType::Bool, Direction::Input, "ethercat.DI.Input2"),
            var("b", IecType::Bool, Direction::Input, "ethercat.di.input2"),
        ];
        let b = resolve_vars(&vars, &layout()).unwrap();
        assert_eq!(b[0].entry, b[1].entry);
        assert_problems(
            &[
                var("w", IecType::Uint, Direction::Output, "ethercat.dq.word"),
                var("v", IecType::Uint, Direction::Output, "ethercat.DQ.Word"),
            ],
            &["`w` is written to this output entry already"],
        );
    }

    /// An entry named by a dotted path, as the framework's motion axes name theirs.
    #[test]
    fn an_entry_path_of_several_parts_resolves() {
        let mut axis = devices::el1004("motion");
        axis.entries = vec![
            PdoEntry::new("x.position", PdoDirection::Input, 16, IecType::Int),
            PdoEntry::new("x.actual_velocity", PdoDirection::Input, 16, IecType::Int),
        ];
        let bus = BusConfig {
            devices: vec![devices::ek1100("coupler"), axis],
        };
        bus.validate().unwrap();
        let vars = [var(
            "v",
            IecType::Dint,
            Direction::Input,
            "ethercat.motion.x.actual_velocity",
        )];
        let b = resolve_vars(&vars, &BusLayout::new(&bus)).unwrap();
        assert_eq!((b[0].entry.bit_offset, b[0].entry.bits), (16, 16));
    }

    #[test]
    fn good_links_resolve_and_inputs_may_be_shared() {
        let vars = [
            var("a", IecType::Bool, Direction::Input, "ethercat.di.input2"),
            var(
                "b",
                IecType::Bool,
                Direction::Internal,
                "ethercat.di.input2",
            ),
            var("w", IecType::Udint, Direction::Output, "ethercat.dq.word"),
        ];
        // UDINT does not widen to UINT: the output word must be u16 or narrower.
        assert!(resolve_vars(&vars, &layout()).is_err());
        let vars = [
            var("a", IecType::Bool, Direction::Input, "ethercat.di.input2"),
            var(
                "b",
                IecType::Bool,
                Direction::Internal,
                "ethercat.di.input2",
            ),
            var("w", IecType::Usint, Direction::Output, "ethercat.dq.word"),
        ];
        let b = resolve_vars(&vars, &layout()).unwrap();
        assert_eq!(b.len(), 3);
        assert_eq!(b[0].entry.bit_offset, 1);
        assert_eq!(b[2].entry.bits, 16);
    }

    #[test]
    fn every_problem_is_listed_with_the_variable_and_what_to_do() {
        let vars = [
            var(
                "no_dev",
                IecType::Bool,
                Direction::Input,
                "ethercat.nope.input1",
            ),
            var(
                "no_entry",
                IecType::Bool,
                Direction::Input,
                "ethercat.di.input9",
            ),
            var(
                "coupler_io",
                IecType::Bool,
                Direction::Input,
                "ethercat.coupler.x",
            ),
            var(
                "wrong_dir",
                IecType::Bool,
                Direction::Output,
                "ethercat.di.input1",
            ),
            var(
                "wrong_type",
                IecType::Usint,
                Direction::Input,
                "ethercat.di.input1",
            ),
            var(
                "narrow",
                IecType::Dint,
                Direction::Output,
                "ethercat.dq.word",
            ),
            var(
                "first",
                IecType::Uint,
                Direction::Output,
                "ethercat.dq.word",
            ),
            var(
                "second",
                IecType::Uint,
                Direction::Output,
                "ethercat.dq.word",
            ),
            var(
                "cmd",
                IecType::Bool,
                Direction::Command,
                "ethercat.di.input1",
            ),
        ];
        // `narrow` is the entry's first writer despite its type error, so `first` and
        // `second` are both second writers.
        assert_problems(
            &vars,
            &[
                "`no_dev` (link `ethercat.nope.input1`): the bus has no device `nope`: use one of `coupler`, `di`, `dq`",
                "`no_entry` (link `ethercat.di.input9`): device `di` has no entry `input9` (did you mean `input1`?): use one of `input1`, `input2`, `input3`, `input4`",
                "`coupler_io` (link `ethercat.coupler.x`): device `coupler` has no process data",
                "`wrong_dir` (link `ethercat.di.input1`): `input1` is an input entry, but the variable is declared `direction = \"output\"`",
                "`wrong_type` (link `ethercat.di.input1`): the variable is USINT and the input entry is BOOL (1 bit); BOOL does not widen implicitly to USINT",
                "`narrow` (link `ethercat.dq.word`): the variable is DINT and the output entry is UINT (16 bits); DINT does not widen implicitly to UINT",
                "`first` (link `ethercat.dq.word`): `narrow` is written to this output entry already",
                "`second` (link `ethercat.dq.word`): `narrow` is written to this output entry already",
                "`cmd` (link `ethercat.di.input1`): `input1` is an input entry, but the variable is declared `direction = \"command\"`",
            ],
        );
    }

    #[test]
    fn a_type_of_the_same_rust_type_is_named_by_its_iec_type() {
        // WORD and UINT are both `u16`: "declare it `u16`" would not help.
        assert_problems(
            &[var(
                "word_typed",
                IecType::Word,
                Direction::Output,
                "ethercat.dq.word",
            )],
            &[
                "WORD does not widen implicitly to UINT (IEC 61131-3): declare it with \
               `iec_type = \"UINT\"`, or give the entry the type WORD in the bus description",
            ],
        );
    }

    #[test]
    fn arrays_strings_and_status_variables_cannot_be_linked() {
        let mut array = var("arr", IecType::Bool, Direction::Input, "ethercat.di.input1");
        (array.dims, array.size) = (&[4], 4);
        let mut string = var(
            "text",
            IecType::String,
            Direction::Input,
            "ethercat.di.input2",
        );
        (string.size, string.rust_type) = (16, "FixedString<16>");
        let vars = [
            array,
            string,
            var(
                "state",
                IecType::Bool,
                Direction::Status,
                "ethercat.di.input3",
            ),
        ];
        assert_problems(
            &vars,
            &[
                "`arr` (link `ethercat.di.input1`): only scalar numbers and bools can be linked, \
             this is a BOOL array: link a scalar variable",
                "`text` (link `ethercat.di.input2`): only scalar numbers and bools can be linked, \
             this is a STRING: link a scalar variable",
                "`state` (link `ethercat.di.input3`): `input3` is an input entry, but the variable \
             is declared `direction = \"status\"`",
            ],
        );
    }

    #[test]
    fn a_second_writer_is_reported_even_when_the_first_has_a_type_error() {
        let vars = [
            var(
                "too_wide",
                IecType::Udint,
                Direction::Output,
                "ethercat.dq.word",
            ),
            var(
                "second",
                IecType::Uint,
                Direction::Output,
                "ethercat.dq.word",
            ),
        ];
        assert_problems(
            &vars,
            &[
                "`too_wide` (link `ethercat.dq.word`): the variable is UDINT",
                "`second` (link `ethercat.dq.word`): `too_wide` is written to this output entry \
                 already",
            ],
        );
    }

    #[test]
    fn consecutive_devices_sharing_a_name_form_one_module() {
        let bus = BusConfig {
            devices: vec![
                devices::ek1100("coupler"),
                devices::el1004("impact67_0").grouped(
                    PdoDirection::Input,
                    "digital_inputs",
                    IecType::Uint,
                ),
                devices::el2889("impact67_0").grouped(
                    PdoDirection::Output,
                    "digital_outputs",
                    IecType::Uint,
                ),
            ],
        };
        bus.validate().unwrap();
        let vars = [
            var(
                "i",
                IecType::Uint,
                Direction::Input,
                "ethercat.impact67_0.digital_inputs",
            ),
            var(
                "o",
                IecType::Uint,
                Direction::Output,
                "ethercat.impact67_0.digital_outputs",
            ),
        ];
        let b = resolve_vars(&vars, &BusLayout::new(&bus)).unwrap();
        assert_eq!((b[0].entry.device, b[1].entry.device), (1, 2));
    }
}
