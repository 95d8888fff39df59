//! `try_get` / `set` by variable index: what tools and the mailbox use. `set` keeps a
//! bit-mapped bool and its source word consistent in both directions.

use super::{mapped_onto, private};
use crate::ast::Container;
use proc_macro2::TokenStream;
use quote::quote;

/// After field `i` changed: a bit-mapped bool updates its bit of the source word, a source
/// word its bools.
pub fn after_set(c: &Container, i: usize) -> TokenStream {
    let p = private(c);
    let v = &c.vars[i];
    let ident = v.ident;
    let to_source = v.mapped_to.map(|(s, bit)| {
        let src = c.vars[s].ident;
        let bit = bit as u32;
        quote!(self.#src = #p::with_bit(self.#src, #bit, #p::to_bit(self.#ident));)
    });
    let to_bools = mapped_onto(c, i).map(|(b, bit)| {
        let b = b.ident;
        let bit = bit as u32;
        quote!(#p::set_from_bit(&mut self.#b, #p::get_bit(self.#ident, #bit));)
    });
    quote!(#to_source #(#to_bools)*)
}

pub fn expand(c: &Container) -> TokenStream {
    let p = private(c);
    let krate = &c.krate;
    let gets = c.vars.iter().enumerate().map(|(i, v)| {
        let (ident, ty) = (v.ident, v.ty);
        quote!(#i => <#ty as #p::PlcType>::get_element(&self.#ident, element),)
    });
    let sets = c.fields().enumerate().map(|(i, (v, m))| {
        let (ident, name) = (v.ident, &m.name.value);
        let bits = after_set(c, i);
        quote! {
            #i => {
                #p::set_field(
                    &mut self.#ident,
                    #name,
                    <Self as #krate::GlobalMemory>::VARIABLES[#i].iec_type,
                    element,
                    value,
                )?;
                #bits
                ::core::result::Result::Ok(())
            }
        }
    });
    quote! {
        fn try_get(&self, index: usize, element: usize) -> ::core::option::Option<#krate::Value> {
            match index {
                #(#gets)*
                _ => ::core::option::Option::None,
            }
        }

        fn set(
            &mut self,
            index: usize,
            element: usize,
            value: #krate::Value,
        ) -> ::core::result::Result<(), #krate::SetError> {
            match index {
                #(#sets)*
                _ => ::core::result::Result::Err(#krate::SetError::UnknownIndex { index }),
            }
        }
    }
}
