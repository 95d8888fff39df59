//! Where each basic value lies in the user's struct (`GlobalMemory::struct_places`,
//! `PlcType::__places` of a structure), for forces that write it there: a table of the
//! fields' places built from `offset_of!` in a `const`, and what a `set` also writes of a
//! bit-mapped bool or a source word (as `access::after_set` does it through the fields).

use super::{mapped_onto, private};
use crate::ast::Container;
use proc_macro2::{Literal, TokenStream};
use quote::quote;

/// `const __PLC_PLACES`, for an inherent impl: each field's offset and type, in declaration
/// order. One table instead of a `match` arm per field: a 10,000-field declaration's arms cost
/// the borrow checker seconds (`access`), a `const` array does not. The offsets are measured on
/// one uninitialised `Self` inside the `const` rather than with `offset_of!`, which expands to
/// an inline `const { .. }` block per field: 2,000 bodies to type- and borrow-check, which
/// doubled a 2,000-field declaration's `cargo check` (`derive_vs_serde_2000`).
pub fn table(c: &Container) -> TokenStream {
    let p = private(c);
    let n = Literal::usize_unsuffixed(c.vars.len());
    let entries = c.vars.iter().map(|v| {
        let (field, ty) = (v.ident, v.ty);
        quote!(#p::FieldPlaces::new::<#ty>(__plc_base, &raw const (*__plc_base).#field))
    });
    quote! {
        // SAFETY: each entry gives `FieldPlaces::new` a pointer to the `Self` below and one to
        // a field of it, projected by the compiler from the field's name (no reference is made
        // to the uninitialised memory); `new` takes the field's type from that pointer, so it
        // is the field's declared type, and fails to compile if the field would not lie
        // inside `Self`.
        const __PLC_PLACES: [#p::FieldPlaces<Self>; #n] = unsafe {
            let __plc_value = #p::core::mem::MaybeUninit::<Self>::uninit();
            let __plc_base: *const Self = __plc_value.as_ptr();
            [#(#entries,)*]
        };
    }
}

/// What a `set` of field `__plc_i` writes besides the field itself, given to `each`: a
/// bit-mapped bool's bit of its source word, a source word's bools. `true` for the others.
fn links(c: &Container) -> TokenStream {
    let p = private(c);
    let onto = mapped_onto(c);
    let mut arms = TokenStream::new();
    for (i, v) in c.vars.iter().enumerate() {
        if let Some((s, bit)) = v.mapped_to {
            let src_ty = c.vars[s].ty;
            let bit = u32::from(bit);
            // SAFETY: entry `s` of `__PLC_PLACES` was made by `FieldPlaces::new::<src_ty>` from
            // a pointer to the source field, so its offset is where that field lies and
            // `src_ty` its type; `bit_places` checks that it is an integer and the bit within
            // it. (The table's offset, not an `offset_of!`: see `table`.)
            arms.extend(quote! {
                #i => unsafe {
                    #p::bit_places::<Self, #src_ty>(__plc_table[#s].offset(), #bit, each)
                },
            });
        }
        if !onto[i].is_empty() {
            let bools = onto[i].iter().map(|&(b, _)| b);
            arms.extend(quote!(#i => true #(&& __plc_table[#bools].places(0, each))*,));
        }
    }
    if arms.is_empty() {
        return quote!(true);
    }
    quote! {
        match __plc_i {
            #arms
            _ => true,
        }
    }
}

/// `struct_places` for the `GlobalMemory` impl: the variable's leaf, then its links.
pub fn expand(c: &Container) -> TokenStream {
    let p = private(c);
    let krate = &c.krate;
    let n = Literal::usize_unsuffixed(c.vars.len());
    let links = links(c);
    quote! {
        fn struct_places(
            index: usize,
            element: usize,
            each: &mut dyn ::core::ops::FnMut(#krate::place::StructPlace<Self>),
        ) -> bool {
            let __plc_table: &'static [#p::FieldPlaces<Self>; #n] = &Self::__PLC_PLACES;
            let __plc_i = index;
            match __plc_table.get(__plc_i) {
                ::core::option::Option::Some(__plc_field) if __plc_field.places(element, each) => {
                    #links
                }
                _ => false,
            }
        }
    }
}

/// `__places` for a structure's `PlcType` impl: the member that holds the leaf (each
/// member's leaves in turn, as `get_element` counts them), then its links.
pub fn expand_struct(c: &Container) -> TokenStream {
    let p = private(c);
    let n = Literal::usize_unsuffixed(c.vars.len());
    let links = links(c);
    quote! {
        fn __places(
            leaf: usize,
            each: &mut dyn ::core::ops::FnMut(#p::StructPlace<Self>),
        ) -> bool {
            let __plc_table: &'static [#p::FieldPlaces<Self>; #n] = &Self::__PLC_PLACES;
            let mut __plc_leaf = leaf;
            let mut __plc_i = 0usize;
            while __plc_i < #n {
                let __plc_field = &__plc_table[__plc_i];
                if __plc_leaf < __plc_field.leaves() {
                    return __plc_field.places(__plc_leaf, each) && { #links };
                }
                __plc_leaf -= __plc_field.leaves();
                __plc_i += 1;
            }
            false
        }
    }
}
