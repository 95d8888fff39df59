//! Loads a sealed module into this process and checks its entry: the same checks in the trial
//! child and in the host. Every byte the module reports is read through a bounded length, and
//! the descriptor is checked as a tool checks one from a segment: the module is code of the
//! host's own user, but a damaged one must cost a refusal, not the machine.

use super::error::ModuleError;
use crate::abi::{ABI_VERSION, ENTRY_SYMBOL, EntryFn, ModuleBytes, ProgramEntry};
use crate::fingerprint::Fingerprint;
use plc_shm::LayoutDescriptor;
use std::ffi::{CStr, CString};
use std::path::Path;

/// The most bytes of a name, a fingerprint, a descriptor and a bus description.
const MAX_NAME: usize = 256;
const MAX_FINGERPRINT: usize = 4096;
const MAX_DESCRIPTOR: usize = 64 << 20;
const MAX_BUS: usize = 16 << 20;
/// The largest image a module may declare (the segment's own bound).
const MAX_IMAGE: u64 = 256 << 20;

/// A loaded module's entry and what it says of itself, checked.
#[derive(Debug)]
pub struct Checked {
    /// The table, in the module, which is never unloaded.
    pub entry: &'static ProgramEntry,
    /// The crate's name.
    pub name: String,
    /// What built it (the host's own fingerprint: it was checked to be).
    pub fingerprint: String,
    /// The descriptor of its variables.
    pub descriptor: LayoutDescriptor,
    /// The bus description it was compiled against: file name and text.
    pub bus: Option<(String, String)>,
}

/// Loads the library at `load_path` (a sealed copy of `path`) into this process for good:
/// a module is never unloaded, since its code may run until the process ends.
pub fn open(path: &Path, load_path: &str) -> Result<&'static ProgramEntry, ModuleError> {
    let c_path =
        CString::new(load_path).map_err(|_| ModuleError::NotAFile { path: path.into() })?;
    // SAFETY: a valid C string. The module's constructors run here: it is code of the host's
    // own user, which only that user can write (checked before).
    let handle = unsafe { libc::dlopen(c_path.as_ptr(), libc::RTLD_NOW | libc::RTLD_LOCAL) };
    if handle.is_null() {
        return Err(ModuleError::NotALibrary {
            path: path.into(),
            why: format!("the dynamic loader refused it: {}", last_dl_error()),
        });
    }
    let symbol = |name: &[u8]| {
        // SAFETY: a NUL-terminated name and a live handle.
        unsafe { libc::dlsym(handle, name.as_ptr().cast()) }
    };
    let found = symbol(ENTRY_SYMBOL);
    if found.is_null() {
        let later = (2..10).find(|v| !symbol(format!("plc_program_v{v}\0").as_bytes()).is_null());
        let why = match later {
            Some(v) => format!(
                "it exports `plc_program_v{v}`, a later version of the entry than this host's \
                 `plc_program_v{ABI_VERSION}`: run it with the plc-vars it was built with"
            ),
            None => format!("it exports no `plc_program_v{ABI_VERSION}`"),
        };
        return Err(ModuleError::NotAProgram {
            path: path.into(),
            why,
        });
    }
    // SAFETY: the symbol `program!` defines has this type; a library that defines the name
    // with another type is code of the host's own user (as above).
    let entry_fn: EntryFn = unsafe { std::mem::transmute::<*mut libc::c_void, EntryFn>(found) };
    // SAFETY: as above; the entry catches its own panics.
    let table = unsafe { entry_fn() };
    // SAFETY: `program!` returns null or a pointer to a static that lives while the module
    // is loaded, which is for good.
    match unsafe { table.as_ref() } {
        Some(table) => Ok(table),
        None => Err(ModuleError::NotAProgram {
            path: path.into(),
            why: "its entry could not build its table (it panicked)".into(),
        }),
    }
}

/// Checks the table `entry` of module `path` against this host.
pub fn check(path: &Path, entry: &'static ProgramEntry) -> Result<Checked, ModuleError> {
    let bad = |why: String| ModuleError::NotAProgram {
        path: path.into(),
        why,
    };
    if entry.abi_version != ABI_VERSION {
        return Err(bad(format!(
            "its entry says version {}, its name version {ABI_VERSION}",
            entry.abi_version
        )));
    }
    let text = |what: &str, b: ModuleBytes, max: usize| -> Result<String, ModuleError> {
        let bytes = bytes_of(b, max).ok_or_else(|| bad(format!("its {what} is not readable")))?;
        String::from_utf8(bytes.to_vec()).map_err(|_| bad(format!("its {what} is not UTF-8")))
    };
    let fingerprint = text("fingerprint", entry.fingerprint, MAX_FINGERPRINT)?;
    if let Some(why) = Fingerprint::from_text(&fingerprint).mismatch(&Fingerprint::host()) {
        return Err(ModuleError::Fingerprint {
            path: path.into(),
            why,
        });
    }
    let name = text("name", entry.name, MAX_NAME)?;
    let json = bytes_of(entry.descriptor, MAX_DESCRIPTOR)
        .ok_or_else(|| bad("its descriptor is not readable".into()))?;
    let descriptor: LayoutDescriptor = serde_json::from_slice(json)
        .map_err(|e| bad(format!("its descriptor is not valid: {e}")))?;
    descriptor
        .check_variables()
        .map_err(|e| bad(format!("its descriptor is not valid: {e}")))?;
    let computed = descriptor.computed_hash();
    if descriptor.format_version != plc_rules::layout::FORMAT_VERSION
        || computed != descriptor.layout_hash
        || computed != entry.layout_hash
    {
        return Err(bad(format!(
            "its descriptor (format {}, layout hash {:#018x}) does not match its variables' \
             hash {computed:#018x} and this host's format {}",
            descriptor.format_version,
            entry.layout_hash,
            plc_rules::layout::FORMAT_VERSION
        )));
    }
    if entry.image_size != descriptor.image_size as u64 || entry.image_size > MAX_IMAGE {
        return Err(bad(format!(
            "its image has {} bytes where its descriptor says {} (at most {MAX_IMAGE})",
            entry.image_size, descriptor.image_size
        )));
    }
    let bus_text = text("bus description", entry.bus, MAX_BUS)?;
    let bus = match bus_text.split_once('\0') {
        Some((file, text)) => Some((file.to_string(), text.to_string())),
        None if bus_text.is_empty() => None,
        None => return Err(bad("its bus description has no file name".into())),
    };
    Ok(Checked {
        entry,
        name,
        fingerprint,
        descriptor,
        bus,
    })
}

/// The bytes `b` points to, if they are at most `max` and the pointer is not null.
fn bytes_of(b: ModuleBytes, max: usize) -> Option<&'static [u8]> {
    if b.len > max || (b.ptr.is_null() && b.len > 0) {
        return None;
    }
    if b.len == 0 {
        return Some(&[]);
    }
    // SAFETY: the module's static bytes, which stay loaded (see `open`).
    Some(unsafe { std::slice::from_raw_parts(b.ptr, b.len) })
}

/// The dynamic loader's last error message.
fn last_dl_error() -> String {
    // SAFETY: dlerror returns null or a NUL-terminated message owned by the loader.
    let msg = unsafe { libc::dlerror() };
    if msg.is_null() {
        "no reason given".into()
    } else {
        // SAFETY: as above; copied out at once.
        unsafe { CStr::from_ptr(msg) }
            .to_string_lossy()
            .into_owned()
    }
}
