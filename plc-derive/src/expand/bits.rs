//! `unpack_bits` / `pack_bits`: branch-free single-bit moves; the other bits of a
//! source word are never touched.

use super::private;
use crate::ast::Container;
use proc_macro2::TokenStream;
use quote::quote;

pub fn expand(c: &Container) -> TokenStream {
    let p = private(c);
    let mut unpack = Vec::new();
    let mut pack = Vec::new();
    for v in &c.vars {
        let Some((s, bit)) = v.mapped_to else {
            continue;
        };
        let (b, src) = (v.ident, c.vars[s].ident);
        let bit = bit as u32;
        unpack.push(quote!(#p::set_from_bit(&mut self.#b, #p::get_bit(self.#src, #bit));));
        pack.push(quote!(self.#src = #p::with_bit(self.#src, #bit, #p::to_bit(self.#b));));
    }
    quote! {
        #[inline]
        fn unpack_bits(&mut self) {
            #(#unpack)*
        }

        #[inline]
        fn pack_bits(&mut self) {
            #(#pack)*
        }
    }
}
