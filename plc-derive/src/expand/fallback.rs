//! After a declaration error, a stand-in impl so that code using the struct does not add a
//! cascade of "GlobalMemory is not implemented" errors to the real ones (thiserror's fallback).

use crate::ast::Container;
use proc_macro2::TokenStream;
use quote::quote;

pub fn expand(c: &Container) -> TokenStream {
    let krate = &c.krate;
    let ident = c.ident;
    let unreachable = quote!(::core::unreachable!("the declaration has compile errors"));
    quote! {
        #[automatically_derived]
        impl #krate::GlobalMemory for #ident {
            type Image = [u8; 0];
            const VARIABLES: &'static [#krate::VarInfo] = &[];
            const LAYOUT_HASH: u64 = 0;
            fn unpack_bits(&mut self) {}
            fn pack_bits(&mut self) {}
            fn to_image(&self) -> [u8; 0] { [] }
            fn from_image(_: &[u8; 0]) -> Self { #unreachable }
            fn try_get(&self, _: usize, _: usize) -> ::core::option::Option<#krate::Value> {
                ::core::option::Option::None
            }
            fn set(&mut self, index: usize, _: usize, _: #krate::Value)
                -> ::core::result::Result<(), #krate::SetError> {
                ::core::result::Result::Err(#krate::SetError::UnknownIndex { index })
            }
            fn read_inputs<B: ::core::convert::AsRef<[u8]>>(&mut self, _: &#krate::ProcessImage<B>)
                -> ::core::result::Result<(), #krate::ProcessImageError> {
                ::core::result::Result::Ok(())
            }
            fn write_outputs<B: ::core::convert::AsRef<[u8]> + ::core::convert::AsMut<[u8]>>(
                &self, _: &mut #krate::ProcessImage<B>,
            ) -> ::core::result::Result<(), #krate::ProcessImageError> {
                ::core::result::Result::Ok(())
            }
        }

        #[automatically_derived]
        impl ::core::default::Default for #ident {
            fn default() -> Self { #unreachable }
        }
    }
}

/// The same for a structure: a `PlcType` with no members, so fields of its type add no errors.
pub fn expand_struct(c: &Container) -> TokenStream {
    let krate = &c.krate;
    let p = super::private(c);
    let ident = c.ident;
    let unreachable = quote!(::core::unreachable!("the declaration has compile errors"));
    quote! {
        impl #p::Sealed for #ident {}

        #[automatically_derived]
        impl #p::PlcType for #ident {
            const IEC_TYPE: #krate::IecType = #krate::IecType::Byte;
            const RANK: usize = 0;
            const DIMS: &'static [usize] = &[];
            const ELEMENTS: usize = 1;
            const STRING_CAPACITY: usize = 0;
            const TYPE_NAME: ::core::option::Option<&'static str> = ::core::option::Option::None;
            // Not a panic: a declaration that uses this structure would evaluate it and report
            // one more error. All zero is a value of every member type the derive accepts.
            const __ZERO: Self = unsafe { ::core::mem::MaybeUninit::<Self>::zeroed().assume_init() };
            type Repr = [u8; 0];
            fn to_repr(&self) -> [u8; 0] { [] }
            fn from_repr(_: &[u8; 0]) -> Self { #unreachable }
            fn get_element(&self, _: usize) -> ::core::option::Option<#krate::Value> {
                ::core::option::Option::None
            }
            fn set_element(&mut self, _: usize, _: #krate::Value, _: #krate::IecType)
                -> ::core::result::Result<(), #p::ElementError> {
                ::core::result::Result::Err(#p::ElementError::OutOfRange { len: 0 })
            }
        }

        #[automatically_derived]
        impl ::core::default::Default for #ident {
            fn default() -> Self { #unreachable }
        }
    }
}
