//! `unpack_bits` / `pack_bits`: branch-free single-bit moves; the other bits of a
//! source word are never touched.

use super::runs::{self, BitPiece, BitRun};
use super::{image, private};
use crate::ast::Container;
use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::quote;

/// This level's moves: each bit-mapped bool from (`unpack`) and into (`pack`) its source word,
/// long runs of them in loops (`runs`). The code uses `unsafe`: its functions allow it.
pub fn moves(c: &Container) -> (TokenStream, TokenStream) {
    let p = private(c);
    let mut unpack = TokenStream::new();
    let mut pack = TokenStream::new();
    for piece in runs::bit_pieces(c, runs::MIN_BIT_RUN) {
        match piece {
            BitPiece::Bool(i) => {
                let v = &c.vars[i];
                let Some((s, bit)) = v.mapped_to else {
                    continue;
                };
                let (b, src) = (v.ident, c.vars[s].ident);
                let bit = bit as u32;
                unpack
                    .extend(quote!(#p::set_from_bit(&mut self.#b, #p::get_bit(self.#src, #bit));));
                pack.extend(
                    quote!(self.#src = #p::with_bit(self.#src, #bit, #p::to_bit(self.#b));),
                );
            }
            BitPiece::Run(run) => {
                let (u, k) = bit_loops(c, run);
                unpack.extend(u);
                pack.extend(k);
            }
        }
    }
    (unpack, pack)
}

/// The unpack and pack loops of a bit run: one pass per source word, one move per bit or,
/// where the bools are one byte apart, per eight bits.
fn bit_loops(c: &Container, run: BitRun) -> (TokenStream, TokenStream) {
    let p = private(c);
    let ident = c.ident;
    let (src_ty, bool_ty) = (c.vars[run.source].ty, c.vars[run.start].ty);
    let words: Vec<usize> = (run.source..run.source + run.words).collect();
    let bools: Vec<usize> = (run.start..run.start + run.len()).collect();
    let (w_name, b_name) = (
        Ident::new("__PLC_RUN_WORDS", Span::call_site()),
        Ident::new("__PLC_RUN_BOOLS", Span::call_site()),
    );
    let w_table = image::struct_offsets(c, &w_name, &words);
    let b_table = image::struct_offsets(c, &b_name, &bools);
    let (n_words, n_bools) = (
        Literal::usize_unsuffixed(run.words),
        Literal::usize_unsuffixed(run.len()),
    );
    let bits = Literal::usize_unsuffixed(run.bits);
    let first = Literal::u32_unsuffixed(run.first_bit);
    // As for the fields' runs (`image::run_loops`): the addresses from the steps when the
    // compiler laid the words and the bools out evenly, else from the tables.
    let setup = quote! {
        #w_table
        #b_table
        const __PLC_WORD_STEP: ::core::option::Option<[usize; 1]> =
            #p::run_steps::<1>(&__PLC_RUN_WORDS);
        const __PLC_BOOL_STEP: ::core::option::Option<[usize; 1]> =
            #p::run_steps::<1>(&__PLC_RUN_BOOLS);
        let __plc_words: &'static [usize; #n_words] = &__PLC_RUN_WORDS;
        let __plc_bools: &'static [usize; #n_bools] = &__PLC_RUN_BOOLS;
    };
    let word_at = quote! {
        let __plc_word = match __PLC_WORD_STEP {
            ::core::option::Option::Some([__plc_step]) => __plc_words[0] + __plc_w * __plc_step,
            ::core::option::Option::None => __plc_words[__plc_w],
        };
    };
    let bool_at = quote! {
        let __plc_k = __plc_w * #bits + __plc_j;
        let __plc_bool = match __PLC_BOOL_STEP {
            ::core::option::Option::Some([__plc_step]) => __plc_bools[0] + __plc_k * __plc_step,
            ::core::option::Option::None => __plc_bools[__plc_k],
        };
        let __plc_bit = #first + __plc_j as u32;
    };
    // Bools one byte apart (as the compiler lays out a struct's bools): eight at a time,
    // through their bytes; the rest bit by bit.
    let bytes_at = quote! {
        let __plc_at = __plc_bools[0] + __plc_w * #bits + __plc_j;
        let __plc_bit = #first + __plc_j as u32;
    };
    let each = |word: TokenStream, byte: TokenStream, bit: TokenStream, after: TokenStream| {
        quote! {{
            #setup
            const __PLC_BYTEWISE: bool = ::core::mem::size_of::<#bool_ty>() == 1
                && ::core::matches!(__PLC_BOOL_STEP, ::core::option::Option::Some([1]));
            let mut __plc_w = 0usize;
            while __plc_w < #n_words {
                #word_at
                #word
                let mut __plc_j = 0usize;
                while __PLC_BYTEWISE && __plc_j + 8 <= #bits {
                    #bytes_at
                    #byte
                    __plc_j += 8;
                }
                while __plc_j < #bits {
                    #bool_at
                    #bit
                    __plc_j += 1;
                }
                #after
                __plc_w += 1;
            }
        }}
    };
    // SAFETY (all): `__plc_word` and `__plc_bool` are `offset_of!` of the run's words and
    // bools, each of the same type tokens as the run's first, so of `src_ty` and `bool_ty`;
    // no two of the references are alive at once. Bytewise, `__plc_at..__plc_at + 8` are
    // eight of the run's bools (one byte each, one byte apart: `__PLC_BYTEWISE`), written
    // only with bytes of 0 or 1.
    let unpack = each(
        quote!(let __plc_value: #src_ty =
            *unsafe { #p::field_at::<#ident, #src_ty>(self, __plc_word) };),
        quote!(unsafe {
            #p::set_bool_bytes(self, __plc_at, #p::bools_from_byte(__plc_value, __plc_bit))
        };),
        quote!(#p::set_from_bit(
            unsafe { #p::field_at_mut::<#ident, #bool_ty>(self, __plc_bool) },
            #p::get_bit(__plc_value, __plc_bit),
        );),
        TokenStream::new(),
    );
    let pack = each(
        quote!(let mut __plc_value: #src_ty =
            *unsafe { #p::field_at::<#ident, #src_ty>(self, __plc_word) };),
        quote!(__plc_value = #p::with_byte_from_bools(
            __plc_value,
            __plc_bit,
            unsafe { #p::bool_bytes(self, __plc_at) },
        );),
        quote!(__plc_value = #p::with_bit(__plc_value, __plc_bit, #p::to_bit(
            *unsafe { #p::field_at::<#ident, #bool_ty>(self, __plc_bool) },
        ));),
        quote!(*unsafe { #p::field_at_mut::<#ident, #src_ty>(self, __plc_word) } = __plc_value;),
    );
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
