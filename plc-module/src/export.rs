//! The module's side of the entry: what [`program!`](crate::program) expands to calls these.
//! Each entry point checks the image's size, works on a copy of the program's variables made
//! from the image, and writes them back only when the program's code returned: a panic leaves
//! the image as it was, is caught here (one unwinding out of `extern "C"` would abort the
//! host) and its message handed to the host.

use crate::abi::{
    ABI_VERSION, CycleFacts, ImageFn, ModuleBytes, PanicText, ProgramEntry, TickFn, status,
};
use crate::fingerprint::Fingerprint;
use plc_core::{GlobalMemory, Time};
use plc_runtime::{BusState, Context};
use std::any::Any;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::time::Duration;
use zerocopy::FromBytes;

/// The entry points `program!` generates for one program, to put in its table.
#[derive(Clone, Copy, Debug)]
pub struct EntryPoints {
    /// See [`ProgramEntry::initial_image`].
    pub initial_image: ImageFn,
    /// See [`ProgramEntry::unpack_bits`].
    pub unpack_bits: ImageFn,
    /// See [`ProgramEntry::tick`].
    pub tick: TickFn,
    /// See [`ProgramEntry::pack_bits`].
    pub pack_bits: ImageFn,
}

/// The module's table and the bytes it points into, made once on the host's first call.
#[derive(Debug)]
pub struct Built {
    _name: String,
    _fingerprint: String,
    _descriptor: Vec<u8>,
    _bus: Vec<u8>,
    entry: ProgramEntry,
}

// SAFETY: immutable once built; the pointers in `entry` point into the owned buffers beside it,
// which live as long as the static that holds this.
unsafe impl Send for Built {}
unsafe impl Sync for Built {}

impl Built {
    /// The table of program `T`, built by crate `name` whose panics unwind or not.
    pub fn new<T: GlobalMemory>(name: &str, panic_unwinds: bool, points: EntryPoints) -> Built {
        let name = name.to_string();
        let fingerprint = Fingerprint::of_build(panic_unwinds).text().to_string();
        let descriptor = serde_json::to_vec(&plc_shm::LayoutDescriptor::of::<T>())
            .expect("a descriptor is plain data and always serialises");
        let bus = match T::BUS {
            Some(bus) => [bus.file.as_bytes(), &[0], bus.text.as_bytes()].concat(),
            None => Vec::new(),
        };
        let bytes = |b: &[u8]| ModuleBytes {
            ptr: b.as_ptr(),
            len: b.len(),
        };
        let entry = ProgramEntry {
            abi_version: ABI_VERSION,
            name: bytes(name.as_bytes()),
            fingerprint: bytes(fingerprint.as_bytes()),
            descriptor: bytes(&descriptor),
            bus: bytes(&bus),
            layout_hash: T::LAYOUT_HASH,
            image_size: size_of::<T::Image>() as u64,
            initial_image: points.initial_image,
            unpack_bits: points.unpack_bits,
            tick: points.tick,
            pack_bits: points.pack_bits,
        };
        Built {
            _name: name,
            _fingerprint: fingerprint,
            _descriptor: descriptor,
            _bus: bus,
            entry,
        }
    }

    /// The table.
    pub fn entry(&self) -> *const ProgramEntry {
        &self.entry
    }
}

/// The table, or null if building it panicked (the host then refuses the module).
pub fn entry_of(build: impl FnOnce() -> *const ProgramEntry) -> *const ProgramEntry {
    catch_unwind(AssertUnwindSafe(build)).unwrap_or(core::ptr::null())
}

/// The image `len` bytes at `image`, if that is `T`'s size.
///
/// # Safety
/// `image` must point to `len` writable bytes that nothing else uses during the call.
unsafe fn image_of<'a, T: GlobalMemory>(image: *mut u8, len: usize) -> Option<&'a mut T::Image> {
    if image.is_null() || len != size_of::<T::Image>() {
        return None;
    }
    // SAFETY: the caller's promise; `Image` is unaligned plain bytes of this size.
    let bytes = unsafe { core::slice::from_raw_parts_mut(image, len) };
    T::Image::mut_from_bytes(bytes).ok()
}

/// Runs `work` over the image, catching a panic into `panic`.
///
/// # Safety
/// As `image_of`; `panic` is null or points to a [`PanicText`] whose buffer has `cap`
/// writable bytes.
pub unsafe fn guarded<T: GlobalMemory>(
    image: *mut u8,
    len: usize,
    panic: *mut PanicText,
    work: impl FnOnce(&mut T::Image),
) -> i32 {
    // SAFETY: the caller's promise.
    let Some(image) = (unsafe { image_of::<T>(image, len) }) else {
        return status::WRONG_IMAGE;
    };
    match catch_unwind(AssertUnwindSafe(|| work(image))) {
        Ok(()) => status::OK,
        Err(payload) => {
            // SAFETY: the caller's promise.
            unsafe { report(panic, payload) };
            status::PANICKED
        }
    }
}

/// Writes the image of `T`'s initial values.
///
/// # Safety
/// As [`guarded`].
pub unsafe fn initial_image<T: GlobalMemory + Default>(
    image: *mut u8,
    len: usize,
    panic: *mut PanicText,
) -> i32 {
    // SAFETY: the caller's promise.
    unsafe { guarded::<T>(image, len, panic, |img| *img = T::default().to_image()) }
}

/// Unpacks (`unpack` true) or packs the image's bit-mapped bools.
///
/// # Safety
/// As [`guarded`].
pub unsafe fn bits<T: GlobalMemory>(
    image: *mut u8,
    len: usize,
    panic: *mut PanicText,
    unpack: bool,
) -> i32 {
    // SAFETY: the caller's promise.
    unsafe {
        guarded::<T>(image, len, panic, |img| {
            let mut gm = T::from_image(img);
            if unpack {
                gm.unpack_bits();
            } else {
                gm.pack_bits();
            }
            gm.store_image(img);
        })
    }
}

/// Runs `program` over the image in the cycle `facts` describes.
///
/// # Safety
/// As [`guarded`]; `facts` points to a [`CycleFacts`].
pub unsafe fn tick<T: GlobalMemory>(
    image: *mut u8,
    len: usize,
    facts: *const CycleFacts,
    panic: *mut PanicText,
    program: fn(&mut Context<T>),
) -> i32 {
    if facts.is_null() {
        return status::WRONG_IMAGE;
    }
    // SAFETY: the caller's promise.
    let facts = unsafe { *facts };
    // SAFETY: the caller's promise.
    unsafe {
        guarded::<T>(image, len, panic, |img| {
            let mut ctx = context(T::from_image(img), &facts);
            program(&mut ctx);
            ctx.gm.store_image(img);
        })
    }
}

/// The program's view of the cycle the host describes.
fn context<T>(gm: T, facts: &CycleFacts) -> Context<T> {
    let mut ctx = Context::for_test(gm);
    ctx.cycle = facts.cycle;
    ctx.inputs_valid = facts.inputs_valid != 0;
    ctx.bus_fault = facts.bus_fault != 0;
    ctx.bus_state = BusState::from_code(facts.bus_state.into());
    ctx.stats.period = Duration::from_nanos(facts.period_ns);
    ctx.stats.last = Duration::from_nanos(facts.last_ns);
    ctx.stats.max = Duration::from_nanos(facts.max_ns);
    ctx.stats.overruns = facts.overruns;
    ctx.set_now(Time::from_nanos(
        i64::try_from(facts.now_ns).unwrap_or(i64::MAX),
    ));
    ctx
}

/// Copies a panic's message into the host's buffer, cut to fit on a character boundary.
///
/// # Safety
/// `out` is null or a valid [`PanicText`].
unsafe fn report(out: *mut PanicText, payload: Box<dyn Any + Send>) {
    let text = payload
        .downcast_ref::<&str>()
        .copied()
        .or_else(|| payload.downcast_ref::<String>().map(String::as_str))
        .unwrap_or("a panic whose payload is not text");
    // SAFETY: the caller's promise.
    if let Some(out) = unsafe { out.as_mut() }
        && !out.ptr.is_null()
    {
        let mut n = text.len().min(out.cap);
        while !text.is_char_boundary(n) {
            n -= 1;
        }
        // SAFETY: `n` bytes fit the host's buffer, which is not the message's memory.
        unsafe { core::ptr::copy_nonoverlapping(text.as_ptr(), out.ptr, n) };
        out.len = n;
    }
    // A payload whose own drop panics must not unwind into the host either.
    if let Err(again) = catch_unwind(AssertUnwindSafe(move || drop(payload))) {
        core::mem::forget(again);
    }
}
