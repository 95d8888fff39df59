//! `try_get` / `set` by variable index: what tools and the mailbox use. `set` keeps a
//! bit-mapped bool and its source word consistent in both directions.
//!
//! A large declaration is split into chunks of [`CHUNK`] variables, one function each: the
//! borrow checker's work on one body with an arm per variable grows faster than its arms.
//! (Naming a chunk's fields through one pattern, `let Self { a: __plc_0, .. } = self;`, to
//! spare the compiler's search of all fields per `self.a`, made borrow checking ten times
//! slower: a thousand references live across the whole body.)

use super::{mapped_onto, private};
use crate::ast::Container;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

/// Variables per chunk function (a 10,000-variable declaration checked in 2.1 s and 250 MB
/// less with chunks than with one `match`).
const CHUNK: usize = 1024;

/// After field `i` changed: a bit-mapped bool updates its bit of the source word, a source
/// word its bools (`onto`: [`mapped_onto`]).
pub fn after_set(c: &Container, onto: &[Vec<(usize, u8)>], i: usize) -> TokenStream {
    let p = private(c);
    let v = &c.vars[i];
    let ident = v.ident;
    let to_source = v.mapped_to.map(|(s, bit)| {
        let src = c.vars[s].ident;
        let bit = bit as u32;
        quote!(self.#src = #p::with_bit(self.#src, #bit, #p::to_bit(self.#ident));)
    });
    let to_bools = onto[i].iter().map(|&(b, bit)| {
        let b = c.vars[b].ident;
        let bit = bit as u32;
        quote!(#p::set_from_bit(&mut self.#b, #p::get_bit(self.#ident, #bit));)
    });
    quote!(#to_source #(#to_bools)*)
}

/// `try_get` and `set` for the `GlobalMemory` impl, and their chunk functions for an inherent
/// impl (none when one chunk holds every variable).
pub fn expand(c: &Container) -> (TokenStream, TokenStream) {
    let p = private(c);
    let krate = &c.krate;
    let ident = c.ident;
    let onto = mapped_onto(c);
    let get_arm = |i: usize| {
        let (ty, field) = (c.vars[i].ty, c.vars[i].ident);
        quote!(#i => <#ty as #p::PlcType>::get_element(&self.#field, element),)
    };
    // No `?` per arm: the `Try` machinery of 10,000 arms cost the compiler seconds.
    let set_arm = |i: usize| {
        let bits = after_set(c, &onto, i);
        let field = c.vars[i].ident;
        let set = quote!(#p::set_field(&mut self.#field, &__plc_vars[#i], element, value));
        if bits.is_empty() {
            quote!(#i => #set,)
        } else {
            quote!(#i => {
                let __plc_set = #set;
                if __plc_set.is_ok() {
                    #bits
                }
                __plc_set
            })
        }
    };
    let get_sig =
        quote!((&self, index: usize, element: usize) -> ::core::option::Option<#krate::Value>);
    let set_sig = quote! {
        (&mut self, index: usize, element: usize, value: #krate::Value)
            -> ::core::result::Result<(), #krate::SetError>
    };
    let get_body = |arms: TokenStream| {
        quote!(match index {
            #arms
            _ => ::core::option::Option::None,
        })
    };
    let set_body = |arms: TokenStream| {
        quote! {
            let __plc_vars: &'static [#krate::VarInfo] = <Self as #krate::GlobalMemory>::VARIABLES;
            match index {
                #arms
                _ => ::core::result::Result::Err(#krate::SetError::UnknownIndex { index }),
            }
        }
    };
    let n = c.vars.len();
    if n <= CHUNK {
        let gets: TokenStream = (0..n).map(&get_arm).collect();
        let sets: TokenStream = (0..n).map(&set_arm).collect();
        let (get, set) = (get_body(gets), set_body(sets));
        let items = quote! {
            fn try_get #get_sig { #get }
            fn set #set_sig { #set }
        };
        return (items, TokenStream::new());
    }
    let mut chunk_fns = TokenStream::new();
    let mut get_arms = TokenStream::new();
    let mut set_arms = TokenStream::new();
    for (k, start) in (0..n).step_by(CHUNK).enumerate() {
        let fields = start..(start + CHUNK).min(n);
        let (get_k, set_k) = (
            format_ident!("__plc_try_get_{k}"),
            format_ident!("__plc_set_{k}"),
        );
        let gets: TokenStream = fields.clone().map(&get_arm).collect();
        let sets: TokenStream = fields.map(&set_arm).collect();
        let (get, set) = (get_body(gets), set_body(sets));
        chunk_fns.extend(quote! {
            #[inline(never)]
            fn #get_k #get_sig { #get }
            #[inline(never)]
            fn #set_k #set_sig { #set }
        });
        get_arms.extend(quote!(#k => #ident::#get_k(self, index, element),));
        set_arms.extend(quote!(#k => #ident::#set_k(self, index, element, value),));
    }
    let items = quote! {
        fn try_get #get_sig {
            match index / #CHUNK {
                #get_arms
                _ => ::core::option::Option::None,
            }
        }
        fn set #set_sig {
            match index / #CHUNK {
                #set_arms
                _ => ::core::result::Result::Err(#krate::SetError::UnknownIndex { index }),
            }
        }
    };
    (items, chunk_fns)
}
