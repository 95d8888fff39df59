//! `#[derive(GlobalMemory)]`: placeholder until the derive lands.
use proc_macro::TokenStream;

/// Derives `plc_core::GlobalMemory`.
#[proc_macro_derive(GlobalMemory, attributes(plc))]
pub fn derive_global_memory(_input: TokenStream) -> TokenStream {
    TokenStream::new()
}
