//! Code generation, split by concern. Everything goes into one `const _: () = { ... };` so no
//! helper name reaches the user's namespace, and every path is fully qualified through
//! `plc_core::__private` so the code works under `#![no_implicit_prelude]`.

mod access;
mod alarms;
mod asserts;
mod bits;
mod default;
mod fallback;
mod image;
mod located;
mod metadata;
mod places;
mod runs;
mod structure;

use crate::ast::{self, Container, Kind};
use crate::check;
use crate::ctxt::Ctxt;
use proc_macro2::TokenStream;
use quote::quote;
use syn::DeriveInput;

/// Name of the image struct inside the `const _` block. It shadows nothing the user can see
/// outside the block, and is unusual enough not to shadow a type the fields name.
pub const IMAGE: &str = "__PlcVarsImage";

pub fn derive(input: &DeriveInput, kind: Kind) -> TokenStream {
    let mut cx = Ctxt::default();
    let Some(mut c) = ast::parse(input, kind, &mut cx) else {
        return cx.into_tokens();
    };
    check::check(&mut c, &mut cx);
    let bus_file = crate::bus::check(&c, &mut cx);
    let tracked = crate::bus::track(bus_file.as_ref());
    let bus_const = crate::bus::constant(&c, bus_file.as_ref());
    // Type-dependent checks run whatever else failed, so all mistakes show at once.
    let asserts = asserts::expand(&c);
    if cx.has_errors() {
        let fallback = match (input.generics.params.is_empty(), kind) {
            (false, _) => TokenStream::new(),
            (true, Kind::GlobalMemory) => fallback::expand(&c),
            (true, Kind::PlcStruct) => fallback::expand_struct(&c),
        };
        let errors = cx.into_tokens();
        return quote! {
            #errors
            const _: () = { #tracked #asserts #fallback };
        };
    }
    let image_struct = image::image_struct(&c);
    let (alarm_items, alarm_assoc) = alarms::expand(&c);
    if kind == Kind::PlcStruct {
        let structure = structure::expand(&c, &alias_bounds(&c), &alarm_assoc);
        return quote! {
            const _: () = {
                #image_struct
                #asserts
                #alarm_items
                #structure
            };
        };
    }
    let bounds = alias_bounds(&c);
    let (access, access_chunks) = access::expand(&c);
    let zero = image::zero(&c);
    let hash_parts = metadata::hash_parts(&c);
    let body = [
        image::expand(&c),
        metadata::expand(&c),
        bits::expand(&c),
        access,
        located::expand(&c),
        places::expand(&c),
    ];
    let ident = c.ident;
    let krate = &c.krate;
    let image_ident = image_ident();
    let default = default::expand(&c, &bounds);
    let places_table = places::table(&c);
    quote! {
        const _: () = {
            #tracked
            #image_struct
            #asserts
            #alarm_items

            #[automatically_derived]
            impl #krate::GlobalMemory for #ident #bounds {
                type Image = #image_ident;
                #(#body)*
                #alarm_assoc
                #bus_const
            }

            #[automatically_derived]
            #[doc(hidden)]
            impl #ident #bounds {
                #zero
                #places_table
                #hash_parts
                #access_chunks
            }

            #default
        };
    }
}

/// `where for<'__plc> Alias: PlcType, ...` for the field types only the compiler knows, on
/// every generated item that names them. If such a type is not a `PlcType`, the one spanned
/// error comes from the type's `const` assertion (`asserts`); these items assume the bound
/// instead of repeating that error dozens of times. (A bound without the binder would be
/// "trivially false" and reported at each item; with it, only where the impl is used.)
fn alias_bounds(c: &Container) -> TokenStream {
    let p = private(c);
    let tys: Vec<_> = c
        .vars
        .iter()
        .filter(|v| v.syn_type == crate::types::SynType::Unknown)
        .map(|v| v.ty)
        .collect();
    if tys.is_empty() {
        return TokenStream::new();
    }
    quote!(where #(for<'__plc> #tys: #p::PlcType,)*)
}

/// `<krate>::__private`.
pub fn private(c: &Container) -> TokenStream {
    let krate = &c.krate;
    quote!(#krate::__private)
}

pub fn image_ident() -> syn::Ident {
    syn::Ident::new(IMAGE, proc_macro2::Span::call_site())
}

/// For each variable, the bools mapped onto it with their bits (empty for all but source
/// words). Built once: a search per variable was quadratic in the number of variables.
pub fn mapped_onto(c: &Container) -> Vec<Vec<(usize, u8)>> {
    let mut onto = vec![Vec::new(); c.vars.len()];
    for (i, v) in c.vars.iter().enumerate() {
        if let Some((s, bit)) = v.mapped_to {
            onto[s].push((i, bit));
        }
    }
    onto
}
