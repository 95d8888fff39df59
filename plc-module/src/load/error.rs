//! Why a module was refused: each names the file, what is wrong and what to do. A refused
//! module was never loaded into the host, or, for the last checks, loaded and never run.

use std::fmt;
use std::path::PathBuf;

/// Why [`Module::load`](crate::Module::load) refused a module file.
#[derive(Debug)]
#[non_exhaustive]
pub enum ModuleError {
    /// It could not be opened or read.
    Io {
        /// The file.
        path: PathBuf,
        /// What failed.
        doing: &'static str,
        /// The system's error.
        error: std::io::Error,
    },
    /// It is a symbolic link (never followed: whoever may change the link would choose the code).
    Link {
        /// The link.
        path: PathBuf,
    },
    /// It is not a regular file.
    NotAFile {
        /// The path.
        path: PathBuf,
    },
    /// It belongs to another user.
    Owner {
        /// The file.
        path: PathBuf,
        /// Its owner.
        owner: u32,
        /// The host's user.
        host: u32,
    },
    /// Someone besides its owner may write it.
    Writable {
        /// The file.
        path: PathBuf,
        /// `group` or `others`.
        who: &'static str,
    },
    /// It is larger than a module may be.
    TooLarge {
        /// The file.
        path: PathBuf,
        /// Its size.
        size: u64,
        /// The most a module may have.
        max: u64,
    },
    /// It is not a shared library for this machine.
    NotALibrary {
        /// The file.
        path: PathBuf,
        /// What it is or lacks.
        why: String,
    },
    /// It is a shared library with a part that lies outside the file, as a truncated copy has.
    Damaged {
        /// The file.
        path: PathBuf,
        /// Where.
        why: String,
    },
    /// It is a shared library but no plc-vars program.
    NotAProgram {
        /// The file.
        path: PathBuf,
        /// What is missing or wrong in its entry.
        why: String,
    },
    /// It was built with another compiler, target, plc-vars or panic strategy.
    Fingerprint {
        /// The file.
        path: PathBuf,
        /// Both fingerprints and the fix.
        why: String,
    },
    /// Trying it in a child process failed: the child crashed, hung or refused it.
    Trial {
        /// The file.
        path: PathBuf,
        /// What happened.
        why: String,
    },
    /// The memory file to load it from could not be made (`memfd_create`, its seals).
    MemoryFile {
        /// The file.
        path: PathBuf,
        /// The system's error.
        error: std::io::Error,
    },
}

impl fmt::Display for ModuleError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use ModuleError::*;
        match self {
            Io { path, doing, error } => {
                write!(f, "module `{}`: cannot {doing}: {error}", path.display())
            }
            Link { path } => write!(
                f,
                "module `{}` is a symbolic link, which is never followed (whoever can change \
                 the link would choose the code that runs): give the file it points to",
                path.display()
            ),
            NotAFile { path } => write!(
                f,
                "module `{}` is not a regular file: give the `lib<name>.so` that `cargo build` \
                 wrote",
                path.display()
            ),
            Owner { path, owner, host } => write!(
                f,
                "module `{}` belongs to uid {owner}, not to uid {host} who runs the program: \
                 only the program's own user may give it code; copy it and own the copy",
                path.display()
            ),
            Writable { path, who } => write!(
                f,
                "module `{}` is writable by {who}: whoever may write it could change the code \
                 the machine runs; run `chmod go-w {}`",
                path.display(),
                path.display()
            ),
            TooLarge { path, size, max } => write!(
                f,
                "module `{}` has {size} bytes, more than the {max} a module may have",
                path.display()
            ),
            NotALibrary { path, why } => write!(
                f,
                "`{}` is not a program module: {why}; build the program's crate with \
                 `crate-type = [\"cdylib\"]` and give its `target/release/lib<name>.so`",
                path.display()
            ),
            Damaged { path, why } => write!(
                f,
                "module `{}` is damaged: {why}; the file is truncated or was written while \
                 being copied: build it again",
                path.display()
            ),
            NotAProgram { path, why } => write!(
                f,
                "`{}` is a shared library but not a plc-vars program: {why}; its crate needs \
                 `plc_io::program!(Gm, tick);`",
                path.display()
            ),
            Fingerprint { path, why } => {
                write!(f, "module `{}` cannot run here: {why}", path.display())
            }
            Trial { path, why } => write!(
                f,
                "module `{}` failed its trial load in a child process: {why}; the running \
                 program is untouched",
                path.display()
            ),
            MemoryFile { path, error } => write!(
                f,
                "module `{}`: cannot make the sealed memory file to load it from: {error}",
                path.display()
            ),
        }
    }
}

impl std::error::Error for ModuleError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            ModuleError::Io { error, .. } | ModuleError::MemoryFile { error, .. } => Some(error),
            _ => None,
        }
    }
}
