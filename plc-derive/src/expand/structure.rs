//! `#[derive(PlcStruct)]`: the structure as a `PlcType`, so a `GlobalMemory` (or another
//! structure) holds it like any field: its image is its members' images in declaration order
//! (the same bytes as a `#[repr(C)]` struct of them), at a constant offset in the program's.
//! Its basic values are numbered by leaves (`PlcType::LEAVES`): each member's in turn, which
//! is how `get`, `set`, the mailbox and paths reach every member.

use super::{image_ident, private};
use crate::ast::Container;
use crate::expand::metadata;
use proc_macro2::{Literal, TokenStream};
use quote::quote;

/// `bounds`: `where` clauses assuming the member types only the compiler knows are PLC types
/// (their one error comes from their assertion); `alarms`: the associated `ALARMS`, if any.
pub fn expand(c: &Container, bounds: &TokenStream, alarms: &TokenStream) -> TokenStream {
    let p = private(c);
    let krate = &c.krate;
    let ident = c.ident;
    let image = image_ident();
    let type_name = &c.type_name;
    let tys: Vec<_> = c.vars.iter().map(|v| v.ty).collect();
    let idents: Vec<_> = c.vars.iter().map(|v| v.ident).collect();
    // Members only the compiler knows may be structures, whose members have initials.
    let (nested_idents, nested): (Vec<_>, Vec<_>) = c
        .vars
        .iter()
        .filter(|v| v.syn_type == crate::types::SynType::Unknown)
        .map(|v| (v.ident, v.ty))
        .unzip();
    let members = metadata::infos(c);
    let at: Vec<_> = (0..c.vars.len()).map(Literal::usize_unsuffixed).collect();
    let (unpack, pack) = super::bits::moves(c);
    let get = leaf_get(c);
    let set = leaf_set(c);
    let places = super::places::expand_struct(c);
    let places_table = super::places::table(c);
    let initials = super::default::initials(
        c,
        quote!(<Self as #p::PlcType>::__unpack_bits(gm);),
        quote!(<Self as #p::PlcType>::__pack_bits(gm);),
    );
    quote! {
        impl #p::Sealed for #ident #bounds {}

        #[automatically_derived]
        impl #p::PlcType for #ident #bounds {
            const IEC_TYPE: #krate::IecType = #krate::IecType::Byte;
            const RANK: usize = 0;
            const DIMS: &'static [usize] = &[];
            const ELEMENTS: usize = 1;
            const STRING_CAPACITY: usize = 0;
            const __ZERO: Self = Self { #(#idents: <#tys as #p::PlcType>::__ZERO,)* };
            const LEAVES: usize = 0 #(+ <#tys as #p::PlcType>::LEAVES)*;
            const MEMBERS: &'static [#krate::VarInfo] = &[#(#members,)*];
            const TYPE_NAME: ::core::option::Option<&'static str> =
                ::core::option::Option::Some(#type_name);
            const DEPTH: usize = 1 + #p::max_depth(&[#(<#tys as #p::PlcType>::DEPTH,)*]);
            type Repr = #image;
            #alarms

            #[inline]
            fn to_repr(&self) -> #image {
                let mut image = <#image as #p::zerocopy::FromZeros>::new_zeroed();
                let __plc_at = &__PLC_OFFSETS;
                #(*#p::repr_at_mut::<#tys>(&mut image.0, __plc_at[#at]) =
                    <#tys as #p::PlcType>::to_repr(&self.#idents);)*
                image
            }

            #[inline]
            fn from_repr(image: &#image) -> Self {
                let __plc_at = &__PLC_OFFSETS;
                Self {
                    #(#idents: <#tys as #p::PlcType>::from_repr(
                        #p::repr_at::<#tys>(&image.0, __plc_at[#at])
                    ),)*
                }
            }

            fn get_element(&self, element: usize) -> ::core::option::Option<#krate::Value> {
                let mut leaf = element;
                #get
                ::core::option::Option::None
            }

            fn set_element(
                &mut self,
                element: usize,
                value: #krate::Value,
                _: #krate::IecType,
            ) -> ::core::result::Result<(), #p::ElementError> {
                let mut leaf = element;
                #set
                ::core::result::Result::Err(#p::ElementError::OutOfRange {
                    len: <Self as #p::PlcType>::LEAVES,
                })
            }

            #[inline]
            fn __unpack_bits(&mut self) {
                #unpack
                #(<#tys as #p::PlcType>::__unpack_bits(&mut self.#idents);)*
            }

            #[inline]
            fn __pack_bits(&mut self) {
                #(<#tys as #p::PlcType>::__pack_bits(&mut self.#idents);)*
                #pack
            }

            fn __init(&mut self) {
                let gm = self;
                #(<#nested as #p::PlcType>::__init(&mut gm.#nested_idents);)*
                #initials
            }

            #places
        }

        #[automatically_derived]
        #[doc(hidden)]
        impl #ident #bounds {
            #places_table
        }

        #[automatically_derived]
        impl ::core::default::Default for #ident #bounds {
            fn default() -> Self {
                let zeroed = <#image as #p::zerocopy::FromZeros>::new_zeroed();
                let mut s = <Self as #p::PlcType>::from_repr(&zeroed);
                <Self as #p::PlcType>::__init(&mut s);
                s
            }
        }
    }
}

/// Leaf `leaf` of the member that holds it: each member's leaves in turn.
fn leaf_get(c: &Container) -> TokenStream {
    let p = private(c);
    c.vars
        .iter()
        .map(|v| {
            let (ident, ty) = (v.ident, v.ty);
            quote! {
                if leaf < <#ty as #p::PlcType>::LEAVES {
                    return <#ty as #p::PlcType>::get_element(&self.#ident, leaf);
                }
                leaf -= <#ty as #p::PlcType>::LEAVES;
            }
        })
        .collect()
}

/// Sets leaf `leaf` with the member's declared IEC type, keeping bit-mapped bools and their
/// source words consistent as `GlobalMemory::set` does.
fn leaf_set(c: &Container) -> TokenStream {
    let p = private(c);
    let onto = super::mapped_onto(c);
    c.vars
        .iter()
        .enumerate()
        .map(|(i, v)| {
            let (ident, ty) = (v.ident, v.ty);
            let bits = super::access::after_set(c, &onto, i);
            quote! {
                if leaf < <#ty as #p::PlcType>::LEAVES {
                    <#ty as #p::PlcType>::set_element(
                        &mut self.#ident,
                        leaf,
                        value,
                        <Self as #p::PlcType>::MEMBERS[#i].iec_type,
                    )?;
                    #bits
                    return ::core::result::Result::Ok(());
                }
                leaf -= <#ty as #p::PlcType>::LEAVES;
            }
        })
        .collect()
}
