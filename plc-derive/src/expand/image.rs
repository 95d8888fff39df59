//! The image struct and the conversions between it and the user's struct.

use super::{image_ident, private};
use crate::ast::Container;
use proc_macro2::{Group, Span, TokenStream, TokenTree};
use quote::quote;

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

/// `#[repr(C)]`, alignment 1 (every field's `Repr` is `Unaligned`), so no padding and the
/// same offsets in every process that compiles the same declaration.
pub fn image_struct(c: &Container, bounds: &TokenStream) -> TokenStream {
    let p = private(c);
    let image = image_ident();
    let zerocopy_path = format!("{}::zerocopy", p.to_string().replace(' ', ""));
    let fields = c.vars.iter().map(|v| {
        let (ident, ty) = (v.ident, v.ty);
        // Under the user's type: an unsupported type behind an alias is reported there.
        let repr = respan(quote!(<#ty as #p::PlcType>::Repr), v.ty_span());
        quote!(pub #ident: #repr)
    });
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
        pub struct #image #bounds {
            #(#fields,)*
        }
    }
}

pub fn expand(c: &Container) -> TokenStream {
    let p = private(c);
    let image = image_ident();
    let idents: Vec<_> = c.vars.iter().map(|v| v.ident).collect();
    let tys: Vec<_> = c.vars.iter().map(|v| v.ty).collect();
    quote! {
        #[inline]
        fn to_image(&self) -> #image {
            #image { #(#idents: <#tys as #p::PlcType>::to_repr(&self.#idents),)* }
        }

        #[inline]
        fn from_image(image: &#image) -> Self {
            Self { #(#idents: <#tys as #p::PlcType>::from_repr(&image.#idents),)* }
        }

        #[inline]
        fn load_image(&mut self, image: &#image) {
            #(self.#idents = <#tys as #p::PlcType>::from_repr(&image.#idents);)*
        }

        #[inline]
        fn store_image(&self, image: &mut #image) {
            #(image.#idents = <#tys as #p::PlcType>::to_repr(&self.#idents);)*
        }
    }
}
