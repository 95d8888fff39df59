//! A module built as another toolchain's would be: the entry's table written out by hand with
//! the layout of version 1, and a fingerprint naming another compiler. A host must refuse it
//! before running any of its code but the entry.

#[repr(C)]
pub struct Bytes {
    ptr: *const u8,
    len: usize,
}

type ImageFn = unsafe extern "C" fn(*mut u8, usize, *mut u8) -> i32;
type TickFn = unsafe extern "C" fn(*mut u8, usize, *const u8, *mut u8) -> i32;

#[repr(C)]
pub struct Entry {
    abi_version: u32,
    name: Bytes,
    fingerprint: Bytes,
    descriptor: Bytes,
    bus: Bytes,
    layout_hash: u64,
    image_size: u64,
    initial_image: ImageFn,
    unpack_bits: ImageFn,
    tick: TickFn,
    pack_bits: ImageFn,
}

// SAFETY: immutable statics.
unsafe impl Sync for Entry {}

const fn bytes(b: &'static [u8]) -> Bytes {
    Bytes {
        ptr: b.as_ptr(),
        len: b.len(),
    }
}

unsafe extern "C" fn nothing(_: *mut u8, _: usize, _: *mut u8) -> i32 {
    0
}

unsafe extern "C" fn no_tick(_: *mut u8, _: usize, _: *const u8, _: *mut u8) -> i32 {
    0
}

static ENTRY: Entry = Entry {
    abi_version: 1,
    name: bytes(b"foreign"),
    fingerprint: bytes(
        b"plc-core 0.1.0, rustc 1.80.0 (051478957 2024-07-21), x86_64-unknown-linux-gnu, panic=unwind",
    ),
    descriptor: bytes(b"{}"),
    bus: bytes(b""),
    layout_hash: 0,
    image_size: 0,
    initial_image: nothing,
    unpack_bits: nothing,
    tick: no_tick,
    pack_bits: nothing,
};

/// The entry a host looks for.
#[unsafe(no_mangle)]
pub extern "C" fn plc_program_v1() -> *const Entry {
    &ENTRY
}
