//! The image type and the conversions between it and the user's struct.
//!
//! The image is one byte array (`plc_core`'s `image_bytes` says why not a struct of fields):
//! `__PLC_SIZES` holds the size of each variable's stored form, `__PLC_OFFSETS` where it
//! starts, in declaration order and without gaps, so the bytes are those a `#[repr(C)]` struct
//! of the stored forms would have.

use super::{image_ident, private};
use crate::ast::Container;
use proc_macro2::{Group, Literal, Span, TokenStream, TokenTree};
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

/// `__PLC_OFFSETS[i]`: where variable `i` starts in the image, in a `const` context.
pub fn offset(i: usize) -> TokenStream {
    let i = Literal::usize_unsuffixed(i);
    quote!(__PLC_OFFSETS[#i])
}

/// `__PLC_SIZES[i]`: the bytes of variable `i` in the image.
pub fn size(i: usize) -> TokenStream {
    let i = Literal::usize_unsuffixed(i);
    quote!(__PLC_SIZES[#i])
}

/// The sizes, offsets and total of the layout, and the image type: `#[repr(C)]` around a byte
/// array, alignment 1, no padding, the same bytes in every process that compiles the same
/// declaration.
pub fn image_struct(c: &Container) -> TokenStream {
    let p = private(c);
    let n = Literal::usize_unsuffixed(c.vars.len());
    let sizes = c.vars.iter().map(|v| {
        let ty = v.ty;
        // Under the user's type, through the same `facts` as the type's assertions: a type
        // that is not a PLC type gets one error there, not one per use.
        respan(quote!(#p::facts::<#ty>().repr_size()), v.ty_span())
    });
    let image = image_ident();
    let zerocopy_path = format!("{}::zerocopy", p.to_string().replace(' ', ""));
    quote! {
        const __PLC_SIZES: [usize; #n] = [#(#sizes,)*];
        const __PLC_OFFSETS: [usize; #n] = #p::offsets(__PLC_SIZES);

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
        pub struct #image([u8; #p::image_size(&__PLC_SIZES)]);
    }
}

pub fn expand(c: &Container) -> TokenStream {
    let p = private(c);
    let krate = &c.krate;
    let image = image_ident();
    let idents: Vec<_> = c.vars.iter().map(|v| v.ident).collect();
    let tys: Vec<_> = c.vars.iter().map(|v| v.ty).collect();
    // At run time the offsets are read through a `&'static` to the promoted array: indexing
    // the `const` itself would copy the whole array onto the stack at every use in an
    // unoptimised build (a 2,000-variable struct overflowed the stack), and an inline `const`
    // block per use costs seconds of incremental checking. Optimised, the loads fold away.
    let n = Literal::usize_unsuffixed(c.vars.len());
    let at = quote!(let __plc_at: &'static [usize; #n] = &__PLC_OFFSETS;);
    let offsets: Vec<_> = (0..c.vars.len())
        .map(|i| {
            let i = Literal::usize_unsuffixed(i);
            quote!(__plc_at[#i])
        })
        .collect();
    quote! {
        #[inline]
        fn to_image(&self) -> #image {
            let mut image = <#image as #p::zerocopy::FromZeros>::new_zeroed();
            <Self as #krate::GlobalMemory>::store_image(self, &mut image);
            image
        }

        #[inline]
        fn from_image(image: &#image) -> Self {
            #at
            Self {
                #(#idents: <#tys as #p::PlcType>::from_repr(
                    #p::repr_at::<#tys>(&image.0, #offsets)
                ),)*
            }
        }

        #[inline]
        fn load_image(&mut self, image: &#image) {
            #at
            #(self.#idents = <#tys as #p::PlcType>::from_repr(
                #p::repr_at::<#tys>(&image.0, #offsets)
            );)*
        }

        #[inline]
        fn store_image(&self, image: &mut #image) {
            #at
            #(*#p::repr_at_mut::<#tys>(&mut image.0, #offsets) =
                <#tys as #p::PlcType>::to_repr(&self.#idents);)*
        }
    }
}
