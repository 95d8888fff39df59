//! What crosses between a module and its host: one exported function that returns a
//! `#[repr(C)]` table of bytes and entry points. Nothing else crosses: no Rust type, no
//! allocation, no unwinding. A module and its host each have their own copy of the standard
//! library and of plc-vars, so only plain bytes and C calls may pass between them.
//!
//! The symbol's name carries the ABI's version: a later, incompatible table is exported under
//! another name, and a host looks only for the one it knows.

/// The symbol every module exports (with its terminating NUL, as `dlsym` takes it).
pub const ENTRY_SYMBOL: &[u8] = b"plc_program_v1\0";

/// The table's own version, in its first field: `ENTRY_SYMBOL`'s number.
pub const ABI_VERSION: u32 = 1;

/// What an entry point returns.
pub mod status {
    /// Done.
    pub const OK: i32 = 0;
    /// The program panicked; the message is in the [`PanicText`](super::PanicText) buffer and
    /// the image is as it was before the call.
    pub const PANICKED: i32 = 1;
    /// The image given is not the module's size: nothing was done.
    pub const WRONG_IMAGE: i32 = 2;
}

/// Bytes that live in the module, valid as long as it is loaded (its host never unloads it).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct ModuleBytes {
    /// The first byte.
    pub ptr: *const u8,
    /// How many.
    pub len: usize,
}

// SAFETY: the bytes are immutable statics of a module that stays loaded.
unsafe impl Sync for ModuleBytes {}
unsafe impl Send for ModuleBytes {}

impl ModuleBytes {
    /// Bytes of a `'static` slice (the module's side).
    pub const fn of(bytes: &'static [u8]) -> ModuleBytes {
        ModuleBytes {
            ptr: bytes.as_ptr(),
            len: bytes.len(),
        }
    }
}

/// Where a module writes a panic's message (as much as fits, cut on a character boundary).
#[repr(C)]
#[derive(Debug)]
pub struct PanicText {
    /// The host's buffer.
    pub ptr: *mut u8,
    /// Its size.
    pub cap: usize,
    /// Bytes the module wrote.
    pub len: usize,
}

/// The facts of the cycle a tick runs in, from the host.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CycleFacts {
    /// Cycles started so far, this one included.
    pub cycle: u64,
    /// This cycle's start, in nanoseconds since the runtime started.
    pub now_ns: u64,
    /// The configured period, in nanoseconds.
    pub period_ns: u64,
    /// The last cycle's duration, in nanoseconds.
    pub last_ns: u64,
    /// The longest cycle so far, in nanoseconds.
    pub max_ns: u64,
    /// Cycles that did not finish within their period.
    pub overruns: u64,
    /// 1: the inputs are this cycle's.
    pub inputs_valid: u8,
    /// 1: the bus is not healthy.
    pub bus_fault: u8,
    /// The bus state's code (`plc_shm::BusState::code`).
    pub bus_state: u8,
    /// Zero.
    pub reserved: [u8; 5],
}

/// An entry point over the image: make the initial image, unpack bits, pack bits.
pub type ImageFn = unsafe extern "C" fn(image: *mut u8, len: usize, panic: *mut PanicText) -> i32;

/// The tick: the program's code over the image, in the cycle `facts` describes.
pub type TickFn = unsafe extern "C" fn(
    image: *mut u8,
    len: usize,
    facts: *const CycleFacts,
    panic: *mut PanicText,
) -> i32;

/// The table a module's [`ENTRY_SYMBOL`] returns: a `'static` in the module.
#[repr(C)]
#[derive(Debug)]
pub struct ProgramEntry {
    /// [`ABI_VERSION`].
    pub abi_version: u32,
    /// The crate's name (UTF-8).
    pub name: ModuleBytes,
    /// What built it (UTF-8): see [`Fingerprint`](crate::Fingerprint).
    pub fingerprint: ModuleBytes,
    /// The layout descriptor as JSON, the one its segment publishes.
    pub descriptor: ModuleBytes,
    /// The bus description the program was compiled against (`#[plc(bus = ...)]`): its file
    /// name, a NUL, then its text; empty when it names none.
    pub bus: ModuleBytes,
    /// The layout hash of its variables.
    pub layout_hash: u64,
    /// The image's size in bytes.
    pub image_size: u64,
    /// Writes the image of the initial values.
    pub initial_image: ImageFn,
    /// Copies each bit-mapped bool out of its source word.
    pub unpack_bits: ImageFn,
    /// Runs the program's tick over the image.
    pub tick: TickFn,
    /// Copies each bit-mapped bool into its source word.
    pub pack_bits: ImageFn,
}

// SAFETY: a table of immutable bytes and function pointers.
unsafe impl Sync for ProgramEntry {}

/// The type of [`ENTRY_SYMBOL`].
pub type EntryFn = unsafe extern "C" fn() -> *const ProgramEntry;
