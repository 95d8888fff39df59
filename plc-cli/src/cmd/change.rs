//! `plc change SEGMENT MODULE [--dry-run] [--reset PATH...]`, `plc change SEGMENT --back`: an
//! online change of a program `plc run` hosts, asked of the host through its change socket
//! (`change_server`), which reports each value kept, converted, added, reset and removed.
//! Against a linked program only `--dry-run` works: the module is then checked here as a host
//! checks it and loaded only by a short-lived child, its code never run in `plc`.

use super::Error;
use super::change_wire::{Outcome, Request, ask, head, refused_plan, report, socket_path};
use plc_module::Module;
use plc_module::trial::Trial;
use plc_shm::DynSegment;
use plc_shm::change::{ChangePlan, Direction};
use std::os::unix::net::UnixStream;
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
    let socket = socket_path(&args.segment)?;
    let module = match &args.module {
        Some(m) => Some(std::path::absolute(m)?),
        None => None,
    };
    match UnixStream::connect(&socket) {
        Ok(stream) => ask_host(stream, module, args),
        Err(e) if e.kind() == std::io::ErrorKind::PermissionDenied => Err(format!(
            "segment `{}` is run by another user: only the user who runs a program may change \
             it (its change socket `{}` is not yours)",
            args.segment,
            socket.display()
        )
        .into()),
        Err(_) => {
            let seg = DynSegment::attach(&args.segment)?;
            match (&module, args.dry_run) {
                (Some(module), true) => plan_here(&seg, module, args),
                _ => Err(format!(
                    "segment `{}` is not run by `plc run` (no change socket `{}` of yours): only \
                     a program `plc run` hosts takes a new build between two cycles; a linked \
                     program is stopped and started again (`plc change {} MODULE --dry-run` \
                     shows what a change would do to each value)",
                    args.segment,
                    socket.display(),
                    args.segment
                )
                .into()),
            }
        }
    }
}

/// The change through the host's socket: it prepares, makes and reports it.
fn ask_host(stream: UnixStream, module: Option<PathBuf>, args: &ChangeArgs) -> Result<(), Error> {
    let request = Request {
        module,
        resets: args.reset.clone(),
        dry_run: args.dry_run,
        info: false,
    };
    let answer = ask(&stream, &request)?;
    match answer.outcome {
        Outcome::Done => {
            print!("{}", answer.text);
            Ok(())
        }
        Outcome::Refused => Err(answer.text.into()),
        Outcome::SwappedBack => {
            let (report, why) = answer
                .text
                .rsplit_once("swapped back: ")
                .unwrap_or(("", &answer.text));
            print!("{report}");
            Err(format!("swapped back: {why}").into())
        }
    }
}

/// A dry run against a program `plc run` does not host: the two descriptors, here.
fn plan_here(seg: &DynSegment, module: &Path, args: &ChangeArgs) -> Result<(), Error> {
    let info = Module::inspect(module, &Trial::this_program()?)?;
    let plan = ChangePlan::new(
        seg.descriptor(),
        &info.descriptor,
        &args.reset,
        Direction::Forward,
    )
    .map_err(|refused| refused_plan(module, &refused))?;
    let head = head(&args.segment, &info.name, module, &info.fingerprint, true);
    print!("{}", report(&head, &plan));
    Ok(())
}
