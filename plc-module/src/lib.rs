//! A plc-vars program as a loadable module, so that a new build can take over a running
//! machine between two cycles (an online change).
//!
//! - The module's side: [`program!`] in a `cdylib` crate exports one versioned C entry
//!   ([`abi`]): the program's descriptor, layout hash, fingerprint and the entry points a host
//!   calls on the image (initial image, unpack bits, tick, pack bits), each catching a panic.
//! - The host's side: [`Module::load`] opens a module file without following links, checks
//!   who owns it and who may write it, checks it is a shared library whose loadable segments
//!   lie inside the file, copies it into a sealed memory file, tries it in a short-lived child
//!   ([`trial`]) and only then loads it into the host.
//!
//! A program's state is its image: the variables of its `GlobalMemory`, with their structures,
//! function block instances and axes. Anything a program keeps outside the image (a `static`,
//! a `thread_local!`) starts afresh in each module it is built into: after a change it is the
//! new module's.
//!
//! ```ignore
//! // src/lib.rs of a crate with `crate-type = ["cdylib"]`:
//! use plc_io::{Context, GlobalMemory};
//!
//! #[derive(GlobalMemory, Debug, Clone)]
//! pub struct Gm {
//!     #[plc(direction = "input")]
//!     start: bool,
//!     #[plc(direction = "output")]
//!     motor_on: bool,
//! }
//!
//! fn tick(ctx: &mut Context<Gm>) {
//!     ctx.gm.motor_on = ctx.gm.start;
//! }
//!
//! plc_io::program!(Gm, tick);
//! ```
#![deny(missing_docs)]

pub mod abi;
#[doc(hidden)]
pub mod export;
mod fingerprint;
mod host;
mod load;

pub use fingerprint::Fingerprint;
pub use host::change::{AtChange, Prepared, prepare, prepare_back};
pub use host::memory::ModuleMemory;
pub use host::tick::{facts, tick};
pub use load::error::ModuleError;
pub use load::info::ModuleInfo;
pub use load::module::{Module, ModuleFault};

/// Makes this `cdylib` crate a program module: `program!(Gm, tick)` with
/// `fn tick(ctx: &mut Context<Gm>)`, where `Gm` is the program's `#[derive(GlobalMemory)]`
/// struct. It exports the entry [`abi::ENTRY_SYMBOL`] that hosts (`plc run`) look for.
///
/// The tick's `Context` carries the cycle's facts from the host (cycle number, time, bus
/// state, statistics); its alarms are the host's to evaluate and are empty here.
#[macro_export]
macro_rules! program {
    ($gm:ty, $tick:expr) => {
        const _: () = {
            use $crate::abi::{CycleFacts, PanicText, ProgramEntry};

            unsafe extern "C" fn __plc_initial_image(
                image: *mut u8,
                len: usize,
                panic: *mut PanicText,
            ) -> i32 {
                // SAFETY: the host's promise (see `plc_module::abi`).
                unsafe { $crate::export::initial_image::<$gm>(image, len, panic) }
            }
            unsafe extern "C" fn __plc_unpack_bits(
                image: *mut u8,
                len: usize,
                panic: *mut PanicText,
            ) -> i32 {
                // SAFETY: the host's promise.
                unsafe { $crate::export::bits::<$gm>(image, len, panic, true) }
            }
            unsafe extern "C" fn __plc_pack_bits(
                image: *mut u8,
                len: usize,
                panic: *mut PanicText,
            ) -> i32 {
                // SAFETY: the host's promise.
                unsafe { $crate::export::bits::<$gm>(image, len, panic, false) }
            }
            unsafe extern "C" fn __plc_tick(
                image: *mut u8,
                len: usize,
                facts: *const CycleFacts,
                panic: *mut PanicText,
            ) -> i32 {
                let program: fn(&mut $crate::__Context<$gm>) = $tick;
                // SAFETY: the host's promise.
                unsafe { $crate::export::tick::<$gm>(image, len, facts, panic, program) }
            }

            static __PLC_BUILT: ::std::sync::OnceLock<$crate::export::Built> =
                ::std::sync::OnceLock::new();

            #[unsafe(no_mangle)]
            pub extern "C" fn plc_program_v1() -> *const ProgramEntry {
                $crate::export::entry_of(|| {
                    __PLC_BUILT
                        .get_or_init(|| {
                            $crate::export::Built::new::<$gm>(
                                ::core::env!("CARGO_PKG_NAME"),
                                ::core::cfg!(panic = "unwind"),
                                $crate::export::EntryPoints {
                                    initial_image: __plc_initial_image,
                                    unpack_bits: __plc_unpack_bits,
                                    tick: __plc_tick,
                                    pack_bits: __plc_pack_bits,
                                },
                            )
                        })
                        .entry()
                })
            }
        };
    };
}

#[doc(hidden)]
pub use plc_runtime::Context as __Context;

/// The trial load: a module is tried in a short-lived child (this program run again) before a
/// host trusts it. A program that loads modules calls [`serve_if_asked`](trial::serve_if_asked)
/// first thing in `main`.
pub mod trial {
    pub use crate::load::trial::{TRIAL_ARG, Trial};
    pub use crate::load::trial_child::serve_if_asked;
}
