//! `plc change SEGMENT MODULE --dry-run [--reset PATH...]`: what an online change to a new
//! build of the program would do to every value of the running one, from the two descriptors.
//! The module is checked as a host checks it (owner, writers, links, ELF, fingerprint, entry)
//! and loaded only by a short-lived child: its code never runs in `plc`.

use super::Error;
use plc_module::trial::Trial;
use plc_module::{Module, ModuleInfo};
use plc_shm::DynSegment;
use plc_shm::change::{ChangePlan, Direction};
use std::path::{Path, PathBuf};

/// `plc change`.
#[derive(clap::Args)]
pub struct ChangeArgs {
    /// Segment of the running program.
    pub segment: String,
    /// The new build of the program: the `lib<name>.so` of a crate that uses
    /// `plc_io::program!`.
    #[arg(required_unless_present = "back")]
    pub module: Option<PathBuf>,
    /// Print what the change would do to each value, and change nothing.
    #[arg(long)]
    pub dry_run: bool,
    /// Start this value afresh from the new build's initial value, whatever it was (a
    /// variable, a structure or array with everything in it, or one value: `axes[1].pos`).
    /// A change that cannot carry a value over is refused unless this names it.
    #[arg(long, value_name = "PATH")]
    pub reset: Vec<String>,
    /// Return to the build that ran before the last change.
    #[arg(long, conflicts_with = "module")]
    pub back: bool,
}

pub fn run(args: &ChangeArgs) -> Result<(), Error> {
    let seg = DynSegment::attach(&args.segment)?;
    let module = match (&args.module, args.dry_run && !args.back) {
        (Some(module), true) => module,
        _ => {
            return Err(format!(
                "segment `{}`: this version of plc-vars plans a change but does not make one \
                 yet: stop the program and start the new build (`plc run MODULE` keeps the \
                 retained values); `plc change {} MODULE --dry-run` shows what a change would \
                 do to each value",
                args.segment, args.segment
            )
            .into());
        }
    };
    let info = Module::inspect(module, &Trial::this_program()?)?;
    let plan = ChangePlan::new(
        seg.descriptor(),
        &info.descriptor,
        &args.reset,
        Direction::Forward,
    )
    .map_err(|refused| {
        let lines: Vec<String> = refused.iter().map(|r| format!("  {r}")).collect();
        format!(
            "the change of `{}` to `{}` is refused, nothing changed:\n{}\nname a value with \
             --reset PATH to start it afresh from the new build's initial value",
            args.segment,
            module.display(),
            lines.join("\n")
        )
    })?;
    print!("{}", report(&args.segment, module, &info, &plan));
    Ok(())
}

/// The report: the change and each value in the list of what happens to it.
fn report(segment: &str, module: &Path, info: &ModuleInfo, plan: &ChangePlan) -> String {
    let mut out = format!(
        "dry run, nothing changed: segment `{segment}` would run `{}` ({}), built by {}\n",
        info.name,
        module.display(),
        info.fingerprint
    );
    if plan.changes_nothing() {
        out.push_str("every value is kept as it is: the change would swap the code only\n");
    }
    let lists = [
        ("kept", &plan.kept),
        ("converted", &plan.widened),
        ("added", &plan.added),
        ("reset", &plan.reset),
        ("removed", &plan.removed),
    ];
    for (what, paths) in lists {
        out.push_str(&format!("{what:<10} {:>5}", paths.len()));
        let mut width = 16;
        for (k, path) in paths.iter().enumerate() {
            let sep = if k == 0 { "  " } else { ", " };
            if k > 0 && width + sep.len() + path.len() > 100 {
                out.push_str(",\n                 ");
                width = 17;
            } else {
                out.push_str(sep);
                width += sep.len();
            }
            out.push_str(path);
            width += path.len();
        }
        out.push('\n');
    }
    out
}
