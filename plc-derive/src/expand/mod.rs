//! Code generation, split by concern. Everything goes into one `const _: () = { ... };` so no
//! helper name reaches the user's namespace, and every path is fully qualified through
//! `plc_core::__private` so the code works under `#![no_implicit_prelude]`.

mod access;
mod asserts;
mod bits;
mod default;
mod fallback;
mod image;
mod located;
mod metadata;

use crate::ast::{self, Container, Var};
use crate::check;
use crate::ctxt::Ctxt;
use proc_macro2::TokenStream;
use quote::quote;
use syn::DeriveInput;

/// Name of the image struct inside the `const _` block. It shadows nothing the user can see
/// outside the block, and is unusual enough not to shadow a type the fields name.
pub const IMAGE: &str = "__PlcVarsImage";

pub fn derive(input: &DeriveInput) -> TokenStream {
    let mut cx = Ctxt::default();
    let Some(mut c) = ast::parse(input, &mut cx) else {
        return cx.into_tokens();
    };
    check::check(&mut c, &mut cx);
    // Type-dependent checks run whatever else failed, so all mistakes show at once.
    let asserts = asserts::expand(&c);
    if cx.has_errors() {
        let fallback = if input.generics.params.is_empty() {
            fallback::expand(&c)
        } else {
            TokenStream::new()
        };
        let errors = cx.into_tokens();
        return quote! {
            #errors
            const _: () = { #asserts #fallback };
        };
    }
    let body = [
        image::expand(&c),
        metadata::expand(&c),
        bits::expand(&c),
        access::expand(&c),
        located::expand(&c),
    ];
    let ident = c.ident;
    let krate = &c.krate;
    let image_ident = image_ident();
    let default = default::expand(&c);
    let image_struct = image::image_struct(&c);
    quote! {
        const _: () = {
            #image_struct
            #asserts

            #[automatically_derived]
            impl #krate::GlobalMemory for #ident {
                type Image = #image_ident;
                #(#body)*
            }

            #default
        };
    }
}

/// `<krate>::__private`.
pub fn private(c: &Container) -> TokenStream {
    let krate = &c.krate;
    quote!(#krate::__private)
}

pub fn image_ident() -> syn::Ident {
    syn::Ident::new(IMAGE, proc_macro2::Span::call_site())
}

/// The bools mapped onto source `s`, with their bits.
pub fn mapped_onto<'c, 'a>(
    c: &'c Container<'a>,
    s: usize,
) -> impl Iterator<Item = (&'c Var<'a>, u8)> {
    c.vars.iter().filter_map(move |v| {
        v.mapped_to
            .filter(|(src, _)| *src == s)
            .map(|(_, b)| (v, b))
    })
}
