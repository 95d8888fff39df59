//! The image struct and the conversions between it and the user's struct.

use super::{image_ident, private};
use crate::ast::Container;
use proc_macro2::{Group, Span, TokenStream, TokenTree};
use quote::{format_ident, quote};

/// `tokens` with every span set to `span`.
fn respan(tokens: TokenStream, span: Span) -> TokenStream {
    tokens
        .into_iter()
        .map(|mut t| {
            if let TokenTree::Group(g) = &t {
                let mut inner = Group::new(g.delimiter(), respan(g.stream(), span));
                inner.set_span(span);
                return TokenTree::Group(inner);
            }
            t.set_span(span);
            t
        })
        .collect()
}

/// Fields per part of the image of a large struct. zerocopy's derives build expressions whose
/// depth grows with the number of fields (the padding check sums every field's size), and
/// rustc overflows its stack on them somewhere below 10,000 fields. Structs with more fields
/// than this get an image of parts, each a `#[repr(C)]` struct of at most this many fields;
/// since every part and field has alignment 1, the parts lay the fields out exactly as one
/// flat struct would (same offsets, no padding). Smaller structs keep the flat image.
pub const PART: usize = 256;

fn chunked(c: &Container) -> bool {
    c.vars.len() > PART
}

fn part_ident(k: usize) -> syn::Ident {
    format_ident!("{}Part{}", super::IMAGE, k)
}

fn part_field(k: usize) -> syn::Ident {
    format_ident!("__plc_part{}", k)
}

/// Where variable `i` lives in the image: `field`, or `__plc_partK.field` in a large struct.
pub fn field_path(c: &Container, i: usize) -> TokenStream {
    let ident = c.vars[i].ident;
    if chunked(c) {
        let part = part_field(i / PART);
        quote!(#part.#ident)
    } else {
        quote!(#ident)
    }
}

/// `#[repr(C)]`, alignment 1 (every field's `Repr` is `Unaligned`), so no padding and the
/// same offsets in every process that compiles the same declaration.
pub fn image_struct(c: &Container, bounds: &TokenStream) -> TokenStream {
    let p = private(c);
    let fields: Vec<TokenStream> = c
        .vars
        .iter()
        .map(|v| {
            let (ident, ty) = (v.ident, v.ty);
            // Under the user's type: an unsupported type behind an alias is reported there.
            let repr = respan(quote!(<#ty as #p::PlcType>::Repr), v.ty_span());
            quote!(pub #ident: #repr)
        })
        .collect();
    if !chunked(c) {
        return layout_struct(c, &image_ident(), &fields, bounds);
    }
    let mut out = TokenStream::new();
    let mut parts = Vec::new();
    for (k, chunk) in fields.chunks(PART).enumerate() {
        let (ident, field) = (part_ident(k), part_field(k));
        out.extend(layout_struct(c, &ident, chunk, bounds));
        parts.push(quote!(pub #field: #ident));
    }
    out.extend(layout_struct(c, &image_ident(), &parts, bounds));
    out
}

/// One `#[repr(C)]` zerocopy struct with `fields`.
fn layout_struct(
    c: &Container,
    ident: &syn::Ident,
    fields: &[TokenStream],
    bounds: &TokenStream,
) -> TokenStream {
    let p = private(c);
    let zerocopy_path = format!("{}::zerocopy", p.to_string().replace(' ', ""));
    quote! {
        #[repr(C)]
        #[derive(
            ::core::clone::Clone,
            ::core::marker::Copy,
            #p::zerocopy::FromBytes,
            #p::zerocopy::IntoBytes,
            #p::zerocopy::KnownLayout,
            #p::zerocopy::Immutable,
            #p::zerocopy::Unaligned
        )]
        #[zerocopy(crate = #zerocopy_path)]
        #[doc(hidden)]
        // The fields repeat the user's names, which the user may have allowed to be non-snake
        // case (an imported `Speed`); the warning belongs on their struct, not on ours.
        #[allow(non_snake_case)]
        pub struct #ident #bounds {
            #(#fields,)*
        }
    }
}

/// The image built from `self`: `Image { a: .., b: .. }`, or part by part.
fn image_literal(c: &Container) -> TokenStream {
    let p = private(c);
    let value = |v: &crate::ast::Var| {
        let (ident, ty) = (v.ident, v.ty);
        quote!(#ident: <#ty as #p::PlcType>::to_repr(&self.#ident))
    };
    let image = image_ident();
    if !chunked(c) {
        let values = c.vars.iter().map(value);
        return quote!(#image { #(#values,)* });
    }
    let parts = c.vars.chunks(PART).enumerate().map(|(k, chunk)| {
        let (ident, field) = (part_ident(k), part_field(k));
        let values = chunk.iter().map(value);
        quote!(#field: #ident { #(#values,)* })
    });
    quote!(#image { #(#parts,)* })
}

pub fn expand(c: &Container) -> TokenStream {
    let p = private(c);
    let image = image_ident();
    let idents: Vec<_> = c.vars.iter().map(|v| v.ident).collect();
    let tys: Vec<_> = c.vars.iter().map(|v| v.ty).collect();
    let paths: Vec<_> = (0..c.vars.len()).map(|i| field_path(c, i)).collect();
    let literal = image_literal(c);
    quote! {
        #[inline]
        fn to_image(&self) -> #image {
            #literal
        }

        #[inline]
        fn from_image(image: &#image) -> Self {
            Self { #(#idents: <#tys as #p::PlcType>::from_repr(&image.#paths),)* }
        }

        #[inline]
        fn load_image(&mut self, image: &#image) {
            #(self.#idents = <#tys as #p::PlcType>::from_repr(&image.#paths);)*
        }

        #[inline]
        fn store_image(&self, image: &mut #image) {
            #(image.#paths = <#tys as #p::PlcType>::to_repr(&self.#idents);)*
        }
    }
}
