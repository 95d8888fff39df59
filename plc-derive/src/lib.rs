//! `#[derive(GlobalMemory)]` for plc-vars: turns a struct of PLC variables into a fixed
//! shared-memory layout with bit packing, metadata and compile-time checked declarations;
//! `#[derive(PlcStruct)]` declares the structure types its fields may have.
//!
//! Use it through `plc_core`, which re-exports it; see `plc_core::GlobalMemory` and the crate
//! README for the `#[plc(...)]` attribute reference.
#![deny(missing_docs)]

#[cfg(test)]
mod agreement;
mod alarm;
mod ast;
mod attr;
mod bus;
mod check;
mod ctxt;
mod expand;
mod initial;
mod kind;
mod loc;
mod raw_value;
mod symbol;
mod types;

use proc_macro::TokenStream;

/// Implements `plc_core::GlobalMemory` (and `Default`, from the `initial` values) for a struct
/// with named fields. Every mistake in the `#[plc(...)]` attributes is a compile error under the
/// offending token, all of a struct's mistakes at once.
#[proc_macro_derive(GlobalMemory, attributes(plc))]
pub fn derive_global_memory(input: TokenStream) -> TokenStream {
    let input = syn::parse_macro_input!(input as syn::DeriveInput);
    expand::derive(&input, ast::Kind::GlobalMemory).into()
}

/// Implements `plc_core::PlcType` (and `Default`, from the members' `initial` values) for a
/// structure type with named fields, so that it can be the type of a `GlobalMemory` field or of
/// another structure's, alone or in arrays. Its members take the field keys of `GlobalMemory`
/// but `link` and `at` (physical I/O is declared at the top level); `direction = "input"` or
/// `"output"` marks an IN or OUT parameter. `#[plc(name = "...")]` on the struct sets the type
/// name tools show (default: the struct's name).
#[proc_macro_derive(PlcStruct, attributes(plc))]
pub fn derive_plc_struct(input: TokenStream) -> TokenStream {
    let input = syn::parse_macro_input!(input as syn::DeriveInput);
    expand::derive(&input, ast::Kind::PlcStruct).into()
}
