//! `unpack_bits` / `pack_bits`: branch-free single-bit moves; the other bits of a
//! source word are never touched.

use super::private;
use crate::ast::Container;
use proc_macro2::TokenStream;
use quote::quote;

/// This level's moves: each bit-mapped bool from (`unpack`) and into (`pack`) its source word.
pub fn moves(c: &Container) -> (TokenStream, TokenStream) {
    let p = private(c);
    let mut unpack = TokenStream::new();
    let mut pack = TokenStream::new();
    for v in &c.vars {
        let Some((s, bit)) = v.mapped_to else {
            continue;
        };
        let (b, src) = (v.ident, c.vars[s].ident);
        let bit = bit as u32;
        unpack.extend(quote!(#p::set_from_bit(&mut self.#b, #p::get_bit(self.#src, #bit));));
        pack.extend(quote!(self.#src = #p::with_bit(self.#src, #bit, #p::to_bit(self.#b));));
    }
    (unpack, pack)
}

pub fn expand(c: &Container) -> TokenStream {
    let p = private(c);
    let (unpack, pack) = moves(c);
    // Fields only the compiler knows may be structures with bits of their own: their calls
    // are empty for basic types.
    let nested: Vec<_> = c
        .vars
        .iter()
        .filter(|v| v.syn_type == crate::types::SynType::Unknown)
        .map(|v| (v.ident, v.ty))
        .collect();
    let unpack_nested = nested
        .iter()
        .map(|(f, ty)| quote!(<#ty as #p::PlcType>::__unpack_bits(&mut self.#f);));
    let pack_nested = nested
        .iter()
        .map(|(f, ty)| quote!(<#ty as #p::PlcType>::__pack_bits(&mut self.#f);));
    quote! {
        #[inline]
        fn unpack_bits(&mut self) {
            #unpack
            #(#unpack_nested)*
        }

        #[inline]
        fn pack_bits(&mut self) {
            #(#pack_nested)*
            #pack
        }
    }
}
