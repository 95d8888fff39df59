//! A loaded, checked module, and the calls a host makes on it over image bytes.

use super::error::ModuleError;
use super::info::ModuleInfo;
use super::library::{self, Checked};
use super::sealed::SealedCopy;
use super::trial::Trial;
use super::{elf, file};
use crate::abi::{CycleFacts, ImageFn, PanicText, status};
use plc_shm::LayoutDescriptor;
use std::fmt;
use std::path::{Path, PathBuf};

/// The most bytes of a panic's message a host keeps.
const PANIC_TEXT_BYTES: usize = 1024;

/// Why a call into a module did not complete. The image is as it was before the call.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ModuleFault {
    /// The program panicked with this message.
    Panicked(String),
    /// The image given is not the module's size.
    WrongImage {
        /// The module's image size.
        expected: usize,
        /// The size given.
        got: usize,
    },
}

impl fmt::Display for ModuleFault {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ModuleFault::Panicked(message) => write!(f, "the program panicked: {message}"),
            ModuleFault::WrongImage { expected, got } => write!(
                f,
                "an image of {got} bytes was given to a module whose image has {expected}"
            ),
        }
    }
}

impl std::error::Error for ModuleFault {}

/// A program module loaded into this process: its descriptor and the calls that run it over
/// an image. It is never unloaded (its code may run until the process ends): each load costs
/// the module's size in memory for good, which a host pays once per online change.
///
/// ```no_run
/// use plc_module::{Module, abi::CycleFacts, trial::Trial};
///
/// let module = Module::load("target/release/libconveyor.so", &Trial::this_program()?)?;
/// let mut image = module.initial_image()?;
/// module.unpack_bits(&mut image)?;
/// module.tick(&mut image, &CycleFacts { cycle: 1, ..CycleFacts::default() })?;
/// module.pack_bits(&mut image)?;
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug)]
pub struct Module {
    path: PathBuf,
    checked: Checked,
}

impl Module {
    /// Loads the module file at `path`, after checking the file (owner, writers, no link),
    /// its ELF headers, and trying it in a child process started by `trial`.
    pub fn load(path: impl AsRef<Path>, trial: &Trial) -> Result<Module, ModuleError> {
        let path = path.as_ref();
        let sealed = Module::checked_copy(path)?;
        trial.run(path, &sealed)?;
        let entry = library::open(path, &sealed.proc_path())?;
        // The memory file stays open for good: closing it would free its number, and the
        // loader would answer a later module at the same `/proc/self/fd/N` with this one.
        std::mem::forget(sealed);
        Ok(Module {
            path: path.into(),
            checked: library::check(path, entry)?,
        })
    }

    /// What the module file at `path` says of itself, with every check of [`load`](Self::load)
    /// but none of its code run in this process: only the trial child loads it. For a tool that
    /// plans a change (`plc change --dry-run`).
    pub fn inspect(path: impl AsRef<Path>, trial: &Trial) -> Result<ModuleInfo, ModuleError> {
        let path = path.as_ref();
        let sealed = Module::checked_copy(path)?;
        trial.run(path, &sealed)
    }

    /// The file's checks, then its bytes in a sealed memory file.
    fn checked_copy(path: &Path) -> Result<SealedCopy, ModuleError> {
        let bytes = file::read_checked(path)?;
        elf::check(&bytes).map_err(|issue| match issue {
            elf::ElfIssue::NotALibrary(why) => ModuleError::NotALibrary {
                path: path.into(),
                why,
            },
            elf::ElfIssue::Damaged(why) => ModuleError::Damaged {
                path: path.into(),
                why,
            },
        })?;
        let label = path
            .file_name()
            .map_or("module".into(), |n| n.to_string_lossy());
        SealedCopy::new(&label, &bytes).map_err(|error| ModuleError::MemoryFile {
            path: path.into(),
            error,
        })
    }

    /// A module a trial child loaded from its inherited descriptor.
    pub(crate) fn in_trial(path: &Path, load_path: &str) -> Result<Module, ModuleError> {
        let entry = library::open(path, load_path)?;
        Ok(Module {
            path: path.into(),
            checked: library::check(path, entry)?,
        })
    }

    /// What it says of itself.
    pub fn info(&self) -> ModuleInfo {
        ModuleInfo {
            name: self.checked.name.clone(),
            fingerprint: self.checked.fingerprint.clone(),
            descriptor: self.checked.descriptor.clone(),
            bus: self.checked.bus.clone(),
        }
    }

    /// The file it was loaded from.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The program crate's name.
    pub fn name(&self) -> &str {
        &self.checked.name
    }

    /// Its variables, as its segment publishes them.
    pub fn descriptor(&self) -> &LayoutDescriptor {
        &self.checked.descriptor
    }

    /// The layout hash of its variables.
    pub fn layout_hash(&self) -> u64 {
        self.checked.entry.layout_hash
    }

    /// The size of its image in bytes.
    pub fn image_size(&self) -> usize {
        self.checked.descriptor.image_size
    }

    /// The bus description it was compiled against (`#[plc(bus = ...)]`): the path as written
    /// and the text, if it names one.
    pub fn bus(&self) -> Option<(&str, &str)> {
        self.checked
            .bus
            .as_ref()
            .map(|(file, text)| (file.as_str(), text.as_str()))
    }

    /// The image of its initial values.
    pub fn initial_image(&self) -> Result<Vec<u8>, ModuleFault> {
        let mut image = vec![0; self.image_size()];
        self.image_call(self.checked.entry.initial_image, &mut image)?;
        Ok(image)
    }

    /// Copies each bit-mapped bool of `image` out of its source word (after the inputs).
    pub fn unpack_bits(&self, image: &mut [u8]) -> Result<(), ModuleFault> {
        self.image_call(self.checked.entry.unpack_bits, image)
    }

    /// Copies each bit-mapped bool of `image` into its source word (before the outputs).
    pub fn pack_bits(&self, image: &mut [u8]) -> Result<(), ModuleFault> {
        self.image_call(self.checked.entry.pack_bits, image)
    }

    /// Runs the program's tick over `image` in the cycle `facts` describes. After a panic
    /// `image` is as it was.
    pub fn tick(&self, image: &mut [u8], facts: &CycleFacts) -> Result<(), ModuleFault> {
        let tick = self.checked.entry.tick;
        self.call(image, |image, panic| {
            // SAFETY: an image of the module's size that we hold exclusively, the facts and
            // a panic buffer that outlive the call.
            unsafe { tick(image.as_mut_ptr(), image.len(), facts, panic) }
        })
    }

    fn image_call(&self, f: ImageFn, image: &mut [u8]) -> Result<(), ModuleFault> {
        self.call(image, |image, panic| {
            // SAFETY: as in `tick`.
            unsafe { f(image.as_mut_ptr(), image.len(), panic) }
        })
    }

    fn call(
        &self,
        image: &mut [u8],
        f: impl FnOnce(&mut [u8], *mut PanicText) -> i32,
    ) -> Result<(), ModuleFault> {
        let expected = self.image_size();
        if image.len() != expected {
            return Err(ModuleFault::WrongImage {
                expected,
                got: image.len(),
            });
        }
        let mut buf = [0u8; PANIC_TEXT_BYTES];
        let mut panic = PanicText {
            ptr: buf.as_mut_ptr(),
            cap: buf.len(),
            len: 0,
        };
        match f(image, &mut panic) {
            status::OK => Ok(()),
            status::PANICKED => {
                let len = panic.len.min(buf.len());
                Err(ModuleFault::Panicked(
                    String::from_utf8_lossy(&buf[..len]).into_owned(),
                ))
            }
            _ => Err(ModuleFault::WrongImage {
                expected,
                got: image.len(),
            }),
        }
    }
}
