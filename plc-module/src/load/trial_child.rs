//! The trial child's side: a program started with [`TRIAL_ARG`] loads the module from the
//! descriptor it inherited, checks it, makes its initial image, answers on its standard
//! output and exits.

use super::error::ModuleError;
use super::module::Module;
use super::trial::{CHILD_FD, MARK, TRIAL_ARG, to_wire};
use std::ffi::OsStr;
use std::io::{self, Write};
use std::path::{Path, PathBuf};

/// In a program that loads modules: if this process was started as a trial child, tries the
/// module and exits with the answer; otherwise returns at once.
///
/// ```no_run
/// // First thing in `main`:
/// plc_module::trial::serve_if_asked();
/// ```
pub fn serve_if_asked() {
    let mut args = std::env::args_os();
    if args.nth(1).as_deref() != Some(OsStr::new(TRIAL_ARG)) {
        return;
    }
    let path = PathBuf::from(args.next().unwrap_or_default());
    let answer = Module::in_trial(&path, &format!("/proc/self/fd/{CHILD_FD}")).and_then(|m| {
        let mut image = m.initial_image().map_err(|f| fault(&path, f))?;
        m.unpack_bits(&mut image).map_err(|f| fault(&path, f))?;
        m.pack_bits(&mut image).map_err(|f| fault(&path, f))?;
        Ok(m.info())
    });
    let line = match &answer {
        Ok(info) => match serde_json::to_string(info) {
            Ok(json) => format!("ok {json}"),
            Err(e) => format!("trial\tits description cannot be written: {e}"),
        },
        Err(e) => to_wire(e),
    };
    let mut stdout = io::stdout().lock();
    let _ = writeln!(stdout, "\n{MARK}{line}");
    let _ = stdout.flush();
    std::process::exit(if answer.is_ok() { 0 } else { 1 });
}

fn fault(path: &Path, fault: super::module::ModuleFault) -> ModuleError {
    ModuleError::Trial {
        path: path.into(),
        why: format!("making its initial image failed: {fault}"),
    }
}
