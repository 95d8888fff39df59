//! `Default` from the `initial` values: zero, then each variable's initial, then the bits of
//! source words reach their bools, then the bools' own initials, then everything is packed (so
//! a bool's initial wins for its bit).

use super::{image_ident, private};
use crate::ast::Container;
use crate::expand::metadata::iec_type;
use proc_macro2::TokenStream;
use quote::quote;

pub fn expand(c: &Container, bounds: &TokenStream) -> TokenStream {
    let p = private(c);
    let krate = &c.krate;
    let ident = c.ident;
    let image = image_ident();
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
        #[automatically_derived]
        impl ::core::default::Default for #ident #bounds {
            fn default() -> Self {
                let zeroed = <#image as #p::zerocopy::FromZeros>::new_zeroed();
                let mut gm = <Self as #krate::GlobalMemory>::from_image(&zeroed);
                #(#plain)*
                <Self as #krate::GlobalMemory>::unpack_bits(&mut gm);
                #(#mapped)*
                <Self as #krate::GlobalMemory>::pack_bits(&mut gm);
                gm
            }
        }
    }
}
