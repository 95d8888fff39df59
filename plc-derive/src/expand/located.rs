//! `read_inputs` / `write_outputs` for located variables (`at = "%IW4"`, IEC 61131-3 addressing). Byte order
//! and alignment are facts of the declaration, so they are fixed here, not by the caller.

use super::private;
use crate::ast::Container;
use plc_rules::address::{Area, Size};
use proc_macro2::TokenStream;
use quote::quote;

fn address(c: &Container, a: &plc_rules::IecAddress) -> TokenStream {
    let krate = &c.krate;
    let area = match a.area {
        Area::Input => quote!(#krate::Area::Input),
        Area::Output => quote!(#krate::Area::Output),
        Area::Memory => quote!(#krate::Area::Memory),
    };
    let size = match a.size {
        Size::Bit => quote!(#krate::Size::Bit),
        Size::Byte => quote!(#krate::Size::Byte),
        Size::Word => quote!(#krate::Size::Word),
        Size::DoubleWord => quote!(#krate::Size::DoubleWord),
        Size::LongWord => quote!(#krate::Size::LongWord),
    };
    let byte = a.byte;
    let bit = match a.bit {
        Some(b) => quote!(::core::option::Option::Some(#b)),
        None => quote!(::core::option::Option::None),
    };
    quote!(#krate::IecAddress { area: #area, size: #size, byte: #byte, bit: #bit })
}

pub fn expand(c: &Container) -> TokenStream {
    let p = private(c);
    let krate = &c.krate;
    let order = if c.little_endian {
        quote!(#krate::ByteOrder::LittleEndian)
    } else {
        quote!(#krate::ByteOrder::BigEndian)
    };
    let unaligned = c.decl.unaligned;
    let mut reads = Vec::new();
    let mut writes = Vec::new();
    for v in &c.vars {
        let Some(at) = &v.address else { continue };
        let ident = v.ident;
        let addr = address(c, at);
        match at.area {
            Area::Input => reads.push(quote! {
                #p::read_located(&mut self.#ident, inputs, &#addr, #order, #unaligned)?;
            }),
            _ => writes.push(quote! {
                #p::write_located(self.#ident, outputs, &#addr, #order, #unaligned)?;
            }),
        }
    }
    quote! {
        fn read_inputs<B: ::core::convert::AsRef<[u8]>>(
            &mut self,
            inputs: &#krate::ProcessImage<B>,
        ) -> ::core::result::Result<(), #krate::ProcessImageError> {
            let _ = inputs;
            #(#reads)*
            ::core::result::Result::Ok(())
        }

        fn write_outputs<B: ::core::convert::AsRef<[u8]> + ::core::convert::AsMut<[u8]>>(
            &self,
            outputs: &mut #krate::ProcessImage<B>,
        ) -> ::core::result::Result<(), #krate::ProcessImageError> {
            let _ = &outputs;
            #(#writes)*
            ::core::result::Result::Ok(())
        }
    }
}
