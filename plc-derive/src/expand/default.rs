//! `Default` from the `initial` values: zero, then each variable's initial, then the bits of
//! source words reach their bools, then the bools' own initials, then everything is packed (so
//! a bool's initial wins for its bit).

use super::private;
use crate::ast::Container;
use crate::expand::metadata::iec_type;
use crate::types::SynType;
use proc_macro2::TokenStream;
use quote::quote;

/// The initial values onto `gm` (a `&mut` or a binding of the struct, members zeroed or
/// already initialised): each variable's, then the source words' bits reach their bools
/// (`unpack`), then the bools' own initials, then `pack` (so a bool's initial wins for its bit).
pub fn initials(c: &Container, unpack: TokenStream, pack: TokenStream) -> TokenStream {
    let p = private(c);
    let krate = &c.krate;
    let set = |mapped: bool| -> Vec<TokenStream> {
        c.fields()
            .filter(|(v, _)| v.mapped_to.is_some() == mapped)
            .filter_map(|(v, m)| {
                let init = v.initial.as_ref()?;
                let field = v.ident;
                let iec = iec_type(c, v, m);
                let value = init.value_tokens(krate);
                Some(quote!(#p::set_initial(&mut gm.#field, #iec, #value);))
            })
            .collect()
    };
    let plain = set(false);
    let mapped = set(true);
    quote! {
        #(#plain)*
        #unpack
        #(#mapped)*
        #pack
    }
}

pub fn expand(c: &Container, bounds: &TokenStream) -> TokenStream {
    let p = private(c);
    let krate = &c.krate;
    let ident = c.ident;
    // Structures among the fields (only the compiler knows which) set their members' initials
    // first; for basic types the call is empty.
    let nested = c
        .vars
        .iter()
        .filter(|v| v.syn_type == SynType::Unknown)
        .map(|v| {
            let (field, ty) = (v.ident, v.ty);
            quote!(<#ty as #p::PlcType>::__init(&mut gm.#field);)
        });
    let initials = initials(
        c,
        quote!(<Self as #krate::GlobalMemory>::unpack_bits(&mut gm);),
        quote!(<Self as #krate::GlobalMemory>::pack_bits(&mut gm);),
    );
    quote! {
        #[automatically_derived]
        impl ::core::default::Default for #ident #bounds {
            fn default() -> Self {
                let mut gm = Self::__PLC_ZERO;
                #(#nested)*
                #initials
                gm
            }
        }
    }
}
