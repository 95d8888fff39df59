//! The image type and the conversions between it and the user's struct.
//!
//! The image is one byte array (`plc_core`'s `image_bytes` says why not a struct of fields):
//! `__PLC_SIZES` holds the size of each variable's stored form, `__PLC_OFFSETS` where it
//! starts, in declaration order and without gaps, so the bytes are those a `#[repr(C)]` struct
//! of the stored forms would have.

use super::runs::{self, Piece, Run};
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

/// Where variable `i` starts in the image, in a `const` context. Read through a reference to
/// the array: a use of the array `const` itself copies the whole array in the compiler's
/// const evaluation, twice per variable in `VARIABLES`, which made a 10,000-variable
/// declaration take 800 MB more memory to compile.
pub fn offset(i: usize) -> TokenStream {
    let i = Literal::usize_unsuffixed(i);
    quote!(__PLC_OFFSETS_REF[#i])
}

/// The bytes of variable `i` in the image (through a reference, as [`offset`]).
pub fn size(i: usize) -> TokenStream {
    let i = Literal::usize_unsuffixed(i);
    quote!(__PLC_SIZES_REF[#i])
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
        const __PLC_SIZES_REF: &'static [usize; #n] = &__PLC_SIZES;
        const __PLC_OFFSETS_REF: &'static [usize; #n] = &__PLC_OFFSETS;

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

/// `__PLC_ZERO`, the struct whose image is all zero bytes, as a constant (an associated one,
/// so it can have the impls' bounds): `from_image` and `Default` start from it with one copy.
/// Filling each field from its bytes in one struct literal made a function the optimiser
/// took minutes and gigabytes over for 10,000 variables.
pub fn zero(c: &Container) -> TokenStream {
    let p = private(c);
    let idents = c.vars.iter().map(|v| v.ident);
    let tys = c.vars.iter().map(|v| v.ty);
    quote!(const __PLC_ZERO: Self = Self { #(#idents: <#tys as #p::PlcType>::__ZERO,)* };)
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
    let mut load = TokenStream::new();
    let mut store = TokenStream::new();
    for piece in runs::pieces(c, runs::MIN_RUN_FIELDS) {
        match piece {
            Piece::Field(i) => {
                let (f, ty, at) = (idents[i], tys[i], &offsets[i]);
                load.extend(quote!(self.#f = <#ty as #p::PlcType>::from_repr(
                    #p::repr_at::<#ty>(&image.0, #at)
                );));
                store.extend(quote!(*#p::repr_at_mut::<#ty>(&mut image.0, #at) =
                    <#ty as #p::PlcType>::to_repr(&self.#f);));
            }
            Piece::Run(run) => {
                let (l, s) = run_loops(c, run);
                load.extend(l);
                store.extend(s);
            }
        }
    }
    quote! {
        #[inline]
        fn to_image(&self) -> #image {
            let mut image = <#image as #p::zerocopy::FromZeros>::new_zeroed();
            <Self as #krate::GlobalMemory>::store_image(self, &mut image);
            image
        }

        #[inline]
        fn from_image(image: &#image) -> Self {
            let mut gm = Self::__PLC_ZERO;
            <Self as #krate::GlobalMemory>::load_image(&mut gm, image);
            gm
        }

        // The loops over runs use `unsafe` (`field_at`), with no `#[allow(unsafe_code)]`:
        // rustc does not apply that lint to what a derive expands, and an `allow` would be an
        // error in a crate that forbids unsafe code (tests/pass/forbid_unsafe_code.rs).
        #[inline]
        fn load_image(&mut self, image: &#image) {
            #at
            #load
        }

        #[inline]
        fn store_image(&self, image: &mut #image) {
            #at
            #store
        }
    }
}

/// `offset_of!` each of `fields` in the struct, as a `const` array named `name`.
pub fn struct_offsets(c: &Container, name: &syn::Ident, fields: &[usize]) -> TokenStream {
    let p = private(c);
    let ident = c.ident;
    let len = Literal::usize_unsuffixed(fields.len());
    let fields = fields.iter().map(|&i| c.vars[i].ident);
    quote!(const #name: [usize; #len] = [#(#p::core::mem::offset_of!(#ident, #fields),)*];)
}

/// The load and the store loop of a run: one pass per repetition, one conversion per column.
fn run_loops(c: &Container, run: Run) -> (TokenStream, TokenStream) {
    let p = private(c);
    let ident = c.ident;
    let st = syn::Ident::new("__PLC_RUN_FIELDS", Span::call_site());
    let fields: Vec<usize> = (run.start..run.start + run.len()).collect();
    let table = struct_offsets(c, &st, &fields);
    let (period, reps) = (
        Literal::usize_unsuffixed(run.period),
        Literal::usize_unsuffixed(run.reps),
    );
    let len = Literal::usize_unsuffixed(run.len());
    let start = Literal::usize_unsuffixed(run.start);
    let next = Literal::usize_unsuffixed(run.start + run.period);
    // Where field (r, j) is: in the struct, from the column's step when every column steps
    // evenly (a `const`: the other arm is compiled away), else from the table; in the image
    // the run's fields are one after the other, so each repetition is the first one's size on.
    let setup = quote! {
        #table
        const __PLC_STEPS: ::core::option::Option<[usize; #period]> =
            #p::run_steps::<#period>(&__PLC_RUN_FIELDS);
        const __PLC_IMAGE_STEP: usize = __PLC_OFFSETS[#next] - __PLC_OFFSETS[#start];
        let __plc_fields: &'static [usize; #len] = &__PLC_RUN_FIELDS;
    };
    let mut load = TokenStream::new();
    let mut store = TokenStream::new();
    for j in 0..run.period {
        let ty = c.vars[run.start + j].ty;
        let col = Literal::usize_unsuffixed(j);
        let first = Literal::usize_unsuffixed(run.start + j);
        let place = quote! {
            let __plc_field = match __PLC_STEPS {
                ::core::option::Option::Some(__plc_steps) =>
                    __plc_fields[#col] + __plc_r * __plc_steps[#col],
                ::core::option::Option::None => __plc_fields[__plc_r * #period + #col],
            };
            let __plc_image = __plc_at[#first] + __plc_r * __PLC_IMAGE_STEP;
        };
        // SAFETY (both): `__plc_field` is `offset_of!` of field `run.start + r * period + j`,
        // whose type has the same tokens as this column's first field, so it is `#ty`.
        load.extend(quote! {{
            #place
            *unsafe { #p::field_at_mut::<#ident, #ty>(self, __plc_field) } =
                <#ty as #p::PlcType>::from_repr(#p::repr_at::<#ty>(&image.0, __plc_image));
        }});
        store.extend(quote! {{
            #place
            *#p::repr_at_mut::<#ty>(&mut image.0, __plc_image) =
                <#ty as #p::PlcType>::to_repr(unsafe { #p::field_at::<#ident, #ty>(self, __plc_field) });
        }});
    }
    let wrap = |body: TokenStream| {
        quote! {{
            #setup
            let mut __plc_r = 0usize;
            while __plc_r < #reps {
                #body
                __plc_r += 1;
            }
        }}
    };
    (wrap(load), wrap(store))
}
